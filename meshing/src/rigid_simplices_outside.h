#pragma once
// Private: stage 1 of example_aware_tets.cpp, the rigid edges and faces of
// the rest mesh (rigidSimplices, tet_stellar_split.h) that an embeddable
// example moves out of its own solid (surface_interior.h): no placement of
// the interior vertices can repair their tets, a split can.

#include <vector>

#include "tet_stellar_split.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The simplices of `rigid` (rigidSimplices of the rest mesh, sorted) that
/// leave the solid an embeddable example (one whose surface neither
/// intersects itself nor collapses faces) bounds for their own tet
/// component, as what to split: such an edge itself; such a face through
/// one of its rigid edges if it has one (the split frees the face too),
/// else the face. Sorted, edges first, so splitSimplices never meets a face
/// whose edge it already split.
std::vector<Simplex> rigidSimplicesOutside(const std::vector<Simplex>& rigid,
                                           const Vertices& example, const Triangles& triangles,
                                           const std::vector<int>& vertexComponent,
                                           const std::vector<int>& faceComponent);

}  // namespace tetblend
