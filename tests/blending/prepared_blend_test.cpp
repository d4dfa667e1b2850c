// The prepared per-tet blenders against the core kernels they stand for:
// polar-slerp decomposes every example once at preparation, so its targets
// must equal core's polarSlerpBlend (Shoemake–Duff, decomposing on every
// call) of the rest and the example maps, tet by tet.

#include <gtest/gtest.h>

#include <random>

#include "blending_test_support.h"
#include "tetblend/blending/blend_method.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/blending/tet_adjacency.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/baselines.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// Same polar factors and the same combination; the prepared stretch is
// symmetrised (S = R^T F is symmetric only to round-off), so the two agree to
// a few ulps of |B| ~ 1, far below any blending difference.
constexpr double kSameKernelAbsolute = 1e-13;

Eigen::Matrix4d homogeneous(const Eigen::Matrix3d& linear) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a.topLeftCorner<3, 3>() = linear;
  return a;
}

void expectPolarSlerpMatchesCore(int exampleCount, std::mt19937& rng) {
  const TetMesh rest = boxTetMesh(2, 2, 4, Eigen::Vector3d(1.0, 1.0, 2.0));
  const Eigen::Vector3d base(0.0, 0.0, -1.0);
  std::vector<Vertices> examples = {
      twistAboutAxis(rest.vertices, base, Eigen::Vector3d::UnitZ(), 0.9 * kPi, 2.0),
      bendAboutAxis(rest.vertices, base, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                    kPi / 3.0, 2.0),
      testing::smoothWarp(rest.vertices, 0.1, rng)};
  examples.resize(exampleCount);
  ShapeBlenderOptions options;
  options.methods = {BlendMethod::kPolarSlerp};
  options.keepTargets = true;
  const ShapeBlender blender(rest, examples, options);
  std::vector<std::vector<Eigen::Matrix3d>> gradients;
  for (int k = 0; k < exampleCount; ++k) {
    gradients.push_back(deformationGradients(rest, blender.stitch().restData(), examples[k], k));
  }
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<double> w(exampleCount);
    for (double& x : w) x = weight(rng);
    // Trial 0: unit weight on the last example (pivot = that example).
    if (trial == 0) std::fill(w.begin(), w.end() - 1, 0.0), w.back() = 1.0;
    SCOPED_TRACE("trial " + std::to_string(trial));
    const BlendResult result = blender.blend(w, BlendMethod::kPolarSlerp);
    std::vector<double> all = {1.0};
    for (double x : w) all[0] -= x;
    all.insert(all.end(), w.begin(), w.end());
    for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
      std::vector<Eigen::Matrix4d> maps = {Eigen::Matrix4d::Identity()};
      for (int k = 0; k < exampleCount; ++k) maps.push_back(homogeneous(gradients[k][j]));
      const Eigen::Matrix3d expected = polarSlerpBlend(all, maps).topLeftCorner<3, 3>();
      ASSERT_LT((result.targets[j] - expected).cwiseAbs().maxCoeff(), kSameKernelAbsolute)
          << "tet " << j;
    }
  }
}

TEST(PreparedBlend, PolarSlerpEqualsCorePolarSlerpBlendWithOneExample) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  expectPolarSlerpMatchesCore(1, rng);  // slerp branch (two maps)
}

TEST(PreparedBlend, PolarSlerpEqualsCorePolarSlerpBlendWithThreeExamples) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  expectPolarSlerpMatchesCore(3, rng);  // sign-aligned quaternion sum branch
}

// Preparation runs over fixed tet chunks in parallel; when several tets cannot
// be parametrised, the error must name the first of them on every run, not
// whichever chunk failed first in time. diag(-1, -2, 1) has det > 0 but two
// distinct negative eigenvalues, so it has no real logarithm (alexa refuses
// it). The bad tets sit in different 1024-tet chunks; 5200 opens the upper
// half of the chunks, where a second thread starts, so it tends to fail first
// in time (the run without the ordered rethrow named it in 20 of 20 runs).
TEST(PreparedBlend, PreparationErrorNamesTheFirstBadTetWhateverTheSchedule) {
  const TetMesh rest = boxTetMesh(12, 12, 12, Eigen::Vector3d::Ones());  // 10368 tets
  const RestTetData restData = restTetData(rest);
  const std::vector<Vertices> examples = {rest.vertices};
  std::vector<std::vector<Eigen::Matrix3d>> gradients(
      1, std::vector<Eigen::Matrix3d>(rest.tets.rows(), Eigen::Matrix3d::Identity()));
  const Eigen::Matrix3d noRealLog = Eigen::Vector3d(-1.0, -2.0, 1.0).asDiagonal();
  for (int bad : {9000, 5200, 4000}) gradients[0][static_cast<size_t>(bad)] = noRealLog;
  const TetAdjacency adjacency = buildTetAdjacency(rest.tets);
  const TetComponents components = tetComponents(adjacency);
  BlendInput input;
  input.rest = &rest;
  input.restData = &restData;
  input.examples = &examples;
  input.gradients = &gradients;
  input.adjacency = &adjacency;
  input.components = &components;
  for (int run = 0; run < 20; ++run) {
    try {
      prepareTetMapBlender(BlendMethod::kAlexa, input);
      FAIL() << "alexa prepared a map without a real logarithm";
    } catch (const DomainError& error) {
      EXPECT_NE(std::string(error.what()).find("tet 4000:"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace tetblend
