#pragma once
// Checks of user surfaces before they are tetrahedralised or blended: the
// rest surface must bound a solid (closed, manifold, outward oriented, free
// of self-intersections), and every example must share its connectivity
// (Kaji–Ochiai §6.2: "compatibly triangulated" meshes, one affine map per
// element). Each problem names the file, the element, the value and the fix.

#include <cstddef>
#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// What is wrong. The `element` of a SurfaceProblem is a vertex index for
/// kNonFiniteCoordinate, kUnreferencedVertex and kNonManifoldVertex, -1 for
/// kEmpty, kVertexCountMismatch and kFaceCountMismatch, and a face index for
/// every other kind.
enum class SurfaceProblemKind {
  kEmpty,                    ///< no face; value 0
  kIndexOutOfRange,          ///< value: the offending index
  kNonFiniteCoordinate,      ///< value: the NaN or infinite coordinate
  kRepeatedIndex,            ///< value: the repeated vertex index
  kZeroAreaFace,             ///< value: area / (bounding-box diagonal)^2
  kDuplicateFace,            ///< same three vertices as an earlier face; value: that face
  kUnreferencedVertex,       ///< used by no face; value 0
  kNonManifoldEdge,          ///< value: number of faces on the edge (> 2)
  kNonManifoldVertex,        ///< value: number of separate face fans at the vertex
  kBoundaryEdge,             ///< edge of a single face; value: number of boundary edges
  kInconsistentOrientation,  ///< two faces run a shared edge the same way; value: the other face
  kInwardOrientation,        ///< component with wrong volume sign; value: signed volume
  kSelfIntersection,         ///< value: the other face of the pair
  kVertexCountMismatch,      ///< example differs from rest; value: example's count
  kFaceCountMismatch,        ///< example differs from rest; value: example's count
  kConnectivityMismatch,     ///< example face differs from rest face; value 0
};

/// Short name of a problem kind, e.g. "non-manifold edge".
const char* problemKindName(SurfaceProblemKind kind);

/// One problem found in a surface.
struct SurfaceProblem {
  SurfaceProblemKind kind;
  long long element;  ///< see SurfaceProblemKind
  double value;       ///< see SurfaceProblemKind
  std::string message;
};

/// Area below which a face counts as degenerate, relative to the squared
/// bounding-box diagonal: about 4500 ε of double round-off on a unit
/// bounding box, i.e. a face whose edges are ~1e-6 of the model's size.
constexpr double kDefaultZeroAreaRelTol = 1e-12;

/// Options of validateSurface, with their defaults.
struct SurfaceValidationOptions {
  /// Volumetric mode (TetGen): boundary edges are problems. Set to false for
  /// the per-face tetrisation, which accepts open surfaces.
  bool requireClosed = true;
  /// What bounding a solid needs beyond valid faces: manifold edges and
  /// vertices, consistent and outward orientation. False for the per-face
  /// tetrisation, where each face's tet is its own.
  bool requireSolid = true;
  /// Every closed component bounds a solid of its own (meshed on its own,
  /// component_meshing.h): it must face outward even inside another
  /// component, where it would otherwise be a cavity facing into itself.
  bool componentsAreSolids = false;
  /// Run the exact self-intersection test (CGAL, O(F log F)).
  bool checkSelfIntersections = true;
  /// Relative area tolerance, see kDefaultZeroAreaRelTol.
  double zeroAreaRelTol = kDefaultZeroAreaRelTol;
  /// At most this many intersecting face pairs are listed (all are counted).
  std::size_t maxSelfIntersectionPairs = 10;
};

/// Problems of a surface plus its component count.
struct SurfaceValidation {
  std::vector<SurfaceProblem> problems;
  int componentCount = 0;  ///< edge-connected components (see surface_orientation.h)
  bool ok() const { return problems.empty(); }
};

/// Checks `mesh` (#V by 3 positions, #F by 3 indices) read from `sourceName`
/// (used in messages only). Index range and finiteness are checked first; if
/// they fail, the topological and geometric checks are skipped (they would
/// read garbage). Then: repeated indices, zero area, duplicate faces,
/// unreferenced vertices, non-manifold edges and vertices, boundary edges
/// (when options.requireClosed), inconsistent orientation, inward closed
/// components, self-intersections. Problems come in that order, and within a
/// kind by element index.
SurfaceValidation validateSurface(const SurfaceMesh& mesh, const std::string& sourceName,
                                  const SurfaceValidationOptions& options = {});

/// Checks that `example` (from `exampleName`) is compatible with `rest`: same
/// vertex count, same face count, the same surface (the same triangles, or
/// the same up to their order, corner rotation and quad diagonals: see
/// flippedQuadDiagonals; else the first differing face is reported with both
/// triangles), finite coordinates. Only the example's positions are used
/// afterwards, with the rest's triangles.
std::vector<SurfaceProblem> validateExample(const SurfaceMesh& rest, const SurfaceMesh& example,
                                            const std::string& exampleName);

/// How `example`'s triangles (#F by 3) differ from `rest`'s: -1 when they
/// describe another surface; else the number of quads (two triangles sharing
/// an edge) that the example splits along the other diagonal, 0 when the
/// triangles are the same up to their order and the rotation of their
/// corners. An exporter that splits each frame's quads by its shape
/// (Blender's "Beauty") gives such frames; the pairing is greedy, so an
/// ambiguous pattern counts as another surface.
int flippedQuadDiagonals(const Triangles& rest, const Triangles& example);

/// Throws InputError with the first of `problems`' messages and the number of
/// further problems, if there are any.
void requireNoProblems(const std::vector<SurfaceProblem>& problems);

/// validateSurface, then requireNoProblems.
void requireValidRest(const SurfaceMesh& mesh, const std::string& sourceName,
                      const SurfaceValidationOptions& options = {});

/// validateExample, then throws InputError like requireValidRest.
void requireCompatibleExample(const SurfaceMesh& rest, const SurfaceMesh& example,
                              const std::string& exampleName);

/// Vertices used by no face, in increasing order (out-of-range indices are
/// ignored: validateSurface reports them).
std::vector<int> unreferencedVertices(const SurfaceMesh& mesh);

/// `mesh` without the listed vertices (typically unreferencedVertices of the
/// rest, applied to the rest and to every example alike), the others kept in
/// order and the faces renumbered. Throws InputError if a listed vertex is
/// out of range or used by a face.
SurfaceMesh removeVertices(const SurfaceMesh& mesh, const std::vector<int>& vertices);

}  // namespace tetblend
