// ShapeBlender::blend and StitchSolver::solveInto are const and documented as
// safe to call from several threads at once (per-call StitchWorkspace, the
// factor only read): blends run concurrently must equal the sequential ones
// bit for bit, since every step is deterministic.

#include <gtest/gtest.h>

#include <random>
#include <thread>
#include <vector>

#include "blending_test_support.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/blending/stitch_solver.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// Large enough (637 vertices) for the supernodal factor to have multi-column
// supernodes with off-diagonal blocks, small enough for a fast test.
TetMesh testMesh() { return boxTetMesh(6, 6, 12, Eigen::Vector3d(1.0, 1.0, 2.0)); }

TEST(ConcurrentBlend, TwoThreadsGiveTheSequentialResultsExactly) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = testMesh();
  const std::vector<Vertices> examples = {testing::smoothWarp(rest.vertices, 0.15, rng),
                                          testing::smoothWarp(rest.vertices, 0.15, rng)};
  ShapeBlenderOptions options;
  options.methods = {BlendMethod::kKaji, BlendMethod::kLinear};
  const ShapeBlender blender(rest, examples, options);
  constexpr int kBlendsPerThread = 12;
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  std::vector<std::vector<double>> weights(2 * kBlendsPerThread);
  for (auto& w : weights) w = {weight(rng), weight(rng)};
  const auto methodOf = [](int i) {
    return i % 2 == 0 ? BlendMethod::kKaji : BlendMethod::kLinear;
  };
  std::vector<Vertices> sequential(weights.size());
  for (size_t i = 0; i < weights.size(); ++i) {
    sequential[i] = blender.blend(weights[i], methodOf(static_cast<int>(i))).vertices;
  }
  std::vector<Vertices> concurrent(weights.size());
  const auto work = [&](int thread) {
    for (int b = 0; b < kBlendsPerThread; ++b) {
      const int i = 2 * b + thread;  // the threads interleave methods and weights
      concurrent[i] = blender.blend(weights[i], methodOf(i)).vertices;
    }
  };
  std::thread first(work, 0);
  std::thread second(work, 1);
  first.join();
  second.join();
  for (size_t i = 0; i < weights.size(); ++i) {
    SCOPED_TRACE("blend " + std::to_string(i));
    ASSERT_EQ(concurrent[i].rows(), sequential[i].rows());
    EXPECT_TRUE(concurrent[i] == sequential[i]);
  }
}

TEST(ConcurrentBlend, SupernodalSolveMatchesSimplicialLdltOnAMultiSupernodeMesh) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = testMesh();
  const Vertices warped = testing::smoothWarp(rest.vertices, 0.2, rng);
  StitchOptions simplicial;
  simplicial.backend = StitchBackend::kEigenSimplicialLdlt;
  const StitchSolver supernodal(rest);
  const StitchSolver reference(rest, simplicial);
  // Incompatible targets (rotated per tet) so the least-squares residual is
  // not zero and every part of the triangular solves matters.
  auto targets = deformationGradients(rest, supernodal.restData(), warped, 0);
  std::uniform_real_distribution<double> angle(-0.3, 0.3);
  for (auto& t : targets) t = Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()) * t;
  const Centroids c = supernodal.componentCentroids(warped);
  StitchWorkspace workspace;
  Vertices a, b;
  supernodal.solveInto(targets, c, a, workspace);
  reference.solveInto(targets, c, b);
  // Both factor the same SPD matrix (condition ~1e3 on this grid): they agree
  // to round-off times the condition number, relative to the mesh size.
  constexpr double kAgreeRelative = 1e-11;
  EXPECT_LT((a - b).rowwise().norm().maxCoeff(), kAgreeRelative * boundingBoxDiagonal(warped));
  // Reusing the workspace gives the same answer again.
  Vertices again;
  supernodal.solveInto(targets, c, again, workspace);
  EXPECT_TRUE(again == a);
}

}  // namespace
}  // namespace tetblend
