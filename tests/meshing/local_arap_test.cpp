// ARAP over a region of free vertices (meshing/src/local_arap.h) on a
// Kuhn-split cube grid: the region converges to a rigid motion of the rest
// when everything around it was moved rigidly (ARAP's minimiser then has
// zero energy, an oracle independent of the iteration), a vertex pushed
// through its neighbours comes back valid, and vertices outside the region
// stay bit for bit.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "interior_stiffness.h"
#include "kuhn_grid.h"
#include "local_arap.h"
#include "test_seed.h"
#include "tet_elements.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

const KuhnGrid kGrid{6};

// The interior vertices (i, j, k) with every index in [lo, hi].
std::vector<int> block(int lo, int hi) {
  std::vector<int> region;
  for (int i = lo; i <= hi; ++i) {
    for (int j = lo; j <= hi; ++j) {
      for (int k = lo; k <= hi; ++k) region.push_back(kGrid.index(i, j, k));
    }
  }
  return region;
}

int invertedCount(const TetMesh& mesh, const Vertices& positions) {
  int count = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    count += tetSignedVolume(positions, mesh.tets.row(t)) > 0.0 ? 0 : 1;
  }
  return count;
}

// Converged: a move below this (the grid's cell is 1/6) ends the iteration.
constexpr double kConvergedMove = 1e-13;
// The region's distance from the rigid motion after converging: the local
// and global steps contract a small perturbation by a constant factor per
// iteration, so 200 iterations leave only rounding (positions of order 1).
constexpr double kRigidTolerance = 1e-9;

TEST(LocalArap, ARegionAmidARigidMotionConvergesToThatMotion) {
  const TetMesh mesh = kGrid.mesh();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const VertexStars stars = vertexStars(mesh.tets, static_cast<int>(mesh.vertices.rows()));
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(2.0, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(0.3, -1.2, 2.0);
  const Vertices moved = (mesh.vertices * rotation.transpose()).rowwise() + shift;

  std::mt19937 random(test_seed::seedOfCurrentTest(20261203));
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);  // a fifth of a cell
  const std::vector<int> region = block(2, 4);
  Vertices positions = moved;
  for (int v : region) {
    for (int c = 0; c < 3; ++c) positions(v, c) += jitter(random);
  }
  LocalArapStops stops;
  stops.maxIterations = 200;
  stops.tolerance = kConvergedMove;
  stops.stallFall = -1.0;  // never stop for the energy
  stops.stopWhenValid = false;
  EXPECT_GT(localArap(mesh.tets, elements, stars, region, stops, positions), 1);
  EXPECT_LT((positions - moved).cwiseAbs().maxCoeff(), kRigidTolerance);
}

TEST(LocalArap, APushedVertexComesBackValidAndOnlyTheRegionMoves) {
  const TetMesh mesh = kGrid.mesh();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const VertexStars stars = vertexStars(mesh.tets, static_cast<int>(mesh.vertices.rows()));
  Vertices start = mesh.vertices;
  const int pushed = kGrid.index(3, 3, 3);
  start(pushed, 0) += 1.5 / kGrid.cells;   // through its neighbour (4, 3, 3)
  start(kGrid.index(1, 1, 1), 1) += 0.01;  // outside the region: must not move
  ASSERT_GT(invertedCount(mesh, start), 0);

  const std::vector<int> region = block(2, 4);
  Vertices positions = start;
  LocalArapStops stops;
  stops.maxIterations = 20;
  EXPECT_GE(localArap(mesh.tets, elements, stars, region, stops, positions), 1);
  EXPECT_EQ(invertedCount(mesh, positions), 0);
  std::vector<char> free(static_cast<std::size_t>(mesh.vertices.rows()), 0);
  for (int v : region) free[static_cast<std::size_t>(v)] = 1;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    if (free[static_cast<std::size_t>(v)]) continue;
    EXPECT_EQ(positions.row(v), start.row(v)) << "vertex " << v;
  }
}

TEST(LocalArap, AnEmptyRegionChangesNothing) {
  const TetMesh mesh = kGrid.mesh();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const VertexStars stars = vertexStars(mesh.tets, static_cast<int>(mesh.vertices.rows()));
  Vertices positions = mesh.vertices;
  positions(kGrid.index(3, 3, 3), 2) += 0.5;
  const Vertices start = positions;
  EXPECT_EQ(localArap(mesh.tets, elements, stars, {}, LocalArapStops{}, positions), 0);
  EXPECT_EQ(positions, start);
}

}  // namespace
}  // namespace tetblend
