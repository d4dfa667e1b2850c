#pragma once
// Private: faces an example collapses to (almost) zero area, as animations
// hide a part by scaling it to a point. No placement gives the tets on such
// faces a volume, so example_aware_tets.h treats such an example as it
// treats one whose surface intersects itself.

#include <cstddef>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// How many of `triangles` have (almost) zero area in `example` but not in
/// `rest` (area below kCollapsedArea, 1e-12, times the squared bounding-box
/// diagonal of each: edges of about 1e-6 of the model's size). Faces that
/// small in the rest too (caps of nearly zero area, re-split for meshing)
/// are not counted.
std::size_t collapsedFaceCount(const Vertices& rest, const Vertices& example,
                               const Triangles& triangles);

}  // namespace tetblend
