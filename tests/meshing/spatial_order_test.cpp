#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <vector>

#include "../test_seed.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

unsigned testSeed() { return test_seed::seedOfCurrentTest(20261126u); }

// A tet's corner positions, in corner order (what a renumbering must keep).
using Corners = std::array<double, 12>;

std::vector<Corners> cornerPositions(const TetMesh& mesh) {
  std::vector<Corners> result;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    Corners c{};
    for (int k = 0; k < 4; ++k) {
      for (int axis = 0; axis < 3; ++axis) c[3 * k + axis] = mesh.vertices(mesh.tets(t, k), axis);
    }
    result.push_back(c);
  }
  std::sort(result.begin(), result.end());
  return result;
}

Eigen::RowVector3d centroid(const TetMesh& mesh, Eigen::Index t) {
  Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
  for (int k = 0; k < 4; ++k) sum += mesh.vertices.row(mesh.tets(t, k));
  return sum / 4;
}

// Mean distance between the centroids of consecutive tets.
double meanStep(const TetMesh& mesh) {
  double total = 0.0;
  for (Eigen::Index t = 1; t < mesh.tets.rows(); ++t) {
    total += (centroid(mesh, t) - centroid(mesh, t - 1)).norm();
  }
  return total / static_cast<double>(mesh.tets.rows() - 1);
}

// A 10 x 10 x 10 box of unit cubes (6 tets each) with its tets shuffled.
TetMesh shuffledBox(unsigned seed) {
  TetMesh mesh = boxTetMesh(10, 10, 10, Eigen::Vector3d(10.0, 10.0, 10.0));
  std::vector<int> order(static_cast<std::size_t>(mesh.tets.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  const Tets tets = mesh.tets;
  for (std::size_t i = 0; i < order.size(); ++i) mesh.tets.row(i) = tets.row(order[i]);
  return mesh;
}

TEST(SpatialOrder, KeepsEveryTetAndTheSurfaceVertices) {
  const TetMesh input = shuffledBox(testSeed());
  constexpr int kKept = 50;  // any prefix of the vertices stays in place
  const TetMesh ordered = inSpatialOrder(input, kKept);
  ASSERT_EQ(ordered.vertices.rows(), input.vertices.rows());
  ASSERT_EQ(ordered.tets.rows(), input.tets.rows());
  EXPECT_TRUE(ordered.vertices.topRows(kKept) == input.vertices.topRows(kKept));
  EXPECT_EQ(cornerPositions(ordered), cornerPositions(input));
  // The other vertices are numbered by first use, in tet order.
  int next = kKept;
  for (Eigen::Index t = 0; t < ordered.tets.rows(); ++t) {
    for (int k = 0; k < 4; ++k) {
      const int v = ordered.tets(t, k);
      if (v < kKept) continue;
      ASSERT_LE(v, next) << "tet " << t << " corner " << k;
      if (v == next) ++next;
    }
  }
  EXPECT_EQ(next, ordered.vertices.rows());
}

// The Morton code interleaves x (lowest bit), y and z: the eight octant
// cells of a cube come in the order x + 2 y + 4 z, whatever the input order.
TEST(SpatialOrder, TheOctantsOfACubeComeInZOrder) {
  TetMesh mesh;
  mesh.vertices.resize(32, 3);
  mesh.tets.resize(8, 4);
  for (int cell = 0; cell < 8; ++cell) {
    const int input = 7 - cell;  // given in reverse
    const Eigen::RowVector3d corner(cell & 1, (cell >> 1) & 1, (cell >> 2) & 1);
    const Eigen::RowVector3d low = corner + Eigen::RowVector3d::Constant(0.1);
    mesh.vertices.row(4 * input) = low;
    mesh.vertices.row(4 * input + 1) = low + Eigen::RowVector3d(0.5, 0.0, 0.0);
    mesh.vertices.row(4 * input + 2) = low + Eigen::RowVector3d(0.0, 0.5, 0.0);
    mesh.vertices.row(4 * input + 3) = low + Eigen::RowVector3d(0.0, 0.0, 0.5);
    mesh.tets.row(input) << 4 * input, 4 * input + 1, 4 * input + 2, 4 * input + 3;
  }
  const TetMesh ordered = inSpatialOrder(mesh, 0);
  for (int cell = 0; cell < 8; ++cell) {
    const Eigen::RowVector3d expected(cell & 1, (cell >> 1) & 1, (cell >> 2) & 1);
    const Eigen::RowVector3d low = ordered.vertices.row(ordered.tets(cell, 0));
    EXPECT_TRUE(((low.array() - 0.1).round() == expected.array()).all())
        << "position " << cell << " holds the cell at " << low;
  }
}

// The point of the order: consecutive tets are neighbours. In the shuffled
// box consecutive centroids lie about 0.66 * 10 = 6.6 cube edges apart on
// average (the mean distance of two random points in a cube of side 10);
// along the Morton curve most steps stay within a cube or cross to an
// adjacent one, with rare long jumps between the curve's blocks (measured:
// 6.61 shuffled, 0.79 ordered).
TEST(SpatialOrder, ConsecutiveTetsAreNearEachOther) {
  const TetMesh input = shuffledBox(testSeed());
  constexpr double kMaxMeanStepInCubeEdges = 1.0;
  EXPECT_GT(meanStep(input), 4.0);
  EXPECT_LT(meanStep(inSpatialOrder(input, 0)), kMaxMeanStepInCubeEdges);
}

}  // namespace
}  // namespace tetblend
