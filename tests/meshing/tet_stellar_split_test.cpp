// Private unit of meshing/src: the rest positions of Steiner points are
// relaxed towards their neighbours (relaxSteinerPoints), never worsening the
// worst tet around them.

#include "tet_stellar_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

// The four tets around the edge (a, c) of a regular octahedron (vertices at
// ±1 on the axes: a, c on x; b, d on y; t, u on z), all positive.
TetMesh octahedronAroundAnEdge() {
  TetMesh mesh;
  mesh.vertices.resize(6, 3);
  mesh.vertices << 1, 0, 0,  // a 0
      0, 1, 0,               // b 1
      -1, 0, 0,              // c 2
      0, -1, 0,              // d 3
      0, 0, 1,               // t 4
      0, 0, -1;              // u 5
  mesh.tets.resize(4, 4);
  mesh.tets << 0, 2, 1, 5, 0, 2, 4, 1, 0, 2, 3, 4, 0, 2, 5, 3;
  for (Eigen::Index t = 0; t < 4; ++t) {
    if (tetSignedVolume(mesh.vertices, mesh.tets.row(t)) < 0) {
      std::swap(mesh.tets(t, 0), mesh.tets(t, 1));
    }
  }
  return mesh;
}

double worstQuality(const TetMesh& mesh) {
  double worst = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    worst = std::min(worst, tetShapeQuality(mesh.vertices, mesh.tets.row(t)));
  }
  return worst;
}

TEST(TetShapeQuality, RegularTetIsOneAndFlatOrInvertedTetsAreNot) {
  Vertices regular(4, 3);
  regular << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  const Eigen::RowVector4i positive(0, 1, 2, 3), negative(1, 0, 2, 3);
  const double sign = tetSignedVolume(regular, positive) > 0 ? 1.0 : -1.0;
  EXPECT_NEAR(sign * tetShapeQuality(regular, positive), 1.0, 1e-15);
  EXPECT_NEAR(sign * tetShapeQuality(regular, negative), -1.0, 1e-15);
  regular.row(3) << 0, 0, -1 + 1e-9;  // nearly on the plane z = -1 of the others: a sliver
  regular.row(0) << 1, 1, -1;
  EXPECT_LT(std::abs(tetShapeQuality(regular, positive)), 1e-8);
}

TEST(RelaxSteinerPoints, AnOffCentreSplitOfTheOctahedronsEdgeGoesToItsCentre) {
  // The edge (a, c) split at 0.95 of the way from its midpoint to b, as a
  // split near a flat part of the surface leaves it: the tets at b are
  // slivers. Its neighbours' mean is the centre, where every tet is better.
  TetMesh split = splitSimplices(octahedronAroundAnEdge(), {Simplex{{0, 2, 0}, 2}});
  ASSERT_EQ(split.vertices.rows(), 7);
  ASSERT_EQ(split.tets.rows(), 8);
  split.vertices.row(6) << 0, 0.95, 0;
  const double before = worstQuality(split);
  relaxSteinerPoints(split, 6);
  EXPECT_LT(split.vertices.row(6).norm(), 1e-15);
  EXPECT_GT(worstQuality(split), before);
  for (Eigen::Index t = 0; t < split.tets.rows(); ++t) {
    EXPECT_GT(tetSignedVolume(split.vertices, split.tets.row(t)), 0.0) << "tet " << t;
  }
}

TEST(RelaxSteinerPoints, OnlyTheNewVerticesMoveAndABestPlaceStays) {
  // At the centre the new vertex already has its neighbours' mean: nothing
  // moves, the original vertices least of all.
  const TetMesh octahedron = octahedronAroundAnEdge();
  TetMesh split = splitSimplices(octahedron, {Simplex{{0, 2, 0}, 2}});
  const Vertices before = split.vertices;
  relaxSteinerPoints(split, 6);
  EXPECT_EQ(split.vertices, before);
  relaxSteinerPoints(split, 7);  // no new vertex: a no-op
  EXPECT_EQ(split.vertices, before);
}

}  // namespace
}  // namespace tetblend
