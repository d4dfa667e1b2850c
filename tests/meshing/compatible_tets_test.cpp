#include "tetblend/meshing/compatible_tets.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Affine reproduction: one sparse Cholesky solve plus ARAP iterations that
// must stay at the affine fixed point; 1e-9 of the bbox diagonal leaves room
// for cond(K) ~ 1e4 on these meshes times ε.
constexpr double kAffineRelativeTolerance = 1e-9;

unsigned testSeed() {
  const char* env = std::getenv("TETBLEND_SEED");
  const unsigned seed = env ? static_cast<unsigned>(std::stoul(env)) : 20240611u;
  std::cout << "[ seed ] TETBLEND_SEED=" << seed << "\n";
  return seed;
}

// Independent inversion count: signed volumes straight from tet_geometry.
int countInverted(const Vertices& vertices, const Tets& tets) {
  int count = 0;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (!(tetSignedVolume(vertices, tets.row(t)) > 0.0)) ++count;
  }
  return count;
}

struct Case {
  BoundaryFirstMesh rest;
  Vertices example;  // full procedural deformation; only its surface rows are used
};

Vertices surfaceOf(const Case& c) { return c.example.topRows(c.rest.boundaryVertexCount); }

Case twistedBar(double width, double length, int n, double angle) {
  Case c;
  c.rest = reorderBoundaryFirst(boxTetMesh(n, n, static_cast<int>(n * length / width),
                                           Eigen::Vector3d(width, width, length)));
  c.example = twistAboutAxis(c.rest.mesh.vertices, Eigen::Vector3d(0, 0, -length / 2),
                             Eigen::Vector3d::UnitZ(), angle, length);
  return c;
}

Case skinnedLimb(bool dualQuaternion, const Eigen::Vector3d& axis) {
  Case c;
  c.rest = reorderBoundaryFirst(cylinderTetMesh(3, 64, 0.3, 6.0));
  const Eigen::MatrixXd weights =
      twoBoneWeights(c.rest.mesh.vertices, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 2.5);
  const std::vector<Eigen::Isometry3d> bones = {
      Eigen::Isometry3d::Identity(),
      rotationAboutLine(Eigen::Vector3d::Zero(), axis, 170.0 * kPi / 180.0)};
  c.example = dualQuaternion ? dualQuaternionSkinning(c.rest.mesh.vertices, weights, bones)
                             : linearBlendSkinning(c.rest.mesh.vertices, weights, bones);
  return c;
}

// Places the example and checks the contract: boundary reproduced bit for
// bit, the inverted list agrees with an independent count.
CompatibleTetResult placeAndCheck(const Case& c, const CompatibleTetOptions& options = {}) {
  const CompatibleTetBuilder builder(c.rest.mesh, c.rest.boundaryVertexCount, options);
  const Vertices surface = surfaceOf(c);
  CompatibleTetResult result = builder.place(surface);
  EXPECT_EQ(result.vertices.topRows(surface.rows()), surface) << "boundary must be the example";
  EXPECT_EQ(static_cast<int>(result.invertedTets.size()),
            countInverted(result.vertices, c.rest.mesh.tets));
  EXPECT_EQ(result.harmonicInvertedCount,
            countInverted(builder.harmonicExtension(surface), c.rest.mesh.tets));
  return result;
}

TEST(CompatibleTets, AffineBoundaryGivesAffineInterior) {
  const unsigned seed = testSeed();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const BoundaryFirstMesh rest =
      reorderBoundaryFirst(boxTetMesh(5, 4, 6, Eigen::Vector3d(1.0, 0.8, 1.4)));
  const CompatibleTetBuilder builder(rest.mesh, rest.boundaryVertexCount);
  for (int sample = 0; sample < 5; ++sample) {
    Eigen::Matrix3d linear = Eigen::Matrix3d::Identity() +
                             0.6 * Eigen::Matrix3d::NullaryExpr([&] { return uniform(rng); });
    if (linear.determinant() < 0) linear.col(0) *= -1.0;  // orientation preserving
    const Eigen::Vector3d shift(uniform(rng), uniform(rng), uniform(rng));
    Vertices expected(rest.mesh.vertices.rows(), 3);
    for (Eigen::Index v = 0; v < expected.rows(); ++v) {
      expected.row(v) = (linear * rest.mesh.vertices.row(v).transpose() + shift).transpose();
    }
    const Vertices surface = expected.topRows(rest.boundaryVertexCount);
    const double tolerance = kAffineRelativeTolerance * boundingBoxDiagonal(expected);
    const Vertices harmonic = builder.harmonicExtension(surface);
    EXPECT_LT((harmonic - expected).cwiseAbs().maxCoeff(), tolerance) << "sample " << sample;
    const CompatibleTetResult result = builder.place(surface);
    EXPECT_LT((result.vertices - expected).cwiseAbs().maxCoeff(), tolerance) << "sample " << sample;
    EXPECT_TRUE(result.invertedTets.empty());
    EXPECT_EQ(result.untangleRounds, 0);
  }
}

TEST(CompatibleTets, TwistByTwoAndFourPiOfALongBarHasNoInvertedTet) {
  for (const double angle : {2.0 * kPi, 4.0 * kPi}) {
    const CompatibleTetResult result = placeAndCheck(twistedBar(1.0, 6.0, 4, angle));
    EXPECT_TRUE(result.invertedTets.empty()) << "angle " << angle;
    EXPECT_GT(result.minVolumeRatio, 0.0);
  }
}

// Hard twists: a 4π twist of a 1×1×2 bar and a 2π twist of a 2×2×2 cube. The
// harmonic extension folds tets near the axis; the full pipeline does not.
TEST(CompatibleTets, HardTwistsInvertHarmonicButNotThePipeline) {
  const std::vector<Case> cases = {twistedBar(1.0, 2.0, 5, 4.0 * kPi),
                                   twistedBar(2.0, 2.0, 5, 2.0 * kPi)};
  for (const Case& c : cases) {
    // The procedural interior is valid, so a valid placement exists.
    ASSERT_EQ(countInverted(c.example, c.rest.mesh.tets), 0);
    const CompatibleTetResult result = placeAndCheck(c);
    EXPECT_GT(result.harmonicInvertedCount, 0);
    EXPECT_TRUE(result.invertedTets.empty());
  }
}

TEST(CompatibleTets, BendBy180DegreesHasNoInvertedTet) {
  const double length = 4.0;
  Case c;
  c.rest = reorderBoundaryFirst(boxTetMesh(20, 5, 5, Eigen::Vector3d(length, 1.0, 1.0)));
  c.example = bendAboutAxis(c.rest.mesh.vertices, Eigen::Vector3d(-length / 2, 0, 0),
                            Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), kPi, length);
  const CompatibleTetResult result = placeAndCheck(c);
  EXPECT_TRUE(result.invertedTets.empty());
  EXPECT_GT(result.minVolumeRatio, 0.0);
}

TEST(CompatibleTets, SkinnedLimbsAt170DegreesHaveNoInvertedTet) {
  for (const bool dualQuaternion : {false, true}) {
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0)}) {
      if (!dualQuaternion && axis.z() == 1) continue;  // see the LBS bend test below
      const CompatibleTetResult result = placeAndCheck(skinnedLimb(dualQuaternion, axis));
      EXPECT_TRUE(result.invertedTets.empty())
          << (dualQuaternion ? "DQS" : "LBS") << " axis " << axis.transpose();
    }
  }
}

TEST(CompatibleTets, HarmonicOnlyReportsItsInvertedTetsExactly) {
  CompatibleTetOptions options;
  options.arapIterations = 0;
  options.propagateRotations = false;
  options.untangle = false;
  const Case c = twistedBar(1.0, 2.0, 5, 4.0 * kPi);
  const CompatibleTetResult result = placeAndCheck(c, options);
  ASSERT_FALSE(result.invertedTets.empty());
  EXPECT_EQ(static_cast<int>(result.invertedTets.size()), result.harmonicInvertedCount);
  ASSERT_EQ(result.invertedVolumes.size(), result.invertedTets.size());
  for (size_t i = 0; i < result.invertedTets.size(); ++i) {
    const double volume =
        tetSignedVolume(result.vertices, c.rest.mesh.tets.row(result.invertedTets[i]));
    EXPECT_EQ(result.invertedVolumes[i], volume);
    EXPECT_LE(volume, 0.0);
  }
  EXPECT_LE(result.minVolumeRatio, 0.0);
}

TEST(CompatibleTets, UntanglingAloneRepairsTheHarmonicExtension) {
  CompatibleTetOptions options;
  options.arapIterations = 0;
  options.propagateRotations = false;
  const CompatibleTetResult result = placeAndCheck(twistedBar(2.0, 2.0, 5, 2.0 * kPi), options);
  EXPECT_GT(result.harmonicInvertedCount, 0);
  EXPECT_GT(result.untangleRounds, 0);
  EXPECT_TRUE(result.invertedTets.empty());
}

TEST(CompatibleTets, RejectsBadInput) {
  const BoundaryFirstMesh rest = reorderBoundaryFirst(boxTetMesh(3, 3, 3, Eigen::Vector3d::Ones()));
  // A surface count that leaves a boundary vertex among the "interior" ones.
  EXPECT_THROW(CompatibleTetBuilder(rest.mesh, rest.boundaryVertexCount - 1), InputError);
  EXPECT_THROW(CompatibleTetBuilder(rest.mesh, 0), InputError);
  TetMesh flipped = rest.mesh;
  std::swap(flipped.tets(7, 0), flipped.tets(7, 1));
  EXPECT_THROW(CompatibleTetBuilder(flipped, rest.boundaryVertexCount), InputError);
  const CompatibleTetBuilder builder(rest.mesh, rest.boundaryVertexCount);
  EXPECT_THROW(builder.place(rest.mesh.vertices), InputError);  // #V rows, not #S
  Vertices surface = rest.mesh.vertices.topRows(rest.boundaryVertexCount);
  surface(3, 1) = NAN;
  EXPECT_THROW(builder.place(surface), InputError);
}

}  // namespace
}  // namespace tetblend
