#include "tetblend/blending/nonlinear_stitch.h"

#include <gtest/gtest.h>

#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// The repair moves vertices of a unit-scale box and restores each component's
// centroid: the mean of ~200 coordinates of size ~1, a few ulps each.
constexpr double kCentroidTolerance = 1e-12;

// A target field that the linear stitch cannot satisfy without inverting
// tets: identity everywhere except a central slab of tets whose target map
// squashes z to -0.5 (a reflection), as an over-extrapolated blend can ask.
std::vector<Eigen::Matrix3d> reflectedSlabTargets(const TetMesh& rest) {
  std::vector<Eigen::Matrix3d> targets(rest.tets.rows(), Eigen::Matrix3d::Identity());
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
    double z = 0.0;
    for (int c = 0; c < 4; ++c) z += 0.25 * rest.vertices(rest.tets(j, c), 2);
    if (std::abs(z) < 0.15) targets[j] = Eigen::Vector3d(1.0, 1.0, -0.5).asDiagonal();
  }
  return targets;
}

TEST(NonlinearStitch, RemovesInvertedTetsTheLinearStitchLeaves) {
  const TetMesh rest = boxTetMesh(4, 4, 8, Eigen::Vector3d(1.0, 1.0, 2.0));
  const StitchSolver solver(rest);
  const auto targets = reflectedSlabTargets(rest);
  const Centroids centroids = solver.componentCentroids(rest.vertices);
  const Vertices linear = solver.solve(targets, centroids);
  const int invertedLinear = countInvertedTets(solver, linear);
  ASSERT_GT(invertedLinear, 0) << "the case must make the linear stitch invert tets";
  NonlinearStitchReport report;
  const Vertices x = nonlinearStitch(solver, targets, linear, centroids, {}, &report);
  EXPECT_EQ(report.invertedBefore, invertedLinear);
  EXPECT_EQ(report.invertedAfter, countInvertedTets(solver, x));
  EXPECT_LT(report.invertedAfter, report.invertedBefore);
  EXPECT_EQ(report.invertedAfter, 0);
  // The linear stitch is the unconstrained minimiser: removing inversions
  // can only cost stitch energy.
  EXPECT_GE(report.energyAfter, report.energyBefore);
  EXPECT_DOUBLE_EQ(report.energyBefore, solver.energy(linear, targets));
  // Centroid kept.
  EXPECT_LT((solver.componentCentroids(x) - centroids).norm(), kCentroidTolerance);
}

TEST(NonlinearStitch, LeavesAnUninvertedResultUnchanged) {
  const TetMesh rest = boxTetMesh(2, 2, 2, Eigen::Vector3d::Ones());
  const StitchSolver solver(rest);
  const std::vector<Eigen::Matrix3d> targets(rest.tets.rows(), 2.0 * Eigen::Matrix3d::Identity());
  const Centroids centroids = solver.componentCentroids(rest.vertices);
  const Vertices linear = solver.solve(targets, centroids);
  NonlinearStitchReport report;
  const Vertices x = nonlinearStitch(solver, targets, linear, centroids, {}, &report);
  EXPECT_EQ(report.rounds, 0);
  EXPECT_TRUE(x == linear);
  EXPECT_THROW(nonlinearStitch(solver, {}, linear, centroids), InputError);
}

}  // namespace
}  // namespace tetblend
