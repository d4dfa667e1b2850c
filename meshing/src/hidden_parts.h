#pragma once
// Private: stand-ins for the parts an example hides. Animations hide a part
// by scaling it to a point; its tets then cannot have a volume, but the
// example's other parts must still be placed as any clean example's are
// (example_aware_tets.h). The hidden part is placed as a small copy of its
// rest shape instead, and the caller puts the example's own surface back.

#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// `example` (surface vertices, the rest's order) with each tet component
/// whose faces it all collapses (`collapsed`, the rows of `triangles` that
/// collapsedFaces gives; `faceComponent`, each face's component) replaced by
/// the component's `rest` positions scaled by kHiddenPartScale (1/100) about
/// the example's point. Other components keep their positions bit for bit.
Vertices hiddenPartsStandIn(const Vertices& rest, const Vertices& example,
                            const Triangles& triangles, const std::vector<int>& faceComponent,
                            const std::vector<int>& collapsed);

}  // namespace tetblend
