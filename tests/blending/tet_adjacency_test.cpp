#include "tetblend/blending/tet_adjacency.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tetblend {
namespace {

TEST(TetAdjacency, TwoTetsSharingAFaceAndOneApart) {
  Tets tets(3, 4);
  tets << 0, 1, 2, 3,  //
      1, 2, 3, 4,      // shares face {1,2,3} with tet 0
      5, 6, 7, 8;      // disconnected
  const TetAdjacency adjacency = buildTetAdjacency(tets);
  EXPECT_EQ(adjacency.neighbours[0], std::vector<int>{1});
  EXPECT_EQ(adjacency.neighbours[1], std::vector<int>{0});
  EXPECT_TRUE(adjacency.neighbours[2].empty());
  const TetComponents components = tetComponents(adjacency);
  EXPECT_EQ(components.count, 2);
  EXPECT_EQ(components.label, (std::vector<int>{0, 0, 1}));
}

TEST(TetAdjacency, FacelessTetsAreLinkedThroughSharedEdges) {
  // A and B share a face; C shares only the edge (0, 1) with both, D only the
  // vertex 0 with the others: C has no face neighbour, so it is linked to A
  // and B (and they to it) through the edge; D stays alone.
  Tets tets(4, 4);
  tets << 0, 1, 2, 3,  // A
      0, 1, 2, 4,      // B
      0, 1, 5, 6,      // C
      0, 7, 8, 9;      // D
  const TetAdjacency adjacency = buildTetAdjacency(tets);
  auto sorted = [&](int t) {
    std::vector<int> list = adjacency.neighbours[static_cast<size_t>(t)];
    std::sort(list.begin(), list.end());
    return list;
  };
  EXPECT_EQ(sorted(0), (std::vector<int>{1, 2}));
  EXPECT_EQ(sorted(1), (std::vector<int>{0, 2}));
  EXPECT_EQ(sorted(2), (std::vector<int>{0, 1}));
  EXPECT_TRUE(sorted(3).empty());
  EXPECT_EQ(tetComponents(adjacency).count, 2);
}

TEST(TetAdjacency, TetsWithFaceNeighboursAreNotLinkedThroughEdges) {
  // Two face-sharing pairs that meet only along the edge (0, 1).
  Tets tets(4, 4);
  tets << 0, 1, 2, 3, 0, 1, 2, 4, 0, 1, 5, 6, 0, 1, 5, 7;
  const TetAdjacency adjacency = buildTetAdjacency(tets);
  for (int t = 0; t < 4; ++t) EXPECT_EQ(adjacency.neighbours[static_cast<size_t>(t)].size(), 1u);
  EXPECT_EQ(tetComponents(adjacency).count, 2);
}

}  // namespace
}  // namespace tetblend
