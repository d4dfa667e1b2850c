#include "tetblend/blending/shape_blender.h"

#include <gtest/gtest.h>

#include "blending_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// Interpolation is exact up to round-off: psi/phi round trips (~1e-15) and a
// stitch of a compatible field (~1e-13 on these meshes); the contract is 1e-9
// of the bounding-box diagonal.
constexpr double kInterpolationRelative = 1e-9;
// Rigid inputs give a compatible rigid field; edge lengths are kept to
// round-off, contract 1e-9 relative.
constexpr double kRigidRelative = 1e-9;
// Volume of a blend at weight 1 against the example's: the blend reproduces
// the example to kInterpolationRelative of its size, which moves a volume
// summed over the tets by about that much relative.
constexpr double kVolumeRelative = 1e-9;

const std::vector<BlendMethod>& testedMethods() { return allBlendMethods(); }

double maxRowDistance(const Vertices& a, const Vertices& b) {
  return (a - b).rowwise().norm().maxCoeff();
}

using Fixture = testing::BarExamples;

// A 1 x 1 x 3 bar with three examples: twisted by 3 pi / 4, bent by 60
// degrees, and warped then moved away (every example tet stays positive).
Fixture barFixture(std::mt19937& rng) {
  Fixture f = testing::twistedAndBentBar(6, 0.75 * kPi);
  f.examples.push_back(testing::smoothWarp(f.rest.vertices, 0.1, rng).rowwise() +
                       Eigen::RowVector3d(0.3, -0.2, 1.0));
  return f;
}

ShapeBlenderOptions allMethods() {
  ShapeBlenderOptions options;
  options.methods = testedMethods();
  return options;
}

TEST(ShapeBlender, ZeroWeightsGiveTheRestAndUnitVectorsGiveEachExample) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const Fixture f = barFixture(rng);
  const ShapeBlender blender(f.rest, f.examples, allMethods());
  for (BlendMethod method : testedMethods()) {
    SCOPED_TRACE(blendMethodName(method));
    const Vertices rest = blender.blend({0.0, 0.0, 0.0}, method).vertices;
    EXPECT_LT(maxRowDistance(rest, f.rest.vertices),
              kInterpolationRelative * boundingBoxDiagonal(f.rest.vertices));
    for (int k = 0; k < 3; ++k) {
      std::vector<double> unit(3, 0.0);
      unit[k] = 1.0;
      const Vertices example = blender.blend(unit, method).vertices;
      EXPECT_LT(maxRowDistance(example, f.examples[k]),
                kInterpolationRelative * boundingBoxDiagonal(f.examples[k]))
          << "example " << k;
    }
  }
}

double maxRelativeEdgeChange(const TetMesh& rest, const Vertices& x) {
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  double worst = 0.0;
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
    for (const auto& e : kEdges) {
      const int a = rest.tets(j, e[0]), b = rest.tets(j, e[1]);
      const double before = (rest.vertices.row(a) - rest.vertices.row(b)).norm();
      const double after = (x.row(a) - x.row(b)).norm();
      worst = std::max(worst, std::abs(after - before) / before);
    }
  }
  return worst;
}

TEST(ShapeBlender, RigidExamplesBlendToRigidShapes) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  const TetMesh rest = boxTetMesh(2, 3, 4, Eigen::Vector3d(1.0, 1.5, 2.0));
  // Two rigid motions, one with an angle beyond pi/2 and one near pi.
  std::vector<Vertices> examples;
  const Eigen::Vector3d axes[2] = {Eigen::Vector3d(1, 2, 3).normalized(),
                                   Eigen::Vector3d(-1, 0.5, 0.2).normalized()};
  const double angles[2] = {2.0, 3.0};
  for (int k = 0; k < 2; ++k) {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angles[k], axes[k]).toRotationMatrix();
    examples.push_back((rest.vertices * r.transpose()).rowwise() +
                       Eigen::RowVector3d(k + 1.0, -2.0, 0.5 * k));
  }
  ShapeBlenderOptions options;
  options.methods = {BlendMethod::kKaji, BlendMethod::kDualQuaternion, BlendMethod::kLieBodies};
  const ShapeBlender blender(rest, examples, options);
  for (BlendMethod method : options.methods) {
    SCOPED_TRACE(blendMethodName(method));
    for (int trial = 0; trial < 10; ++trial) {
      const std::vector<double> w = {weight(rng), weight(rng)};
      const Vertices x = blender.blend(w, method).vertices;
      EXPECT_LT(maxRelativeEdgeChange(rest, x), kRigidRelative)
          << "weights " << w[0] << ", " << w[1];
    }
  }
}

TEST(ShapeBlender, LinearStitchEqualsVertexLinearBlend) {
  // Linear blending of compatible gradient fields is itself compatible, so
  // the stitch reproduces the vertex-linear blend (an identity, not a
  // tolerance on the method).
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(-1.0, 2.0);
  const Fixture f = barFixture(rng);
  ShapeBlenderOptions options;
  options.methods = {BlendMethod::kLinear, BlendMethod::kVertexLinear};
  const ShapeBlender blender(f.rest, f.examples, options);
  for (int trial = 0; trial < 5; ++trial) {
    const std::vector<double> w = {weight(rng), weight(rng), weight(rng)};
    const Vertices a = blender.blend(w, BlendMethod::kLinear).vertices;
    const Vertices b = blender.blend(w, BlendMethod::kVertexLinear).vertices;
    EXPECT_LT(maxRowDistance(a, b), kInterpolationRelative * boundingBoxDiagonal(b));
  }
}

TEST(ShapeBlender, PreparedOnceEqualsFreshPreparationFor1000WeightVectors) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(-0.5, 1.5);
  const Fixture f = barFixture(rng);
  const ShapeBlender blender(f.rest, f.examples);  // kaji, the default
  BlendResult reused;
  for (int trial = 0; trial < 1000; ++trial) {
    const std::vector<double> w = {weight(rng), weight(rng), weight(rng)};
    blender.blendInto(w, BlendMethod::kKaji, reused);
    const BlendResult fresh = blendShapes(f.rest, f.examples, w);
    // Same operations in the same order: bitwise equal.
    ASSERT_TRUE(reused.vertices == fresh.vertices) << "trial " << trial;
  }
}

double totalVolume(const TetMesh& rest, const Vertices& x) {
  double sum = 0.0;
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) sum += tetSignedVolume(x, rest.tets.row(j));
  return sum;
}

TEST(ShapeBlender, LieBodiesVolumeChangesMonotonicallyBetweenTwoShapes) {
  // Bansal–Tatu §4 (monotone volume): every tet's volume moves monotonically
  // along t; the stitched total is checked here, at 21 steps of t in [0, 1].
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = boxTetMesh(2, 2, 6, Eigen::Vector3d(1.0, 1.0, 3.0));
  Vertices grown = testing::smoothWarp(rest.vertices, 0.1, rng);
  grown.col(0) *= 1.8;
  grown.col(2) *= 1.3;
  const Vertices example =
      bendAboutAxis(grown, Eigen::Vector3d(0.0, 0.0, -1.95), Eigen::Vector3d::UnitZ(),
                    Eigen::Vector3d::UnitY(), kPi / 2, 3.9);
  ShapeBlenderOptions options;
  options.methods = {BlendMethod::kLieBodies};
  const ShapeBlender blender(rest, {example}, options);
  double previous = totalVolume(rest, rest.vertices);
  const double last = totalVolume(rest, example);
  ASSERT_GT(last, previous);
  for (int step = 1; step <= 20; ++step) {
    const double volume = totalVolume(rest, blender.blend({step / 20.0}).vertices);
    EXPECT_GT(volume, previous) << "t = " << step / 20.0;
    previous = volume;
  }
  EXPECT_NEAR(previous, last, kVolumeRelative * last);
}

TEST(ShapeBlender, ErrorsNameTheProblem) {
  const TetMesh rest = boxTetMesh(1, 1, 2, Eigen::Vector3d::Ones());
  const std::vector<Vertices> examples = {rest.vertices * 1.1};
  const ShapeBlender blender(rest, examples);
  EXPECT_THROW(blender.blend({0.5, 0.5}), InputError);
  EXPECT_THROW(blender.blend({0.5}, BlendMethod::kLinear), InputError);
  EXPECT_THROW(blender.blend({std::nan("")}), InputError);
  EXPECT_THROW(ShapeBlender(rest, {}), InputError);
  EXPECT_THROW(ShapeBlender(rest, {Vertices(3, 3)}), InputError);
  EXPECT_THROW(blendMethodFromName("slerp"), InputError);
  for (BlendMethod method : allBlendMethods()) {
    EXPECT_EQ(blendMethodFromName(blendMethodName(method)), method);
    EXPECT_EQ(canonicalMethodName(blendMethodName(method)), blendMethodName(method));
  }
  // deform's name for dual quaternions is an alias of dq.
  EXPECT_EQ(canonicalMethodName("dqs"), "dq");
  EXPECT_EQ(blendMethodFromName("dqs"), BlendMethod::kDualQuaternion);
  EXPECT_EQ(methodAliasNote(), "dqs = dq");
}

}  // namespace
}  // namespace tetblend
