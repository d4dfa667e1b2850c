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

TEST(TetAdjacency, SharingOnlyAnEdgeIsNotAdjacent) {
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 0, 1, 4, 5;
  const TetAdjacency adjacency = buildTetAdjacency(tets);
  EXPECT_TRUE(adjacency.neighbours[0].empty());
  EXPECT_EQ(tetComponents(adjacency).count, 2);
}

}  // namespace
}  // namespace tetblend
