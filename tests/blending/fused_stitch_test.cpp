// The fused blend-and-stitch path (ShapeBlenderOptions::keepTargets off, the
// default): the stitch's right-hand side takes each chunk of blended maps as
// it is produced instead of a stored #T field. It must be exact, not merely
// close: the same fixed chunks, the same arithmetic and the same summation
// order as blending the whole field first and solving with it.

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <random>
#include <utility>
#include <vector>

#include "blending_test_support.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/blending/stitch_solver.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// 34 560 tets: 34 chunks of kTetMapChunk tets (the last partial), more than
// twice the stitch's 16 right-hand-side chunks, so each of those holds
// several map chunks.
TetMesh largeMesh() { return boxTetMesh(12, 12, 40, Eigen::Vector3d(1.0, 1.0, 3.3)); }

// 8 448 tets: 9 map chunks, fewer than the right-hand-side chunks, so some of
// those are empty; the blend-method test runs on it.
TetMesh mediumMesh() { return boxTetMesh(8, 8, 22, Eigen::Vector3d(1.0, 1.0, 2.75)); }

// 2 592 tets: 3 map chunks.
TetMesh smallMesh() { return boxTetMesh(6, 6, 12, Eigen::Vector3d(1.0, 1.0, 2.0)); }

void expectFusedSolveEqualsStoredField(const TetMesh& rest, std::mt19937& rng) {
  const StitchSolver solver(rest);
  const Vertices warped = testing::smoothWarp(rest.vertices, 0.2, rng);
  std::vector<Eigen::Matrix3d> targets = deformationGradients(rest, solver.restData(), warped, 0);
  std::uniform_real_distribution<double> angle(-0.3, 0.3);
  for (auto& t : targets) t = Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()) * t;
  const Centroids c = solver.componentCentroids(warped);
  StitchWorkspace workspace;
  Vertices stored, fused;
  solver.solveInto(targets, c, stored, workspace);
  std::mutex mutex;
  std::vector<std::pair<int, int>> ranges;
  solver.solveInto(
      [&](int begin, int end, Eigen::Matrix3d* out) {
        for (int j = begin; j < end; ++j) out[j - begin] = targets[j];
        const std::lock_guard<std::mutex> lock(mutex);
        ranges.emplace_back(begin, end);
      },
      c, fused, workspace);
  EXPECT_TRUE(fused == stored);
  // The ranges are the fixed chunks of TetMapBlender::blendTargets, each asked
  // for once: [c kTetMapChunk, min((c + 1) kTetMapChunk, #T)).
  std::sort(ranges.begin(), ranges.end());
  const int tets = static_cast<int>(rest.tets.rows());
  ASSERT_EQ(static_cast<int>(ranges.size()), (tets + kTetMapChunk - 1) / kTetMapChunk);
  for (size_t i = 0; i < ranges.size(); ++i) {
    EXPECT_EQ(ranges[i].first, static_cast<int>(i) * kTetMapChunk);
    EXPECT_EQ(ranges[i].second, std::min(tets, static_cast<int>(i + 1) * kTetMapChunk));
  }
}

TEST(FusedStitch, SolveFromRangesEqualsSolveFromAStoredFieldBitForBit) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  {
    SCOPED_TRACE("34 560 tets");
    expectFusedSolveEqualsStoredField(largeMesh(), rng);
  }
  {
    SCOPED_TRACE("8 448 tets");
    expectFusedSolveEqualsStoredField(mediumMesh(), rng);
  }
  {
    SCOPED_TRACE("2 592 tets");
    expectFusedSolveEqualsStoredField(smallMesh(), rng);
  }
}

void expectKeepTargetsOffGivesTheSameVertices(double twist, std::mt19937& rng) {
  const TetMesh rest = mediumMesh();
  const Eigen::Vector3d base(0.0, 0.0, -1.375);
  const std::vector<Vertices> examples = {
      twistAboutAxis(rest.vertices, base, Eigen::Vector3d::UnitZ(), twist, 2.75),
      testing::smoothWarp(rest.vertices, 0.1, rng)};
  ShapeBlenderOptions options;
  for (BlendMethod method : allBlendMethods()) {
    // alexa has no real logarithm of a tet turned past pi.
    if (method == BlendMethod::kAlexa && twist > kPi) continue;
    if (method != BlendMethod::kVertexLinear) options.methods.push_back(method);
  }
  ShapeBlenderOptions keep = options;
  keep.keepTargets = true;
  const ShapeBlender fused(rest, examples, options);
  const ShapeBlender stored(rest, examples, keep);
  std::uniform_real_distribution<double> weight(-0.2, 1.0);
  const std::vector<double> w = {weight(rng), weight(rng)};
  for (BlendMethod method : options.methods) {
    SCOPED_TRACE(blendMethodName(method));
    const BlendResult a = fused.blend(w, method);
    const BlendResult b = stored.blend(w, method);
    EXPECT_TRUE(a.targets.empty());
    ASSERT_EQ(static_cast<Eigen::Index>(b.targets.size()), rest.tets.rows());
    EXPECT_TRUE(a.vertices == b.vertices);
    // And the stored field is what the stitch solved for.
    EXPECT_TRUE(stored.stitch().solve(b.targets, stored.blendedCentroids(w)) == b.vertices);
  }
}

TEST(FusedStitch, KeepTargetsOffGivesTheSameVerticesForEveryMethod) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  {
    SCOPED_TRACE("twist 0.8 pi: no rotation-lift corrections");
    expectKeepTargetsOffGivesTheSameVertices(0.8 * kPi, rng);
  }
  {
    // kaji and liebodies then store lift corrections for the first
    // example's far end only (the warp needs none).
    SCOPED_TRACE("twist 2.2 pi");
    expectKeepTargetsOffGivesTheSameVertices(2.2 * kPi, rng);
  }
}

}  // namespace
}  // namespace tetblend
