#pragma once
// Private to hole_filling.cpp: how sharply a hole's fill folds in a pose.
// The fill's triangles join the rim's vertices only, so an example that
// moves the rim moves them rigidly; where two of them (or one and the
// surface across the rim) turn nearly back onto each other, the solid is a
// knife edge or a slit there, which the tets along that edge cannot follow.

#include <array>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The hole's side of a boundary edge: it runs from -> to (as the fill's
/// triangle there does), and `face` (which runs to -> from) is on the other
/// side.
struct Border {
  int from;
  int to;
  int face;
};

/// A hole's fill: triangles oriented like the surface, as vertex indices.
using FillTriangles = std::vector<std::array<int, 3>>;

/// The sharpest fold of `fill` at `positions` (#V by 3): the largest angle,
/// in radians, between the unit normals of two faces across an edge of the
/// fill (two fill triangles, or a fill triangle and the surface face of
/// `surfaceTriangles` across one of the hole's `rim` edges). A triangle of
/// zero area counts as a fold of π: its normal is undefined.
double sharpestFold(const FillTriangles& fill, const std::vector<Border>& rim,
                    const Triangles& surfaceTriangles, const Vertices& positions);

}  // namespace tetblend
