#pragma once
// Closing the seams of a surface exported with split vertices: exporters
// duplicate a vertex wherever its texture coordinate or normal jumps (UV
// seams, flat-shaded and sharp edges), so the surface is cut open along
// those edges although both sides meet. Where exactly two boundary edges
// join the same two positions, they are zipped: their vertices are merged.
// Their faces may run them either way (a flat-shaded export orients each
// facet on its own; the meshing orients the zipped surface consistently).
// Only such pairs are merged, so two parts that merely touch at a point, a
// fin of three sheets, or a hole's rim stay apart; rims that touch at a
// point can then be joined there (withTouchingRimsJoined). Positions are compared
// exactly (the copies of a seam vertex are written from one value).

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// A surface with its seams zipped, and where each input vertex went.
struct SeamWelding {
  /// The merged surface: of each group of merged vertices the one with the
  /// smallest index, in input order; the input's faces, renumbered.
  SurfaceMesh surface;
  /// Per input vertex, its row in surface.vertices (0, 1, 2, ... when
  /// nothing was merged).
  std::vector<int> rowOf;
  /// Input vertices merged into one with a smaller index.
  int mergedVertices = 0;
  /// Pairs of boundary edges zipped together.
  int seamEdges = 0;
  /// Of mergedVertices, those merged by withTouchingRimsJoined.
  int rimVertices = 0;
};

/// Per vertex of `vertices` (finite), a number shared exactly by the vertices
/// at the same position (0.0 and -0.0 are one position): 0, 1, 2, ... in
/// the lexicographic order of the positions.
std::vector<int> positionIds(const Vertices& vertices);

/// Per vertex of `surface` (indices in range), 1 where it lies on the rim of
/// a hole: on an edge of exactly one face (faces that repeat a vertex do not
/// count).
std::vector<char> rimVertices(const SurfaceMesh& surface);

/// Zips the seams of `surface` as described above. A surface with non-finite
/// coordinates or a face index out of range, or one whose zipping would
/// collapse a face, is returned as it is (nothing merged), for the
/// validation to name its problem.
SeamWelding weldSeams(const SurfaceMesh& surface);

/// `welding` with, in addition, the vertices on its surface's boundary edges
/// that share a position merged into one (holes whose rims touch there, as
/// in a scan), where they share it in each of `examples` too (one vertex per
/// input vertex; an example with another count is skipped, for the example
/// checks to name). The merged vertex is pinched: two fans of faces
/// meet there, and fillHoles closes each hole around it. Nothing is merged
/// where a face would collapse.
SeamWelding withTouchingRimsJoined(SeamWelding welding, const std::vector<SurfaceMesh>& examples);

/// `positions` (one row per input vertex, e.g. an example of the surface
/// `welding` was made from) on the merged surface's rows. Throws InputError
/// naming `sourceName` and two merged vertices whose positions here differ:
/// a seam that opens in an example cannot share the rest's tets.
Vertices weldedPositions(const SeamWelding& welding, const Vertices& positions,
                         const std::string& sourceName);

}  // namespace tetblend
