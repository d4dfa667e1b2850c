#pragma once
// Face adjacency of a tetrahedral mesh and its connected components: the
// graph over which rotation logarithms are made consistent (Kaji–Ochiai
// Alg. 1 propagated tet to tet) and by which the stitch anchors components.

#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// For each tet, the indices of the tets sharing a face with it (at most 4);
/// a tet with no such neighbour lists the tets it shares an edge with
/// instead, and they list it (a tetrised surface, one tet per triangle, is linked through the
/// surface's edges, so rotation consistency keeps turns beyond π there too).
struct TetAdjacency {
  std::vector<std::vector<int>> neighbours;  ///< #T lists of tet indices
};

/// Builds the adjacency above for `tets` (#T by 4) in O(#T log #T).
TetAdjacency buildTetAdjacency(const Tets& tets);

/// Label of the connected component (over TetAdjacency) of each tet (#T entries, labels
/// 0..count-1 in order of first appearance) and the number of components.
struct TetComponents {
  std::vector<int> label;
  int count = 0;
};

/// Connected components of the tets over `adjacency`, by breadth-first search.
TetComponents tetComponents(const TetAdjacency& adjacency);

}  // namespace tetblend
