#include "tetblend/core/baselines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "rigid_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

using core_test::randomRigid;
using core_test::randomUnitVector;
using core_test::rigidFromAngleAxis;
using core_test::spdWithEigenvalues;
using core_test::testSeed;
using core_test::uniform;

// Polar decompositions, quaternion conversions and Eigen's matrix exp/log of
// unit-scale maps: round-off of a few hundred ulps at most.
constexpr double kTol = 1e-11;
// A two-term weighted sum of 4x4 matrices against the same sum written out:
// two products and one addition per entry, each rounded by at most half an
// ulp; 1e-15 (~4.5 eps) per unit of the result's norm, times 4 at the check.
constexpr double kWeightedSumUlps = 1e-15;
// +90 and -90 degree turns averaged: cos(pi/2) rounds to 6.1e-17, so the
// linear part is diag(6.1e-17, 6.1e-17, 1) and its determinant ~4e-33.
constexpr double kSingularDeterminant = 1e-15;
// Eigen's matrix log of a turn within 1e-6 of pi: the angle is conditioned
// like 1/(pi - angle), ~eps * 1e6 = 2e-10 here.
constexpr double kNearHalfTurnAngle = 1e-9;

using Blend =
    std::function<Eigen::Matrix4d(const std::vector<double>&, const std::vector<Eigen::Matrix4d>&)>;
struct Method {
  std::string name;
  Blend blend;
};

std::vector<Method> methods() {
  return {{"linear", linearMatrixBlend},
          {"alexa", alexaBlend},
          {"polarSlerp", polarSlerpBlend},
          {"logRotation", logRotationBlend}};
}

Eigen::Matrix4d zRotation(double angle) {
  return rigidFromAngleAxis(angle, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero());
}

// Random R S (+ translation) with rotation angle below pi/2: then R S is
// similar to S^1/2 R S^1/2, whose symmetric part is positive definite, so no
// eigenvalue lies on the negative real axis and Alexa's blend is defined.
Eigen::Matrix4d randomAffine(std::mt19937& rng) {
  Eigen::Matrix4d a = randomRigid(rng, 1.5, 2);
  a.topLeftCorner<3, 3>() *= spdWithEigenvalues(
      rng, Eigen::Vector3d(uniform(rng, 0.3, 3), uniform(rng, 0.3, 3), uniform(rng, 0.3, 3)));
  return a;
}

// Signed angle of a rotation about z (the rotation block of a 4x4 map).
double zAngle(const Eigen::Matrix4d& m) { return std::atan2(m(1, 0), m(0, 0)); }

TEST(Baselines, UnitWeightsReturnTheInputForEveryMethod) {
  std::mt19937 rng(testSeed("Baselines.UnitWeightsReturnTheInputForEveryMethod"));
  for (const Method& m : methods()) {
    for (int n : {1, 2, 3}) {
      std::vector<Eigen::Matrix4d> maps;
      for (int i = 0; i < n; ++i) maps.push_back(randomAffine(rng));
      for (int k = 0; k < n; ++k) {
        std::vector<double> w(n, 0.0);
        w[k] = 1.0;
        EXPECT_LE((m.blend(w, maps) - maps[k]).norm(), kTol * maps[k].norm())
            << m.name << " n " << n << " k " << k;
      }
    }
  }
}

TEST(Baselines, RejectBadInputNamingTheMap) {
  Eigen::Matrix4d flipped = Eigen::Matrix4d::Identity();
  flipped(0, 0) = -1;
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
  projective(3, 1) = 0.25;
  const Eigen::Matrix4d id = Eigen::Matrix4d::Identity();
  for (const Method& m : methods()) {
    SCOPED_TRACE(m.name);
    EXPECT_THROW(m.blend({0.5, 0.5}, {id, flipped}), DomainError);
    try {
      m.blend({0.5, 0.5}, {id, projective});
      ADD_FAILURE() << "no error for a projective last row";
    } catch (const DomainError& e) {
      EXPECT_NE(std::string(e.what()).find("map 1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(m.blend({1.0}, {id, id}), InputError);
    EXPECT_THROW(m.blend({}, {}), InputError);
  }
}

TEST(Baselines, LinearBlendIsTheWeightedSumAndCollapsesOpposedTurns) {
  std::mt19937 rng(testSeed("Baselines.LinearBlend"));
  const std::vector<Eigen::Matrix4d> maps = {randomAffine(rng), randomAffine(rng)};
  const Eigen::Matrix4d b = linearMatrixBlend({0.25, 0.75}, maps);
  EXPECT_LE((b - (0.25 * maps[0] + 0.75 * maps[1])).norm(), kWeightedSumUlps * b.norm() * 4);
  // Documented failure mode: +90 and -90 degrees about z average to a
  // singular map.
  const Eigen::Matrix4d c =
      linearMatrixBlend({0.5, 0.5}, {zRotation(kPi / 2), zRotation(-kPi / 2)});
  const double det = c.topLeftCorner<3, 3>().determinant();
  EXPECT_NEAR(det, 0.0, kSingularDeterminant);
}

TEST(Baselines, AlexaIsTheGeometricMeanOfCommutingStretches) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity(), b = a;
  a.diagonal().head<3>() << 2.0, 0.5, 3.0;
  b.diagonal().head<3>() << 8.0, 2.0, 0.1;
  const Eigen::Matrix4d m = alexaBlend({0.25, 0.75}, {a, b});
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(m(k, k), std::pow(a(k, k), 0.25) * std::pow(b(k, k), 0.75), kTol);
  }
  EXPECT_LE((m - Eigen::Matrix4d(m.diagonal().asDiagonal())).norm(), kTol);
}

TEST(Baselines, AlexaBlendsCoaxialAnglesLinearly) {
  for (double a0 : {-3.0, -1.0, 0.0, 2.5}) {
    for (double a1 : {-2.9, 0.5, 3.1}) {
      const Eigen::Matrix4d m = alexaBlend({0.3, 0.7}, {zRotation(a0), zRotation(a1)});
      EXPECT_NEAR(zAngle(m), std::remainder(0.3 * a0 + 0.7 * a1, 2 * kPi), kTol) << a0 << " " << a1;
    }
  }
}

TEST(Baselines, AlexaIsNotConstantSpeed) {
  // Kavan App. B: R0 = rotation by 1 rad about x, R1 = by sqrt(2) about
  // (1,1,0)/sqrt(2); the angular speed of the blend is
  // sqrt((t^4 + t^2 - 2 cos(sqrt(1+t^2)) + 2) / (1+t^2)^2). Finite differences.
  const Eigen::Matrix4d r0 = rigidFromAngleAxis(1.0, Eigen::Vector3d::UnitX(), {0, 0, 0});
  const Eigen::Matrix4d r1 =
      rigidFromAngleAxis(std::sqrt(2.0), Eigen::Vector3d(1, 1, 0), {0, 0, 0});
  constexpr double h = 1e-5;
  constexpr double kFiniteDifferenceTol = 1e-8;
  for (double t : {0.1, 0.5, 0.9}) {
    const Eigen::Matrix3d rt = alexaBlend({1 - t, t}, {r0, r1}).topLeftCorner<3, 3>();
    const Eigen::Matrix3d d =
        (alexaBlend({1 - t - h, t + h}, {r0, r1}) - alexaBlend({1 - t + h, t - h}, {r0, r1}))
            .topLeftCorner<3, 3>() /
        (2 * h);
    const double speed = vee(rt.transpose() * d).norm();
    const double s = std::sqrt(1 + t * t);
    const double expected =
        std::sqrt((t * t * t * t + t * t - 2 * std::cos(s) + 2) / ((1 + t * t) * (1 + t * t)));
    EXPECT_NEAR(speed, expected, kFiniteDifferenceTol) << "t " << t;
  }
}

TEST(Baselines, AlexaReportsMapsWithoutRealLogarithm) {
  const Eigen::Matrix4d id = Eigen::Matrix4d::Identity();
  // Exactly a half-turn, and inside the sqrt(eps) band: no real principal log.
  for (double angle : {kPi, kPi - 1e-9}) {
    try {
      alexaBlend({0.5, 0.5}, {id, zRotation(angle)});
      ADD_FAILURE() << "no error at angle " << angle;
    } catch (const DomainError& e) {
      EXPECT_NE(std::string(e.what()).find("no real principal matrix logarithm"),
                std::string::npos);
      EXPECT_NE(std::string(e.what()).find("map 1"), std::string::npos);
    }
  }
  // det > 0 but two negative eigenvalues.
  Eigen::Matrix4d negative = id;
  negative.diagonal().head<3>() << -1.0, -2.0, 1.0;
  EXPECT_THROW(alexaBlend({0.5, 0.5}, {id, negative}), DomainError);
  // A rotation by 3 rad has a logarithm, but times the stretch
  // diag(4, 1/4, 1) its linear part has eigenvalues -3.95 and -0.25.
  Eigen::Matrix4d stretched = zRotation(3.0);
  EXPECT_NO_THROW(alexaBlend({0.5, 0.5}, {id, stretched}));
  stretched.topLeftCorner<3, 3>() *= Eigen::Vector3d(4.0, 0.25, 1.0).asDiagonal();
  EXPECT_THROW(alexaBlend({0.5, 0.5}, {id, stretched}), DomainError);
  // Outside the band the log exists and the coaxial blend is exact.
  for (double angle : {kPi - 1e-6, kPi - 1e-3}) {
    const Eigen::Matrix4d m = alexaBlend({0.5, 0.5}, {id, zRotation(angle)});
    EXPECT_NEAR(zAngle(m), angle / 2, kNearHalfTurnAngle) << angle;
  }
}

TEST(Baselines, PolarSlerpTakesTheShortArcAndBlendsStretchLinearly) {
  std::mt19937 rng(testSeed("Baselines.PolarSlerp"));
  const Eigen::Matrix3d s0 = spdWithEigenvalues(rng, {0.5, 1.0, 2.0});
  const Eigen::Matrix3d s1 = spdWithEigenvalues(rng, {3.0, 0.7, 1.2});
  const Eigen::Vector3d axis = randomUnitVector(rng);
  // 170 and -170 degrees: the short arc passes through 180.
  const double a0 = 170 * kPi / 180, a1 = -170 * kPi / 180;
  Eigen::Matrix4d m0 = rigidFromAngleAxis(a0, axis, {1, 2, 3});
  Eigen::Matrix4d m1 = rigidFromAngleAxis(a1, axis, {-1, 0, 1});
  m0.topLeftCorner<3, 3>() *= s0;
  m1.topLeftCorner<3, 3>() *= s1;
  for (double t : {0.25, 0.5, 0.75}) {
    const Eigen::Matrix4d b = polarSlerpBlend({1 - t, t}, {m0, m1});
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(a0 + t * (2 * kPi - (a0 - a1)), axis).toRotationMatrix() *
        ((1 - t) * s0 + t * s1);
    EXPECT_LE((b.topLeftCorner<3, 3>() - expected).norm(), kTol) << t;
    EXPECT_LE((b.topRightCorner<3, 1>() -
               ((1 - t) * Eigen::Vector3d(1, 2, 3) + t * Eigen::Vector3d(-1, 0, 1)))
                  .norm(),
              kTol);
  }
}

TEST(Baselines, PolarSlerpForManyInputsIsAlignedQuaternionLerp) {
  // Coaxial rotations: the normalised quaternion sum has the half-angle
  // atan2(sum w sin(a/2), sum w cos(a/2)) once each q is in the pivot's
  // hemisphere; -175 degrees enters as the antipode (+185 degrees).
  const std::vector<double> angles = {170 * kPi / 180, -175 * kPi / 180, 160 * kPi / 180};
  const std::vector<double> w = {0.5, 0.3, 0.2};
  std::vector<Eigen::Matrix4d> maps;
  for (double a : angles) maps.push_back(zRotation(a));
  double s = 0, c = 0;
  for (int i = 0; i < 3; ++i) {
    const double a = i == 1 ? angles[i] + 2 * kPi : angles[i];
    s += w[i] * std::sin(a / 2);
    c += w[i] * std::cos(a / 2);
  }
  const double expected = std::remainder(2 * std::atan2(s, c), 2 * kPi);
  EXPECT_NEAR(zAngle(polarSlerpBlend(w, maps)), expected, kTol);
  EXPECT_GT(std::abs(expected), 170 * kPi / 180);  // near the half-turn, not near 0
  EXPECT_THROW(polarSlerpBlend({1.0, -1.0, 0.0}, {maps[0], maps[0], maps[0]}), DomainError);
}

TEST(Baselines, LogRotationBlendsCoaxialAnglesLinearlyAndFailsAcrossTheHalfTurn) {
  for (double a0 : {-3.0, 0.2, 2.0}) {
    for (double a1 : {-1.0, 3.1}) {
      const Eigen::Matrix4d m = logRotationBlend({0.6, 0.4}, {zRotation(a0), zRotation(a1)});
      EXPECT_NEAR(zAngle(m), std::remainder(0.6 * a0 + 0.4 * a1, 2 * kPi), kTol);
    }
  }
  // Documented failure mode: 170 and -170 degrees blend through 0.
  const Eigen::Matrix4d m =
      logRotationBlend({0.5, 0.5}, {zRotation(170 * kPi / 180), zRotation(-170 * kPi / 180)});
  EXPECT_NEAR(zAngle(m), 0.0, kTol);
}

}  // namespace
}  // namespace tetblend
