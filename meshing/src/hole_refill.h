#pragma once
// Private to hole_filling.cpp: a hole's fill chosen for the examples as well
// as the rest. Every example shares the rest's fill, whose triangles join
// rim vertices only; a fill that is fine at the rest can fold nearly flat
// onto itself where an example moves the rim (CGAL's lion, its open base
// in 48 skinned frames: folds of 167°–176° between fill triangles left the
// tets there inverted in 3 frames whose surfaces are clean). CGAL's fill of
// the same hole in that example's positions usually folds far less there.

#include <vector>

#include "hole_fill_folds.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// CGAL's minimum-weight triangulation (triangulate_hole_polyline) of the
/// hole whose boundary edges, in order, are `rim`, at `positions` (of the
/// surface's vertices): triangles oriented like the surface, empty if CGAL
/// finds none. Each boundary edge's third point (its face's other corner)
/// steers the fill away from folding over the surface.
FillTriangles polylineFill(const SurfaceMesh& surface, const Vertices& positions,
                           const std::vector<Border>& rim);

/// The fill of the hole bounded by `rim` that folds least (sharpestFold)
/// over the rest (`surface.vertices`) and `poses` (positions of the same
/// vertices): `fill` (the rest's own), unless it folds by more
/// than kHarmlessFold somewhere; then, while it does, CGAL's fill in the
/// pose where the current choice folds most (at most kMaxRefills poses)
/// replaces the current choice if it folds less over all of them, cuts none of the surface's faces
/// at the rest, cuts them in no more poses than the current choice (an example whose fill cuts its
/// surface intersects itself: its tets there are excluded) and repeats none of the surface's edges.
FillTriangles leastFoldingFill(FillTriangles fill, const SurfaceMesh& surface,
                               const std::vector<Vertices>& poses, const std::vector<Border>& rim);

}  // namespace tetblend
