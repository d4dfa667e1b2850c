#include "tetblend/core/so3.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "core_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using core_test::randomUnitVector;
using core_test::testSeed;
using core_test::uniform;

// Unit-scale round trips: a few ulps of accumulated round-off, times the angle
// for the oracle comparisons (scaling and squaring loses ~eps per squaring).
constexpr double kRoundTripTol = 2e-15;
constexpr double kOracleTolPerRadian = 2e-15;
// Eigen's log (oracle) is conditioned like theta / sin(theta), 21 at 3 rad, where exp's is <= 1.
constexpr double kLogOracleTolPerRadian = 10 * kOracleTolPerRadian;
// Closest log of a 3-5 pi turn: sin/cos and the 2 pi k shift round at ulps of up to 15.7 rad.
constexpr double kLongTwistTolPerRadian = 20 * kRoundTripTol;
// The closest log of a turn by 4 pi - 1e-3: sin/cos of a 12.6 rad angle
// (ulp 1.8e-15) and the 2 pi k shift back, a few tens of ulps of 12.6.
constexpr double kFourPiTwistTol = 1e-13;
// Distances from references up to 15 rad to logs up to ~20 rad long: each
// log off by ~kOracleTolPerRadian per radian, the brute-force oracle's
// (theta + 2 pi k) a rounded to ulps of ~20: ~1e-13.
constexpr double kClosestDistanceTol = 1e-12;
// exp of the closest log against exp of w: entries of rotations (<= 1) from
// sin/cos of angles up to ~20 rad (ulp 3.6e-15), a few ulps each.
constexpr double kSameRotationTol = 1e-13;

// Hard angles: identity, tiny, both sides of the series switch, both sides of
// the axis-from-symmetric switch (pi/2), near and exactly pi, large.
std::vector<double> hardAngles() {
  const double s = so3_detail::kSmallAngle;
  return {0.0, 1e-300,         1e-12,          1e-8, 0.99 * s,   1.01 * s, 1e-3,
          1.0, kPi / 2 - 1e-7, kPi / 2 + 1e-7, 3.0,  kPi - 1e-9, kPi,      20.0};
}

std::vector<Eigen::Vector3d> hardAxes() {
  return {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
          Eigen::Vector3d(1, 2, 3).normalized(), Eigen::Vector3d(-1, 1e-9, 0.5).normalized()};
}

TEST(So3, HatVeeAndCrossProduct) {
  const Eigen::Vector3d w(0.3, -1.7, 2.5), v(-4.0, 0.25, 1.0);
  EXPECT_LE((hat(w) * v - w.cross(v)).norm(), kRoundTripTol * w.norm() * v.norm());
  EXPECT_EQ(vee(hat(w)), w);
  EXPECT_EQ(hat(w).transpose(), -hat(w));
}

TEST(So3, ExpMatchesOracleOnHardAngles) {
  for (const Eigen::Vector3d& axis : hardAxes()) {
    for (double angle : hardAngles()) {
      SCOPED_TRACE(testing::Message() << "angle " << angle << " axis " << axis.transpose());
      const Eigen::Vector3d w = angle * axis;
      const Eigen::Matrix3d r = so3Exp(w);
      const Eigen::Matrix3d oracle = expm(hat(w));
      EXPECT_LE((r - oracle).norm(), kOracleTolPerRadian * (1.0 + angle));
      EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), kRoundTripTol);
      EXPECT_NEAR(r.determinant(), 1.0, kRoundTripTol);
    }
  }
}

TEST(So3, LogInvertsExpBelowPi) {
  for (const Eigen::Vector3d& axis : hardAxes()) {
    for (double angle : hardAngles()) {
      if (angle >= kPi) continue;
      SCOPED_TRACE(testing::Message() << "angle " << angle << " axis " << axis.transpose());
      const Eigen::Vector3d w = angle * axis;
      // Exact relation on the principal branch: errors are absolute, ~eps.
      EXPECT_LE((so3Log(so3Exp(w)) - w).norm(), kRoundTripTol * (1.0 + angle));
    }
  }
}

TEST(So3, LogMatchesOracleAwayFromPi) {
  std::mt19937 rng(testSeed("So3.LogMatchesOracleAwayFromPi"));
  for (int i = 0; i < 300; ++i) {
    // Eigen's matrix log is the principal log; it is ill-conditioned at pi.
    const Eigen::Vector3d w = uniform(rng, 0.0, 3.0) * randomUnitVector(rng);
    const Eigen::Matrix3d r = so3Exp(w);
    const Eigen::Matrix3d oracle = logm(r);
    EXPECT_LE((hat(so3Log(r)) - oracle).norm(), kLogOracleTolPerRadian * (1.0 + w.norm()));
  }
}

TEST(So3, LogExactlyAtPi) {
  // Exact rotations by pi: 2 a a^T - I (Eberly's special case).
  for (const Eigen::Vector3d& axis : hardAxes()) {
    const Eigen::Matrix3d r = 2.0 * axis * axis.transpose() - Eigen::Matrix3d::Identity();
    const Eigen::Vector3d w = so3Log(r);
    SCOPED_TRACE(testing::Message() << "axis " << axis.transpose());
    EXPECT_NEAR(w.norm(), kPi, kRoundTripTol);
    EXPECT_NEAR(std::abs(w.normalized().dot(axis)), 1.0, kRoundTripTol);
    EXPECT_LE((so3Exp(w) - r).norm(), kRoundTripTol * kPi);
  }
  EXPECT_NEAR(so3Log(Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix()).x(), kPi, 0.0);
}

TEST(So3, RandomRoundTripsAndOracle) {
  std::mt19937 rng(testSeed("So3.RandomRoundTripsAndOracle"));
  for (int i = 0; i < 1000; ++i) {
    const double angle = uniform(rng, 0.0, kPi);
    const Eigen::Vector3d w = angle * randomUnitVector(rng);
    const Eigen::Matrix3d r = so3Exp(w);
    ASSERT_LE((r - expm(hat(w))).norm(), kOracleTolPerRadian * (1.0 + angle)) << w.transpose();
    ASSERT_LE((so3Log(r) - w).norm(), kRoundTripTol * (1.0 + angle)) << w.transpose();
  }
}

TEST(So3, LogClosestRecoversFourPiTwist) {
  // Kaji–Ochiai Fig. 2: twists beyond 2 pi are representable given a nearby
  // reference (neighbouring element / previous frame).
  std::mt19937 rng(testSeed("So3.LogClosestRecoversFourPiTwist"));
  for (int i = 0; i < 200; ++i) {
    const double angle = uniform(rng, 3.0 * kPi, 5.0 * kPi);
    const Eigen::Vector3d w = angle * randomUnitVector(rng);
    const Eigen::Vector3d reference = w + 0.5 * randomUnitVector(rng);
    const Eigen::Vector3d closest = so3LogClosest(so3Exp(w), reference);
    // Angle-proportional: so3Exp of a 15 rad vector rounds sin/cos of 15.
    ASSERT_LE((closest - w).norm(), kLongTwistTolPerRadian * angle) << w.transpose();
  }
  const Eigen::Vector3d fourPi = (4.0 * kPi - 1e-3) * Eigen::Vector3d(0, 0, 1);
  EXPECT_NEAR(so3LogClosest(so3Exp(fourPi), fourPi).norm(), 4.0 * kPi - 1e-3, kFourPiTwistTol);
}

TEST(So3, LogClosestIsTheClosestLog) {
  // Oracle: brute force over the logarithms (theta + 2 pi k) a, k in [-4, 4].
  std::mt19937 rng(testSeed("So3.LogClosestIsTheClosestLog"));
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d w = uniform(rng, 0.01, kPi - 0.01) * randomUnitVector(rng);
    const Eigen::Vector3d reference = uniform(rng, 0.0, 15.0) * randomUnitVector(rng);
    const Eigen::Vector3d axis = w.normalized();
    double best = 1e300;
    for (int k = -4; k <= 4; ++k) {
      best = std::min(best, (reference - (w.norm() + 2 * kPi * k) * axis).norm());
    }
    const Eigen::Vector3d closest = so3LogClosest(so3Exp(w), reference);
    ASSERT_NEAR((reference - closest).norm(), best, kClosestDistanceTol);
    ASSERT_LE((so3Exp(closest) - so3Exp(w)).norm(), kSameRotationTol);
  }
}

TEST(So3, LogClosestOfIdentityLiesOnTheNearestSphere) {
  const Eigen::Vector3d reference(1.1 * 2 * kPi, 0, 0);
  EXPECT_LE((so3LogClosest(Eigen::Matrix3d::Identity(), reference) - Eigen::Vector3d(2 * kPi, 0, 0))
                .norm(),
            kRoundTripTol);
  EXPECT_EQ(so3LogClosest(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()),
            Eigen::Vector3d::Zero());
  EXPECT_EQ(so3LogClosest(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 1, 0)),
            Eigen::Vector3d::Zero());
}

void expectRotation(const Eigen::Matrix3d& r) {
  ASSERT_TRUE(r.allFinite()) << r;
  EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), kRoundTripTol);
  EXPECT_NEAR(r.determinant(), 1.0, kRoundTripTol);
}

TEST(So3, ExpOfHugeAngleIsTheRotationOfTheReducedAngle) {
  // Regression (issue 14): |omega|^2 overflowed for |omega| > ~1.3e154 and
  // so3Exp((1e155, 0, 0)) returned NaN. The rotation depends on the angle
  // modulo 2 pi only; std::cos/std::sin of the double angle are the oracle.
  for (const double angle : {1e155, -1e155, 3e200, 1e308}) {
    SCOPED_TRACE(testing::Message() << "angle " << angle);
    const Eigen::Matrix3d r = so3Exp(Eigen::Vector3d(angle, 0.0, 0.0));
    expectRotation(r);
    Eigen::Matrix3d oracle = Eigen::Matrix3d::Identity();
    oracle.bottomRightCorner<2, 2>() << std::cos(angle), -std::sin(angle), std::sin(angle),
        std::cos(angle);
    EXPECT_LE((r - oracle).norm(), kRoundTripTol);
  }
  // Norms beyond the double range: the axis stays fixed.
  const double big = std::numeric_limits<double>::max();
  for (const Eigen::Vector3d& w :
       {Eigen::Vector3d(1e155, 1e155, -1e155), Eigen::Vector3d(big, big, 0.0),
        Eigen::Vector3d(big, -big, big), Eigen::Vector3d(1e300, 1e-300, 0.0)}) {
    SCOPED_TRACE(testing::Message() << "omega " << w.transpose());
    const Eigen::Matrix3d r = so3Exp(w);
    expectRotation(r);
    const Eigen::Vector3d axis = (w / w.cwiseAbs().maxCoeff()).normalized();
    EXPECT_LE((r * axis - axis).norm(), kRoundTripTol);
  }
}

TEST(So3, HugeAngleFormulaMatchesRodriguesAtModerateAngles) {
  // The huge-angle branch (unit axis, half-angle sine and cosine) is the same
  // formula as the main branch; check it where both apply, below and above pi.
  for (const Eigen::Vector3d& axis : hardAxes()) {
    for (const double angle : {1e-3, 1.0, 3.0, kPi, 20.0, 1e5}) {
      const Eigen::Vector3d w = angle * axis;
      EXPECT_LE((so3_detail::so3ExpHugeAngle(w) - so3Exp(w)).norm(),
                kOracleTolPerRadian * (1.0 + angle))
          << "angle " << angle << " axis " << axis.transpose();
    }
  }
}

TEST(So3, LogCheckedRefusesNonRotations) {
  // Regression (issue 14): so3Log(0) and so3Log(1e-150 I) return (pi, 0, 0);
  // the checked variant refuses what is not a rotation.
  const Eigen::Matrix3d rotation = so3Exp(Eigen::Vector3d(0.3, -1.2, 2.0));
  Eigen::Matrix3d nan = rotation;
  nan(1, 2) = std::nan("");
  for (const Eigen::Matrix3d& m :
       {Eigen::Matrix3d(Eigen::Matrix3d::Zero()),
        Eigen::Matrix3d(1e-150 * Eigen::Matrix3d::Identity()),
        Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal()), Eigen::Matrix3d(1.01 * rotation),
        Eigen::Matrix3d(-rotation), nan}) {
    EXPECT_THROW(so3LogChecked(m), DomainError) << m;
  }
  EXPECT_EQ(so3LogChecked(rotation), so3Log(rotation));
  // A rotation written with 7 significant digits passes the default tolerance.
  const Eigen::Matrix3d rounded = (rotation * 1e7).array().round() / 1e7;
  EXPECT_NO_THROW(so3LogChecked(rounded));
  EXPECT_THROW(so3LogChecked(rounded, 1e-12), DomainError);
}

}  // namespace
}  // namespace tetblend
