#pragma once
// Private: what stage 3 of the example-aware tetrahedralisation
// (example_aware_tets.h) splits for a clean example whose interior placement
// keeps inverted tets: the inverted tets and every tet sharing a vertex with
// one, so that the untangler gets room beside an inverted tet, not only
// inside it. Splitting the inverted tets alone left the hard-pose corpus's
// knot1 1080° twist with 48-89 inverted tets and 8 clean frames of the
// README's sets of The untangler with some; with their neighbours, none and
// 3 (2026-12-02; the refined meshes have up to 38 % more tets, the 3-holes
// eight 1164 → 1601).

#include <vector>

#include "tet_stellar_split.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The edges and faces of `mesh` to split for the inverted tets `inverted`
/// of an example with surface `exampleSurface` (the rest's surface vertex
/// order; `outward` the boundary triangles, `boundary` their simplices),
/// sorted, each once. For each of those tets and every tet sharing a vertex
/// with one: if a boundary edge of the tet has a ring of tets that cannot
/// span the example's fold there (creaseRingSplits), the split that adds a
/// tet to the ring; otherwise simplicesToSplit's.
std::vector<Simplex> splitsForInverted(const TetMesh& mesh, const std::vector<int>& inverted,
                                       const Vertices& exampleSurface, const Triangles& outward,
                                       int surfaceCount, const BoundarySimplices& boundary);

}  // namespace tetblend
