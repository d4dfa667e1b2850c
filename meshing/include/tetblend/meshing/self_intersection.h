#pragma once
// Self-intersection test of a triangle soup with exact predicates (CGAL). The
// header is CGAL-free: CGAL stays in one translation unit, compiled in its own
// object library because it needs -frounding-math.

#include <cstddef>
#include <utility>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Result of findSelfIntersections.
struct SelfIntersections {
  /// Number of intersecting face pairs in total.
  std::size_t pairCount = 0;
  /// The first (in lexicographic order, smaller face index first) at most
  /// `maxReportedPairs` intersecting pairs.
  std::vector<std::pair<int, int>> pairs;
};

/// Finds pairs of triangles of the soup (`vertices` #V by 3, `triangles` #F by
/// 3, indices in range) that intersect other than along the vertices and edges
/// they share: two faces sharing an edge intersect only when they fold onto
/// each other (coplanar, on the same side of the edge); two faces sharing a
/// vertex intersect when either's opposite edge meets the other triangle.
/// Faces with a repeated index, exactly collinear corners, or the same three
/// vertices as another face are skipped (validateSurface reports them as
/// degenerate or duplicate). Exact predicates: the answer has no tolerance.
/// Candidate pairs come from an axis-aligned box intersection,
/// O((F + K) log F) for K candidates.
SelfIntersections findSelfIntersections(const Vertices& vertices, const Triangles& triangles,
                                        std::size_t maxReportedPairs);

/// As above, counting only pairs of faces with the same label in
/// `faceGroup` (#F labels): the faces of different groups may overlap, as
/// closed components meshed each on its own do (component_meshing.h).
SelfIntersections findSelfIntersections(const Vertices& vertices, const Triangles& triangles,
                                        std::size_t maxReportedPairs,
                                        const std::vector<int>& faceGroup);

}  // namespace tetblend
