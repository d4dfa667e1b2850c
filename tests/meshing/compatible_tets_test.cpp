#include "tetblend/meshing/compatible_tets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "test_seed.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// Affine reproduction: one sparse Cholesky solve plus ARAP iterations that
// must stay at the affine fixed point; 1e-9 of the bbox diagonal leaves room
// for cond(K) ~ 1e4 on these meshes times ε.
constexpr double kAffineRelativeTolerance = 1e-9;

unsigned testSeed() { return test_seed::seedOfCurrentTest(20240611u); }

// Independent inversion count: signed volumes straight from tet_geometry.
int countInverted(const Vertices& vertices, const Tets& tets) {
  int count = 0;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (!(tetSignedVolume(vertices, tets.row(t)) > 0.0)) ++count;
  }
  return count;
}

// ARAP energy Σ_t vol_t ‖F_t − R_t‖² / Σ_t vol_t with R_t from a full SVD
// (reflection removed) and min_t det F_t, computed here independently of the
// builder: F_t = D_t(x) D_t(rest)⁻¹ from tetEdgeMatrix.
struct Distortion {
  double energy = 0.0;
  double minDet = INFINITY;
};

Distortion distortionOf(const Vertices& rest, const Vertices& deformed, const Tets& tets) {
  Distortion d;
  double volume = 0.0;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    const Eigen::Matrix3d restEdges = tetEdgeMatrix(rest, tets.row(t));
    const Eigen::Matrix3d f = tetEdgeMatrix(deformed, tets.row(t)) * restEdges.inverse();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    if ((u * svd.matrixV().transpose()).determinant() < 0) u.col(2) *= -1.0;
    const double restVolume = restEdges.determinant() / 6.0;
    d.energy += restVolume * (f - u * svd.matrixV().transpose()).squaredNorm();
    volume += restVolume;
    d.minDet = std::min(d.minDet, f.determinant());
  }
  d.energy /= volume;
  return d;
}

// Both placement policies: accept the first valid candidate (default) and
// run ARAP to convergence.
std::vector<CompatibleTetOptions> bothStopPolicies() {
  CompatibleTetOptions converge;
  converge.stopWhenValid = false;
  return {CompatibleTetOptions{}, converge};
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
  for (const CompatibleTetOptions& options : bothStopPolicies()) {
    for (const double angle : {2.0 * kPi, 4.0 * kPi}) {
      const CompatibleTetResult result = placeAndCheck(twistedBar(1.0, 6.0, 4, angle), options);
      EXPECT_TRUE(result.invertedTets.empty())
          << "angle " << angle << " stopWhenValid " << options.stopWhenValid;
      EXPECT_GT(result.minVolumeRatio, 0.0);
    }
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
  for (const CompatibleTetOptions& options : bothStopPolicies()) {
    const CompatibleTetResult result = placeAndCheck(c, options);
    EXPECT_TRUE(result.invertedTets.empty()) << "stopWhenValid " << options.stopWhenValid;
    EXPECT_GT(result.minVolumeRatio, 0.0);
  }
}

TEST(CompatibleTets, SkinnedLimbsAt170DegreesHaveNoInvertedTet) {
  for (const bool dualQuaternion : {false, true}) {
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0)}) {
      if (!dualQuaternion && axis.z() == 1) continue;  // see the LBS bend test below
      for (const CompatibleTetOptions& options : bothStopPolicies()) {
        const CompatibleTetResult result =
            placeAndCheck(skinnedLimb(dualQuaternion, axis), options);
        EXPECT_TRUE(result.invertedTets.empty())
            << (dualQuaternion ? "DQS" : "LBS") << " axis " << axis.transpose() << " stopWhenValid "
            << options.stopWhenValid;
      }
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

// Reported energy and min det agree with the independent SVD oracle; the
// builder takes singular values from eig(FᵀF), whose smallest carries an
// absolute error ~eps·σ₁², so 1e-9 relative covers these meshes (σ ≤ ~10).
constexpr double kDistortionRelativeTolerance = 1e-9;

void expectDistortionReported(const Case& c, const CompatibleTetResult& result) {
  const Distortion oracle = distortionOf(c.rest.mesh.vertices, result.vertices, c.rest.mesh.tets);
  EXPECT_NEAR(result.arapEnergy, oracle.energy, kDistortionRelativeTolerance * oracle.energy);
  EXPECT_NEAR(result.minVolumeRatio, oracle.minDet,
              kDistortionRelativeTolerance * std::max(1.0, std::abs(oracle.minDet)));
}

// A 2π twist of a long bar: the harmonic extension has no inverted tet, so by
// default it is the result with no ARAP iteration; stopWhenValid = false runs
// ARAP from it and must lower the ARAP energy without inverting a tet.
TEST(CompatibleTets, ValidHarmonicExtensionIsAcceptedWithoutArap) {
  const Case c = twistedBar(1.0, 6.0, 4, 2.0 * kPi);
  const CompatibleTetBuilder builder(c.rest.mesh, c.rest.boundaryVertexCount);
  const Vertices harmonic = builder.harmonicExtension(surfaceOf(c));
  ASSERT_EQ(countInverted(harmonic, c.rest.mesh.tets), 0);

  const CompatibleTetResult accepted = placeAndCheck(c);
  EXPECT_EQ(accepted.harmonicInvertedCount, 0);
  EXPECT_EQ(accepted.arapIterations, 0);
  EXPECT_EQ(accepted.untangleRounds, 0);
  EXPECT_EQ(accepted.vertices, harmonic);
  expectDistortionReported(c, accepted);

  CompatibleTetOptions options;
  options.stopWhenValid = false;
  const CompatibleTetResult converged = placeAndCheck(c, options);
  EXPECT_GT(converged.arapIterations, 0);
  EXPECT_TRUE(converged.invertedTets.empty());
  EXPECT_LT(converged.arapEnergy, accepted.arapEnergy);
  expectDistortionReported(c, converged);
}

// A 4π twist of a short bar inverts the harmonic extension: ARAP and
// untangling still run by default, stop no later than without
// stopWhenValid, and both leave no inverted tet.
TEST(CompatibleTets, InvertedHarmonicExtensionStillRunsArap) {
  const Case c = twistedBar(1.0, 2.0, 5, 4.0 * kPi);
  const CompatibleTetResult stopped = placeAndCheck(c);
  ASSERT_GT(stopped.harmonicInvertedCount, 0);
  EXPECT_TRUE(stopped.invertedTets.empty());
  EXPECT_GT(stopped.minVolumeRatio, 0.0);
  expectDistortionReported(c, stopped);

  CompatibleTetOptions options;
  options.stopWhenValid = false;
  const CompatibleTetResult converged = placeAndCheck(c, options);
  EXPECT_TRUE(converged.invertedTets.empty());
  EXPECT_GT(converged.arapIterations, 0);
  EXPECT_LE(stopped.arapIterations, converged.arapIterations);
  expectDistortionReported(c, converged);
}

// factor() does up front what the first placement would: the placements
// after it are the same, bit for bit.
TEST(CompatibleTets, FactoringUpFrontChangesNoPlacement) {
  const Case c = twistedBar(1.0, 2.0, 5, 4.0 * kPi);
  const CompatibleTetBuilder first(c.rest.mesh, c.rest.boundaryVertexCount);
  first.factor();
  const CompatibleTetBuilder lazy(c.rest.mesh, c.rest.boundaryVertexCount);
  const Vertices surface = surfaceOf(c);
  EXPECT_EQ(first.place(surface).vertices, lazy.place(surface).vertices);
  EXPECT_EQ(first.harmonicExtension(surface), lazy.harmonicExtension(surface));
}

// releaseFactor() frees the interior's factorisation; the next placement
// factors again and places as before, bit for bit, after each release.
TEST(CompatibleTets, PlacingAfterReleasingTheFactorPlacesTheSame) {
  const Case c = twistedBar(1.0, 2.0, 5, 4.0 * kPi);
  const CompatibleTetBuilder builder(c.rest.mesh, c.rest.boundaryVertexCount);
  const Vertices surface = surfaceOf(c);
  const Vertices placed = builder.place(surface).vertices;
  const Vertices harmonic = builder.harmonicExtension(surface);
  builder.releaseFactor();
  EXPECT_EQ(builder.harmonicExtension(surface), harmonic);
  builder.releaseFactor();
  EXPECT_EQ(builder.place(surface).vertices, placed);
}

// place(surface, iterations, rings): ARAP over the interior vertices within
// `rings` tet-rings of the harmonic map's inverted tets only, every other
// vertex left at the harmonic map bit for bit; a region of more than half
// the interior gives the whole interior's search, bit for bit.
TEST(CompatibleTets, LocalArapMovesOnlyTheRingAroundTheHarmonicMapsInvertedTets) {
  // A box whose top face is dented at its centre vertex, 0.6 of its height
  // deep: the harmonic map leaves that vertex's neighbours above it.
  Case c;
  c.rest = reorderBoundaryFirst(boxTetMesh(8, 8, 8, Eigen::Vector3d(1.0, 1.0, 1.0)));
  c.example = c.rest.mesh.vertices;
  const Eigen::Index top = [&] {
    Eigen::Index best = 0;
    const Eigen::RowVector3d corner = c.rest.mesh.vertices.colwise().maxCoeff();
    const Eigen::RowVector3d centre = 0.5 * (corner + c.rest.mesh.vertices.colwise().minCoeff());
    const Eigen::RowVector3d target(centre.x(), centre.y(), corner.z());
    for (Eigen::Index v = 0; v < c.rest.boundaryVertexCount; ++v) {
      if ((c.example.row(v) - target).norm() < (c.example.row(best) - target).norm()) best = v;
    }
    return best;
  }();
  c.example(top, 2) -= 0.6;
  const Tets& tets = c.rest.mesh.tets;
  CompatibleTetOptions options;
  options.untangle = false;
  const CompatibleTetBuilder builder(c.rest.mesh, c.rest.boundaryVertexCount, options);
  const Vertices surface = surfaceOf(c);
  const Vertices harmonic = builder.harmonicExtension(surface);
  // One ring: the vertices of tets that share a vertex with an inverted tet.
  std::vector<char> nearInverted(static_cast<std::size_t>(harmonic.rows()), 0);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (tetSignedVolume(harmonic, tets.row(t)) > 0.0) continue;
    for (int a = 0; a < 4; ++a) nearInverted[static_cast<std::size_t>(tets(t, a))] = 1;
  }
  std::vector<char> ring = nearInverted;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    bool touches = false;
    for (int a = 0; a < 4; ++a)
      touches = touches || nearInverted[static_cast<std::size_t>(tets(t, a))];
    if (!touches) continue;
    for (int a = 0; a < 4; ++a) ring[static_cast<std::size_t>(tets(t, a))] = 1;
  }
  ASSERT_GT(countInverted(harmonic, tets), 0);

  const CompatibleTetResult local = builder.place(surface, 5, 1);
  int moved = 0;
  for (Eigen::Index v = 0; v < harmonic.rows(); ++v) {
    if (local.vertices.row(v) == harmonic.row(v)) continue;
    ++moved;
    EXPECT_GE(v, c.rest.boundaryVertexCount) << "a surface vertex moved";
    EXPECT_TRUE(ring[static_cast<std::size_t>(v)]) << "vertex " << v << " is beyond the ring";
  }
  EXPECT_GT(moved, 0);
  EXPECT_LE(local.invertedTets.size(), static_cast<std::size_t>(countInverted(harmonic, tets)));

  const CompatibleTetResult wide = builder.place(surface, 5, 1000);
  EXPECT_EQ(wide.vertices, builder.place(surface, 5).vertices);
}

// ARAP's local–global iteration converges linearly, so stopping once an
// iteration lowers the energy by less than arapStallFall = 1e-4 leaves it
// within about 1e-4 / (1 − ρ) of its limit; 1 % allows a rate ρ up to 0.99.
constexpr double kArapStallEnergySlack = 1e-2;

// CompatibleTetOptions::arapStallFall: run to convergence from a valid 2π
// twist (stopWhenValid = false, up to 200 iterations), ARAP stops earlier
// with the default fall than with the movement tolerance alone, at nearly
// the same energy.
TEST(CompatibleTets, ArapStopsOnceItsEnergyStalls) {
  const Case c = twistedBar(1.0, 6.0, 4, 2.0 * kPi);
  CompatibleTetOptions stalling;
  stalling.stopWhenValid = false;
  stalling.arapIterations = 200;
  CompatibleTetOptions moving = stalling;
  moving.arapStallFall = 0.0;
  const CompatibleTetResult stopped = placeAndCheck(c, stalling);
  const CompatibleTetResult converged = placeAndCheck(c, moving);
  std::cout << "  ARAP iterations " << stopped.arapIterations << " (energy " << stopped.arapEnergy
            << ") against " << converged.arapIterations << " (" << converged.arapEnergy << ")\n";
  EXPECT_LT(stopped.arapIterations, converged.arapIterations);
  EXPECT_TRUE(stopped.invertedTets.empty());
  EXPECT_LE(stopped.arapEnergy, (1.0 + kArapStallEnergySlack) * converged.arapEnergy);
}

// The harmonic extension solves Σ_t vol_t G_tᵀ G_t x = 0 on the interior
// rows, with K assembled here independently (dense, gradients of the
// barycentric coordinates from the inverse edge matrix) and a non-affine
// boundary (a twist plus a random jitter of the surface). Residual bound:
// round-off of a Cholesky solve, |K| |x| eps cond(K) with cond ~ 1e3 here.
constexpr double kLaplaceRelativeResidual = 1e-10;

TEST(CompatibleTets, HarmonicExtensionSolvesTheDiscreteLaplaceEquation) {
  const unsigned seed = testSeed();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  const Case c = twistedBar(1.0, 2.0, 4, 0.7 * kPi);
  Vertices surface = surfaceOf(c);
  for (Eigen::Index i = 0; i < surface.size(); ++i) surface.data()[i] += jitter(rng);
  const CompatibleTetBuilder builder(c.rest.mesh, c.rest.boundaryVertexCount);
  const Vertices x = builder.harmonicExtension(surface);
  ASSERT_EQ(x.topRows(surface.rows()), surface);

  const Vertices& rest = c.rest.mesh.vertices;
  const Tets& tets = c.rest.mesh.tets;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(rest.rows(), rest.rows());
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    const Eigen::Matrix3d edges = tetEdgeMatrix(rest, tets.row(t));
    Eigen::Matrix<double, 3, 4> gradients;  // ∇λ_a as columns, λ_0 = 1 − Σ λ_1..3
    gradients.rightCols<3>() = edges.inverse().transpose();
    gradients.col(0) = -gradients.rightCols<3>().rowwise().sum();
    const Eigen::Matrix4d local = edges.determinant() / 6.0 * gradients.transpose() * gradients;
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) k(tets(t, a), tets(t, b)) += local(a, b);
    }
  }
  const Eigen::MatrixXd residual = (k * x).bottomRows(rest.rows() - surface.rows());
  EXPECT_LT(residual.cwiseAbs().maxCoeff(),
            kLaplaceRelativeResidual * k.cwiseAbs().maxCoeff() * x.cwiseAbs().maxCoeff());
}

TEST(CompatibleTets, RejectsAFaceSharedByThreeTets) {
  const BoundaryFirstMesh rest = reorderBoundaryFirst(boxTetMesh(3, 3, 3, Eigen::Vector3d::Ones()));
  TetMesh duplicated = rest.mesh;
  duplicated.tets.conservativeResize(duplicated.tets.rows() + 1, 4);
  duplicated.tets.bottomRows(1) = duplicated.tets.row(5);
  try {
    const CompatibleTetBuilder builder(duplicated, rest.boundaryVertexCount);
    ADD_FAILURE() << "a face shared by 3 tets was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("more than 2 tets"), std::string::npos)
        << error.what();
  }
}

TEST(CompatibleTets, RejectsBadInput) {
  const BoundaryFirstMesh rest = reorderBoundaryFirst(boxTetMesh(3, 3, 3, Eigen::Vector3d::Ones()));
  // A surface count that leaves a boundary vertex among the "interior" ones.
  try {
    const CompatibleTetBuilder builder(rest.mesh, rest.boundaryVertexCount - 1);
    ADD_FAILURE() << "a boundary vertex was accepted as interior";
  } catch (const InputError& error) {
    // The vertex named is the one moved out of the surface range.
    EXPECT_NE(std::string(error.what())
                  .find("vertex " + std::to_string(rest.boundaryVertexCount - 1) + " lies on"),
              std::string::npos)
        << error.what();
  }
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
