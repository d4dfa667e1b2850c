// The prepared per-tet blenders against the core kernels they stand for:
// polar-slerp decomposes every example once at preparation, so its targets
// must equal core's polarSlerpBlend (Shoemake–Duff, decomposing on every
// call) of the rest and the example maps, tet by tet.

#include <gtest/gtest.h>

#include <random>

#include "blending_test_support.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/baselines.h"
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
      twistAboutAxis(rest.vertices, base, Eigen::Vector3d::UnitZ(), 0.9 * M_PI, 2.0),
      bendAboutAxis(rest.vertices, base, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                    M_PI / 3.0, 2.0),
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

}  // namespace
}  // namespace tetblend
