#pragma once
// Connected components of a triangle surface, their enclosed volumes and
// nesting, and the repair of face orientation (consistent, and outward for
// closed components). Needed because the per-tet maps of the shape blender
// (Kaji–Ochiai §6.2) require positively oriented tets, which TetGen and the
// tetrisation derive from counter-clockwise-from-outside triangles.

#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// One edge-connected component of a surface (faces linked through shared
/// edges; faces with a repeated vertex index belong to no component).
struct SurfaceComponent {
  int firstFace = -1;  ///< smallest face index in the component
  int faceCount = 0;
  /// Every edge of the component is shared by exactly two of its faces.
  bool closed = false;
  /// Every shared edge is traversed once in each direction.
  bool consistent = false;
  /// Enclosed signed volume (divergence theorem, sum of det[p0,p1,p2]/6), in
  /// file units cubed; meaningful only when closed and consistent.
  double signedVolume = 0.0;
  /// Number of other closed, consistent components that enclose this one
  /// (generalised winding number of a face centroid, |w| > 1/2). A solid's
  /// outer shell has depth 0 and must have positive volume; a cavity wall has
  /// depth 1 and negative volume; an island inside a cavity depth 2, etc.
  int nestingDepth = 0;
};

/// Components of the surface (indices must be in range), ordered by their
/// first face, and `faceComponent` (#F, -1 for faces with a repeated index)
/// mapping each face to its component when not null.
std::vector<SurfaceComponent> surfaceComponents(const SurfaceMesh& mesh,
                                                std::vector<int>* faceComponent = nullptr);

/// Total enclosed volume: the sum over faces of det[p0, p1, p2] / 6 (file
/// units cubed). For a closed, consistently and outward oriented surface this
/// is the volume of the solid (cavities subtract).
double enclosedVolume(const SurfaceMesh& mesh);

/// Generalised winding number of `point` with respect to the surface: the
/// sum of the signed solid angles of its faces seen from `point` (Van
/// Oosterom & Strackee 1983), divided by 4π. For a closed, outward oriented
/// surface it is 1 inside, 0 outside (cavities subtract); undefined on it.
double windingNumber(const SurfaceMesh& mesh, const Eigen::Vector3d& point);

/// What orientConsistently changed.
struct OrientationFix {
  /// Faces whose orientation was reversed (indices 1 and 2 swapped), sorted.
  std::vector<int> flippedFaces;
  /// Components (indices into surfaceComponents order) reversed as a whole
  /// because their enclosed volume had the wrong sign for their nesting depth.
  std::vector<int> reversedComponents;
  int componentCount = 0;
};

/// Makes the orientation of every component consistent (each shared edge
/// traversed once each way; within a component the majority orientation is
/// kept), then reverses each closed component whose signed volume has the
/// wrong sign for its nesting depth (outer shells outward, cavities inward).
/// Open components are only made consistent. Throws InputError (naming the
/// edge or face) when the surface cannot be oriented: an index out of range,
/// an edge shared by more than two faces, or a non-orientable component
/// (Möbius-like).
OrientationFix orientConsistently(SurfaceMesh& mesh);

}  // namespace tetblend
