#pragma once
// Faces a pose collapses to (almost) zero area, as animations hide a part by
// scaling it to a point. No placement gives the tets on such faces a volume:
// example_aware_tets.h places such an example's other parts around a
// stand-in of the hidden part (or, where the faces are not whole parts,
// treats it as self-intersecting), and a rest that collapses faces cannot be
// meshed there (prepare refuses it, naming a remedy).

#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The rows of `triangles` (ascending) that have (almost) zero area in
/// `pose` but not in `reference` (area below kCollapsedArea, 1e-12, times
/// the squared bounding-box diagonal of each: edges of about 1e-6 of the
/// model's size). Faces that small in the reference too (caps of nearly
/// zero area, re-split for meshing) are not counted.
std::vector<int> collapsedFaces(const Vertices& reference, const Vertices& pose,
                                const Triangles& triangles);

}  // namespace tetblend
