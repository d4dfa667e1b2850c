#pragma once
// Private: the fill-reducing elimination order of a rest mesh's interior
// vertices, the unknowns of CompatibleTetBuilder's stiffness block K_II.
// Large interiors are ordered by METIS's nested dissection, which needs only
// the tets and, on a million tets, takes most of a second (a third to a half
// of the factorisation it serves): buildCompatibleTetMeshes therefore orders TetGen's mesh in the
// background while it checks the examples and refines (refinement only
// appends interior vertices and edges to them, so the order stays valid with
// the new vertices eliminated last).

#include <future>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// From this many interior vertices on, K_II is ordered by METIS alone.
/// CHOLMOD's default orders with AMD and, when AMD's fill is high, also with
/// METIS, keeping the better: on bench_meshing's 1 M-tet bar (145 914
/// interior vertices) it kept METIS, and METIS alone gives the same factor
/// (lnz 5.51e7, 6.27e10 flops) with analysis 2535 -> 1864 ms. At 13 309
/// vertices (its 100 k row) CHOLMOD keeps AMD (26 ms) without trying METIS,
/// which would take 141 ms to save 30 % of the factorisation's flops.
constexpr int kMetisOnlyInteriorVertices = 100000;

/// An elimination order of interior vertices: order[k] is the interior index
/// (vertex − #S) of the k-th vertex eliminated.
using InteriorOrder = std::vector<int>;

/// METIS's nested-dissection order (METIS_NodeND, with fewer refinement
/// passes than its default: the .cpp) of the graph of the interior vertices
/// surfaceVertexCount..vertexCount−1 joined by tet edges; not postordered
/// (CHOLMOD's analysis postorders the elimination tree). Deterministic (METIS's
/// fixed seed). Empty when there is no interior, when tetblend is built
/// without METIS, or when METIS fails: the factorisation then orders the
/// interior itself.
InteriorOrder metisInteriorOrder(const Tets& tets, int surfaceVertexCount, int vertexCount);

/// metisInteriorOrder on a thread of its own, started now; the tets are
/// copied. An invalid future when the interior is below
/// kMetisOnlyInteriorVertices, when TBB may use only one thread
/// (tbb::global_control), or when tetblend is built without METIS.
std::shared_future<InteriorOrder> metisInteriorOrderInBackground(const Tets& tets,
                                                                 int surfaceVertexCount,
                                                                 int vertexCount);

/// `order` extended to `interiorCount` vertices, the ones beyond it last,
/// when it is a permutation of 0..order.size()−1 and the appended vertices
/// are few enough not to fill the factor (at most 1 % of them, see the
/// .cpp); empty otherwise.
InteriorOrder extendedInteriorOrder(const InteriorOrder& order, int interiorCount);

}  // namespace tetblend
