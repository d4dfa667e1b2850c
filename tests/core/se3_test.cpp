#include "tetblend/core/se3.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
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

// Closed form vs Eigen's Pade/Schur-Parlett exp/log on unit-scale twists: a
// few hundred ulps of accumulated round-off in the oracle itself.
constexpr double kOracleTol = 1e-12;
// Eigen's 4x4 log (oracle) is conditioned like theta / sin(theta): 314 at the pi - 1e-2 cut-off.
constexpr double kLogOracleTol = 10 * kOracleTol;
// se3Geodesic at t = 1: H0 exp(log(H0^-1 H1)), five steps in a row (at t = 0 only H0 I).
constexpr double kGeodesicEndTol = 10 * kOracleTol;
// Near theta = pi the rotation log is conditioned like 1/sin(theta) in the
// axis (Eberly §3.2): round trips keep the matrix, but the twist itself is
// only reproduced to ~eps / (pi - theta) relative.
constexpr double kNearPiTol = 1e-6;
// Central finite difference with step h = 1e-5 on unit-scale curves: O(h^2)
// truncation plus eps/h round-off.
constexpr double kFiniteDifferenceTol = 1e-8;
// The principal log's rotation angle is at most pi up to the rounding of the
// angle (acos/atan2) near pi: ulp(pi) = 4.4e-16, two ulps allowed.
constexpr double kPrincipalAngleSlack = 1e-15;

Vector6d twist(const Eigen::Vector3d& omega, const Eigen::Vector3d& v) {
  Vector6d xi;
  xi << omega, v;
  return xi;
}

// Oracle: exp of the 4x4 Lie-algebra matrix by Eigen's MatrixFunctions.
Eigen::Matrix4d oracleExp(const Vector6d& xi) { return expm(se3Hat(xi)); }

// Oracle for V = integral_0^1 exp(s S) ds: the top-right block of
// exp([[S, I], [0, 0]]) (6 by 6), independent of Eberly's closed form.
Eigen::Matrix3d oracleV(const Eigen::Vector3d& omega) {
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  m.topLeftCorner<3, 3>() << 0, -omega.z(), omega.y(), omega.z(), 0, -omega.x(), -omega.y(),
      omega.x(), 0;
  m.topRightCorner<3, 3>() = Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, 6, 6> e = expm(m);
  return e.topRightCorner<3, 3>();
}

// The fixed hard angles (radians) of the brief and both sides of the series
// switch.
std::vector<double> hardAngles() {
  return {0.0,
          1e-12,
          1e-6,
          kSe3SeriesThreshold * (1.0 - 1e-12),
          kSe3SeriesThreshold * (1.0 + 1e-12),
          0.3,
          2.0,
          kPi - 1e-9,
          kPi,
          20.0};
}

TEST(Se3, HatVeeRoundTrip) {
  const Vector6d xi = twist(Eigen::Vector3d(0.1, -2, 3), Eigen::Vector3d(4, 5, -6));
  EXPECT_EQ(se3Vee(se3Hat(xi)), xi);
  EXPECT_EQ(se3Hat(xi).row(3), Eigen::RowVector4d::Zero());
}

TEST(Se3, ExpMatchesMatrixExponentialOnHardAngles) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d v(0.7, -0.3, 1.1);
  for (double theta : hardAngles()) {
    SCOPED_TRACE(theta);
    const Vector6d xi = twist(theta * axis, v);
    const Eigen::Matrix4d oracle = oracleExp(xi);
    EXPECT_LE((se3Exp(xi) - oracle).norm(), kOracleTol * oracle.norm());
  }
}

TEST(Se3, LeftJacobianMatchesIntegralOracleOnBothSidesOfSeries) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.4, -1).normalized();
  for (double theta : hardAngles()) {
    if (theta > 2 * kPi) continue;
    SCOPED_TRACE(theta);
    const Eigen::Matrix3d v = se3LeftJacobian(theta * axis);
    EXPECT_LE((v - oracleV(theta * axis)).norm(), kOracleTol);
    const Eigen::Matrix3d vInv = se3LeftJacobianInverse(theta * axis);
    EXPECT_LE((vInv * v - Eigen::Matrix3d::Identity()).norm(), kOracleTol);
  }
}

TEST(Se3, SeriesAndClosedFormAgreeAtTheSwitch) {
  // The series and the closed form must meet continuously at the threshold:
  // evaluated 2e-14 rad apart across it, V and V^{-1} may differ only by that
  // step times |dV/dtheta|_F <= 1, plus round-off. An error in a theta^2
  // series term would show as >= 1e-7, a missing theta^4 term as ~2e-13.
  const Eigen::Vector3d axis = Eigen::Vector3d(2, 1, -1).normalized();
  const double below = kSe3SeriesThreshold * (1.0 - 1e-12);
  const double above = kSe3SeriesThreshold * (1.0 + 1e-12);
  constexpr double kContinuityTol = 1e-13;
  EXPECT_LE((se3LeftJacobian(below * axis) - se3LeftJacobian(above * axis)).norm(), kContinuityTol);
  EXPECT_LE((se3LeftJacobianInverse(below * axis) - se3LeftJacobianInverse(above * axis)).norm(),
            kContinuityTol);
}

TEST(Se3, LeftJacobianInverseRefusesTwoPi) {
  EXPECT_THROW(se3LeftJacobianInverse(Eigen::Vector3d(0, 0, 2 * kPi)), DomainError);
  EXPECT_NO_THROW(se3LeftJacobianInverse(Eigen::Vector3d(0, 0, 2 * kPi - 1e-3)));
}

TEST(Se3, LogInvertsExpOnHardAngles) {
  const Eigen::Vector3d axis = Eigen::Vector3d(-0.2, 1, 0.9).normalized();
  const Eigen::Vector3d v(-1.5, 0.25, 2);
  for (double theta : hardAngles()) {
    SCOPED_TRACE(theta);
    const Vector6d xi = twist(theta * axis, v);
    const Eigen::Matrix4d h = oracleExp(xi);
    const Vector6d log = se3Log(h);
    // The matrix is always reproduced (any branch of the log).
    EXPECT_LE((oracleExp(log) - h).norm(), kOracleTol * h.norm());
    EXPECT_LE(log.head<3>().norm(), kPi + kPrincipalAngleSlack);
    if (theta < kPi - 1e-3) {
      EXPECT_LE((log - xi).norm(), kOracleTol * xi.norm());
      // Against Eigen's principal matrix logarithm of the 4x4 matrix.
      const Eigen::Matrix4d oracleLog = logm(h);
      EXPECT_LE((se3Hat(log) - oracleLog).norm(), kOracleTol * (1.0 + oracleLog.norm()));
    } else if (theta < kPi) {
      EXPECT_LE((log - xi).norm(), kNearPiTol * xi.norm());
    }
  }
}

TEST(Se3, TwentyRadiansWrapsToThePrincipalAngle) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Matrix4d h = oracleExp(twist(20.0 * axis, Eigen::Vector3d(1, 0, 0)));
  const Vector6d log = se3Log(h);
  // 20 - 6 pi = 1.150... rad about the same axis.
  EXPECT_NEAR(log.head<3>().norm(), 20.0 - 6.0 * kPi, kOracleTol);
  EXPECT_LE((log.head<3>().normalized() - axis).norm(), kOracleTol);
}

TEST(Se3, ExactlyPiReturnsOneOfTheTwoLogs) {
  const Eigen::Matrix4d h = oracleExp(twist(Eigen::Vector3d(0, kPi, 0), Eigen::Vector3d(1, 2, 3)));
  const Vector6d log = se3Log(h);
  EXPECT_NEAR(log.head<3>().norm(), kPi, kOracleTol);
  EXPECT_LE((se3Exp(log) - h).norm(), kOracleTol * h.norm());
}

TEST(Se3, LogRejectsNonRigidMatrices) {
  Eigen::Matrix4d scaled = Eigen::Matrix4d::Identity();
  scaled(0, 0) = 1.1;
  EXPECT_THROW(se3Log(scaled), DomainError);
  Eigen::Matrix4d reflection = Eigen::Matrix4d::Identity();
  reflection(2, 2) = -1;
  EXPECT_THROW(se3Log(reflection), DomainError);
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
  projective(3, 0) = 0.5;
  EXPECT_THROW(se3Log(projective), DomainError);
}

TEST(Se3, RandomExpLogAgainstMatrixFunctions) {
  std::mt19937 rng(testSeed("Se3.RandomExpLogAgainstMatrixFunctions"));
  for (int i = 0; i < 200; ++i) {
    const double theta = uniform(rng, 0.0, kPi - 1e-2);
    const Vector6d xi =
        twist(theta * randomUnitVector(rng),
              Eigen::Vector3d(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)));
    const Eigen::Matrix4d oracle = oracleExp(xi);
    ASSERT_LE((se3Exp(xi) - oracle).norm(), kOracleTol * oracle.norm()) << "sample " << i;
    ASSERT_LE((se3Hat(se3Log(oracle)) - logm(oracle)).norm(), kLogOracleTol * oracle.norm())
        << "sample " << i;
  }
}

double rotationAngle(const Eigen::Matrix4d& h) {
  return Eigen::AngleAxisd(Eigen::Matrix3d(h.topLeftCorner<3, 3>())).angle();
}

Eigen::Matrix4d randomRigid(std::mt19937& rng, double maxAngle) {
  return oracleExp(
      twist(uniform(rng, 0.0, maxAngle) * randomUnitVector(rng),
            Eigen::Vector3d(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2))));
}

TEST(Se3, GeodesicMatchesEberlyLeftFormAndEndpoints) {
  std::mt19937 rng(testSeed("Se3.GeodesicMatchesEberlyLeftFormAndEndpoints"));
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix4d h0 = randomRigid(rng, kPi);
    const Eigen::Matrix4d h1 = randomRigid(rng, kPi);
    // Keep the relative rotation away from pi, where Eigen's principal log is
    // ill-conditioned.
    if (rotationAngle(h1 * h0.inverse()) > kPi - 1e-2) continue;
    EXPECT_LE((se3Geodesic(0.0, h0, h1) - h0).norm(), kOracleTol * h0.norm());
    EXPECT_LE((se3Geodesic(1.0, h0, h1) - h1).norm(), kGeodesicEndTol * h1.norm());
    const Eigen::Matrix4d logRel = logm(h1 * h0.inverse());
    for (double t : {-0.5, 0.25, 0.5, 0.9, 1.5}) {
      // Eberly eq. 21: exp(t log(H1 H0^{-1})) H0 via MatrixFunctions.
      const Eigen::Matrix4d eberly = expm(t * logRel) * h0;
      ASSERT_LE((se3Geodesic(t, h0, h1) - eberly).norm(), kLogOracleTol * eberly.norm())
          << "sample " << i << " t " << t;
    }
  }
}

TEST(Se3, GeodesicHasConstantSpeed) {
  // Eberly eq. 30: |F'(t)|_F^2 = |S|^2 + |S T0 + U|^2, with (S, U) from
  // log(H1 H0^{-1}); F' by central differences.
  std::mt19937 rng(testSeed("Se3.GeodesicHasConstantSpeed"));
  constexpr double h = 1e-5;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Matrix4d h0 = randomRigid(rng, kPi);
    const Eigen::Matrix4d h1 = randomRigid(rng, kPi);
    const Vector6d xi = se3Log(h1 * rigidInverse(h0));
    const Eigen::Matrix3d s = se3Hat(xi).topLeftCorner<3, 3>();
    const double expected =
        std::sqrt(s.squaredNorm() + (s * h0.topRightCorner<3, 1>() + xi.tail<3>()).squaredNorm());
    for (double t : {0.1, 0.4, 0.7, 0.95}) {
      const Eigen::Matrix4d d = (se3Geodesic(t + h, h0, h1) - se3Geodesic(t - h, h0, h1)) / (2 * h);
      ASSERT_NEAR(d.norm(), expected, kFiniteDifferenceTol * (1 + expected))
          << "sample " << i << " t " << t;
    }
  }
}

}  // namespace
}  // namespace tetblend
