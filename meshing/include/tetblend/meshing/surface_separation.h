#pragma once
// A rest surface that intersects itself slightly (legs touching, a fold of a
// scan) cannot be tetrahedralised, but it can be blended: the tets are made
// on a separated copy, a surface with the same triangles whose vertices near
// the intersections are moved apart, and the user's rest is then embedded in
// those tets like any pose (the tets it cannot embed are left out of the
// stitch). This file makes the separated copy.

#include <optional>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Options of separateSelfIntersections, with their defaults.
struct SurfaceSeparationOptions {
  /// Rounds of moving the vertices near the remaining intersections, each
  /// followed by an exact self-intersection test. The nine self-intersecting
  /// CGAL demo meshes (3 to 1643 intersecting face pairs) took 1 to 45.
  int maxRounds = 60;
  /// No vertex may move further than this fraction of the bounding-box
  /// diagonal, or than maxEdgeLengths of its own mean edge length if that is
  /// more: beyond both the surface is not "slightly" self-intersecting and
  /// the copy would no longer stand for it. Those meshes needed 0.1 to 3 %.
  double maxDisplacement = 0.05;
  /// A low-poly surface (a game character of a few hundred vertices has
  /// edges of 5-10 % of the diagonal) can only part by moving a vertex about
  /// one edge: one smoothing step moves a convex corner half-way to its
  /// neighbours' mean.
  double maxEdgeLengths = 1.0;
};

/// The separated copy of a surface.
struct SurfaceSeparation {
  Vertices vertices;              ///< #V by 3, the input's rows except the moved ones
  int movedVertices = 0;          ///< rows that differ from the input
  double largestDisplacement = 0;  ///< in file units
  int rounds = 0;                 ///< rounds performed
};

/// Moves the vertices of `surface`'s intersecting faces (and, as rounds go
/// on, the faces that still intersect) until no two faces intersect (exact
/// predicates, self_intersection.h). `surface` must be closed, manifold and
/// consistently oriented outward (validateSurface's checks other than
/// self-intersection pass). Each round smooths the vertices of the
/// intersecting faces and their one-ring towards their neighbours' mean (a
/// local fold unfolds) and pushes each vertex of an intersecting face along
/// its normal, by a fraction of its mean edge length that grows with every
/// push, where the winding number just behind it says the solid is covered
/// twice (parts overlap: inwards) or not at all (the two sides of a thin part
/// crossed: outwards).
/// Returns nullopt when maxRounds rounds do not separate the surface or a
/// vertex would move beyond both bounds of the options. Deterministic. A
/// surface that does not intersect itself comes back unchanged after one
/// test.
std::optional<SurfaceSeparation> separateSelfIntersections(
    const SurfaceMesh& surface, const SurfaceSeparationOptions& options = {});

}  // namespace tetblend
