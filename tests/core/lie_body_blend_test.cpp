// The shape-blender helpers of lie_bodies.h: p0 exp(sum_k w_k log(p0^-1 p_k))
// per component, with principal or consistent (reference) rotation logs.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "lie_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/lie_bodies.h"

namespace tetblend {
namespace {

using lie_test::randomRotation;
using lie_test::randomTet;
using lie_test::testSeed;
using lie_test::uniform;

// Blends of unit-scale tets against closed forms (AngleAxis rotations, the
// geodesic): a few hundred roundings, relative to the corner magnitude.
constexpr double kBlendTol = 1e-12;

Eigen::Matrix3d edgesOf(const TetCorners& c) {
  Eigen::Matrix3d e;
  for (int k = 0; k < 3; ++k) e.col(k) = c.col(k + 1) - c.col(0);
  return e;
}

// `c` rotated by `r` about its first corner, then moved by `shift`.
TetCorners rotatedTet(const TetCorners& c, const Eigen::Matrix3d& r, const Eigen::Vector3d& shift) {
  TetCorners out;
  for (int k = 0; k < 4; ++k) out.col(k) = c.col(0) + r * (c.col(k) - c.col(0)) + shift;
  return out;
}

double maxAbs(const TetCorners& c) { return c.cwiseAbs().maxCoeff(); }

TEST(LieBodyBlend, ZeroAndUnitWeightsGiveRestAndExamples) {
  std::mt19937 rng(testSeed("ZeroAndUnitWeightsGiveRestAndExamples"));
  for (int i = 0; i < 50; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const TetCorners rest = randomTet(rng);
    const LieBody p0 = lieBodyFromCorners(rest);
    std::vector<TetCorners> examples;
    std::vector<LieBodyTangent> logs;
    for (int k = 0; k < 3; ++k) {
      examples.push_back(randomTet(rng));
      logs.push_back(lieBodyRelativeLog(p0, lieBodyFromCorners(examples.back())));
    }
    EXPECT_LE((lieBodyBlendCorners(p0, logs, Eigen::Vector3d::Zero()) - rest).cwiseAbs().maxCoeff(),
              kBlendTol * maxAbs(rest));
    for (int k = 0; k < 3; ++k) {
      const TetCorners got = lieBodyBlendCorners(p0, logs, Eigen::Vector3d::Unit(k));
      EXPECT_LE(
          (got - examples[k]).cwiseAbs().maxCoeff(),
          kBlendTol * (1.0 + maxAbs(examples[k])) * lieBodyFromCorners(examples[k]).shear.norm());
    }
  }
}

TEST(LieBodyBlend, OneExampleBlendIsTheGeodesic) {
  std::mt19937 rng(testSeed("OneExampleBlendIsTheGeodesic"));
  for (int i = 0; i < 50; ++i) {
    const LieBody p0 = lieBodyFromCorners(randomTet(rng));
    const LieBody p1 = lieBodyFromCorners(randomTet(rng));
    const std::vector<LieBodyTangent> logs = {lieBodyRelativeLog(p0, p1)};
    for (double t : {-0.5, 0.3, 1.4}) {
      const TetCorners want = lieBodyCorners(lieBodyInterpolate(p0, p1, t));
      const TetCorners got = lieBodyBlendCorners(p0, logs, Eigen::VectorXd::Constant(1, t));
      EXPECT_LE((got - want).cwiseAbs().maxCoeff(), kBlendTol * (1.0 + maxAbs(want)));
    }
  }
}

TEST(LieBodyBlend, SimilarExamplesBlendToASimilarity) {
  // Examples that are rotated and uniformly scaled copies of the rest blend
  // to a rotated and scaled copy: the shear component stays that of the rest.
  std::mt19937 rng(testSeed("SimilarExamplesBlendToASimilarity"));
  for (int i = 0; i < 50; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const TetCorners rest = randomTet(rng);
    const LieBody p0 = lieBodyFromCorners(rest);
    std::vector<LieBodyTangent> logs;
    for (int k = 0; k < 3; ++k) {
      const double s = std::exp(uniform(rng, -1, 1));
      const TetCorners ex = rotatedTet(
          rest, s * randomRotation(rng, 0.9 * kPi),
          Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
      logs.push_back(lieBodyRelativeLog(p0, lieBodyFromCorners(ex)));
    }
    const Eigen::Vector3d w(uniform(rng, -0.5, 1), uniform(rng, -0.5, 1), uniform(rng, -0.5, 1));
    const Eigen::Matrix3d f = edgesOf(lieBodyBlendCorners(p0, logs, w)) * edgesOf(rest).inverse();
    const double scale = std::cbrt(f.determinant());
    EXPECT_LE((f.transpose() * f / (scale * scale) - Eigen::Matrix3d::Identity()).norm(),
              kBlendTol * edgesOf(rest).inverse().norm());
  }
}

TEST(LieBodyBlend, ReferenceRotationLogTracksTurnsBeyondPiAndTwoPi) {
  const TetCorners rest = canonicalTetCorners();
  const LieBody p0 = lieBodyFromCorners(rest);
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -0.5).normalized();
  for (double angle : {1.5 * kPi, 2.0 * kPi, 2.5 * kPi, 3.7 * kPi}) {
    SCOPED_TRACE("angle " + std::to_string(angle));
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const LieBody pk = lieBodyFromCorners(rotatedTet(rest, r, Eigen::Vector3d(0.3, -1, 2)));
    EXPECT_LE((lieBodyWorldRotation(p0, pk) - r).norm(), kBlendTol);
    const std::vector<LieBodyTangent> logs = {lieBodyRelativeLog(p0, pk, angle * axis)};
    for (double w : {0.5, 1.0, 0.25}) {
      // The blended tet is the rest rotated by w * angle about the axis.
      const Eigen::Matrix3d want = Eigen::AngleAxisd(w * angle, axis).toRotationMatrix();
      const Eigen::VectorXd weights = Eigen::VectorXd::Constant(1, w);
      const LieBody blended = lieBodyBlend(p0, logs, weights);
      EXPECT_LE((lieBodyWorldRotation(p0, blended) - want).norm(), kBlendTol);
      EXPECT_LE((lieBodyEdges(blended) - want * edgesOf(rest)).norm(), kBlendTol);
    }
  }
  // Without a reference the principal log takes the short way round.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.5 * kPi, axis).toRotationMatrix();
  const std::vector<LieBodyTangent> principal = {
      lieBodyRelativeLog(p0, lieBodyFromCorners(rotatedTet(rest, r, Eigen::Vector3d::Zero())))};
  const LieBody half = lieBodyBlend(p0, principal, Eigen::VectorXd::Constant(1, 0.5));
  EXPECT_LE(
      (lieBodyWorldRotation(p0, half) - Eigen::AngleAxisd(-0.25 * kPi, axis).toRotationMatrix())
          .norm(),
      kBlendTol);
}

TEST(LieBodyBlend, FullTurnReferenceKeepsEdgesWhenTranslationIsAcrossTheAxis) {
  // A translated copy with a 2 pi reference: V(omega) is singular, the part of
  // the translation across the axis is dropped, edges and rotation are kept.
  const TetCorners rest = canonicalTetCorners();
  const LieBody p0 = lieBodyFromCorners(rest);
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  const TetCorners moved = rotatedTet(rest, Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 2));
  const std::vector<LieBodyTangent> logs = {
      lieBodyRelativeLog(p0, lieBodyFromCorners(moved), 2.0 * kPi * axis)};
  EXPECT_NEAR(logs[0].rigid.head<3>().norm(), 2.0 * kPi, kBlendTol);
  const LieBody full = lieBodyBlend(p0, logs, Eigen::VectorXd::Ones(1));
  EXPECT_LE((lieBodyEdges(full) - edgesOf(moved)).norm(), kBlendTol);
  const LieBody half = lieBodyBlend(p0, logs, Eigen::VectorXd::Constant(1, 0.5));
  EXPECT_LE(
      (lieBodyWorldRotation(p0, half) - Eigen::AngleAxisd(kPi, axis).toRotationMatrix()).norm(),
      kBlendTol);
}

}  // namespace
}  // namespace tetblend
