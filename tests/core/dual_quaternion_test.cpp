#include "tetblend/core/dual_quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "matrix_function_oracle.h"
#include "rigid_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/se3.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using core_test::randomRigid;
using core_test::rigidFromAngleAxis;
using core_test::testSeed;
using core_test::uniform;

// Round trips and compositions of unit-scale motions: a few ulps.
constexpr double kRoundTripTol = 1e-14;
// Against Eigen's Pade/Schur-Parlett exp/log of the 4x4 matrix.
constexpr double kOracleTol = 1e-12;
// Matrix -> dual quaternion -> product(s) -> matrix or point: 3-5 steps, each within kRoundTripTol.
constexpr double kChainTol = 10 * kRoundTripTol;
// Norms of non-unit q = u c (c0 in [0.1, 3], |c1| <= 2): terms up to |c1| / c0 = 20 cancel.
constexpr double kNonUnitTol = 10 * kRoundTripTol;
// log at half-angle pi - 1e-3 divides vec(q0) by sin(phi) = 1e-3: 1e3 times kOracleTol.
constexpr double kLogNearPiTol = 1e3 * kOracleTol;
// Eigen's 4x4 log (oracle) is conditioned like theta / sin(theta): 314 at the pi - 1e-2 cut-off.
constexpr double kLogOracleTol = 10 * kOracleTol;
// q^(1/2) q^(1/2) against q: two exp(t log q), each within kOracleTol, then a product.
constexpr double kPowerRoundTripTol = 10 * kOracleTol;

// Rotation angles (radians) of the hard cases; the DQ series switch acts on the
// half-angle, so 2 * threshold is tested on both sides.
std::vector<double> hardAngles() {
  return {0.0,
          1e-12,
          2 * kDualQuaternionSeriesThreshold * (1 - 1e-12),
          2 * kDualQuaternionSeriesThreshold * (1 + 1e-12),
          1.0,
          kPi - 1e-9,
          kPi,
          20.0};
}

TEST(DualQuaternion, MatrixRoundTripOnHardAngles) {
  const Eigen::Vector3d axis(0.3, -1, 2);
  for (double angle : hardAngles()) {
    SCOPED_TRACE(angle);
    const Eigen::Matrix4d h = rigidFromAngleAxis(angle, axis, Eigen::Vector3d(1, -2, 0.5));
    const DualQuaternion q = DualQuaternion::fromRigid(h);
    EXPECT_TRUE(q.isUnit(kRoundTripTol));
    EXPECT_GE(q.real().w(), 0.0);
    EXPECT_LE((q.toMatrix() - h).norm(), kRoundTripTol * h.norm());
    // Kavan eq. 1: q_eps = (T/2) q0.
    const Eigen::Quaterniond t(0, 0.5, -1, 0.25);
    EXPECT_LE(((t * q.real()).coeffs() - q.dual().coeffs()).norm(), kRoundTripTol);
  }
}

TEST(DualQuaternion, FromRigidRejectsNonRigid) {
  Eigen::Matrix4d scaled = Eigen::Matrix4d::Identity();
  scaled(1, 1) = 1.01;
  EXPECT_THROW(DualQuaternion::fromRigid(scaled), DomainError);
  Eigen::Matrix4d reflection = Eigen::Matrix4d::Identity();
  reflection(0, 0) = -1;
  EXPECT_THROW(DualQuaternion::fromRigid(reflection), DomainError);
}

TEST(DualQuaternion, ProductConjugatesAndPointTransform) {
  std::mt19937 rng(testSeed("DualQuaternion.ProductConjugatesAndPointTransform"));
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix4d a = randomRigid(rng, kPi, 3);
    const Eigen::Matrix4d b = randomRigid(rng, kPi, 3);
    const DualQuaternion qa = DualQuaternion::fromRigid(a);
    const DualQuaternion qb = DualQuaternion::fromRigid(b);
    ASSERT_LE(((qa * qb).toMatrix() - a * b).norm(), kChainTol * (a * b).norm());
    // The quaternion conjugate inverts a unit dual quaternion (Kavan §3).
    ASSERT_LE((qa * qa.conjugate()).distanceUpToSign(DualQuaternion::Identity()), kRoundTripTol);
    ASSERT_LE((qa.conjugate().toMatrix() - a.inverse()).norm(), kChainTol * a.norm());
    // Kavan §3: q (1 + eps v) q^{*-bar} = 1 + eps (R v + T), both conjugates.
    const Eigen::Vector3d x(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
    const DualQuaternion vq(Eigen::Quaterniond::Identity(),
                            Eigen::Quaterniond(0, x.x(), x.y(), x.z()));
    const DualQuaternion moved = qa * vq * qa.conjugate().dualConjugate();
    const Eigen::Vector3d expected = (a * x.homogeneous()).head<3>();
    ASSERT_LE((moved.dual().vec() - expected).norm(), kChainTol * (1 + expected.norm()));
    ASSERT_NEAR(moved.real().w(), 1.0, kRoundTripTol);
    ASSERT_LE((qa.transformPoint(x) - expected).norm(), kChainTol * (1 + expected.norm()));
  }
}

TEST(DualQuaternion, NormIsMultiplicativeAndNormalisationRecoversTheUnitFactor) {
  std::mt19937 rng(testSeed("DualQuaternion.NormIsMultiplicative"));
  for (int i = 0; i < 50; ++i) {
    const DualQuaternion u = DualQuaternion::fromRigid(randomRigid(rng, kPi, 2));
    const DualQuaternion v = DualQuaternion::fromRigid(randomRigid(rng, kPi, 2));
    // Scale u by the dual number c = c0 + eps c1: q = u c is not unit, and
    // |q| = c (Kavan §3), q / |q| = u.
    const double c0 = uniform(rng, 0.1, 3), c1 = uniform(rng, -2, 2);
    Eigen::Quaterniond dual;
    dual.coeffs() = c0 * u.dual().coeffs() + c1 * u.real().coeffs();
    const DualQuaternion q(Eigen::Quaterniond(c0 * u.real().coeffs()), dual);
    ASSERT_NEAR(q.norm().real, c0, kRoundTripTol * c0);
    ASSERT_NEAR(q.norm().dual, c1, kNonUnitTol * (1 + std::abs(c1)));
    ASSERT_LE(q.normalized().distanceUpToSign(u), kNonUnitTol);
    // |p q| = |p| |q| for dual-number norms (Kavan §3).
    const DualQuaternion p = v * 2.5;
    const DualNumber np = p.norm(), nq = q.norm(), npq = (p * q).norm();
    ASSERT_NEAR(npq.real, np.real * nq.real, kNonUnitTol * npq.real);
    ASSERT_NEAR(npq.dual, np.real * nq.dual + np.dual * nq.real,
                kNonUnitTol * (1 + std::abs(npq.dual)));
  }
  const DualQuaternion purelyDual(Eigen::Quaterniond(0, 0, 0, 0), Eigen::Quaterniond(1, 0, 0, 0));
  EXPECT_THROW(purelyDual.normalized(), DomainError);
}

TEST(DualQuaternion, LogIsHalfTheTwistOfTheMatrixLogarithm) {
  // Oracle: Eigen's principal log of the 4x4 matrix; the dual-quaternion log
  // is x = (omega / 2) + eps (v / 2) for the twist (omega, v).
  const Eigen::Vector3d axis(-1, 0.5, 0.25);
  for (double angle : hardAngles()) {
    if (angle > kPi - 1e-3) continue;  // Eigen's log is ill-conditioned there.
    SCOPED_TRACE(angle);
    const Eigen::Matrix4d h = rigidFromAngleAxis(angle, axis, Eigen::Vector3d(2, 1, -1));
    const Vector6d twist = se3Vee(logm(h));
    const DualQuaternion x = DualQuaternion::fromRigid(h).log();
    EXPECT_EQ(x.real().w(), 0.0);
    EXPECT_EQ(x.dual().w(), 0.0);
    EXPECT_LE((2 * x.real().vec() - twist.head<3>()).norm(), kOracleTol);
    EXPECT_LE((2 * x.dual().vec() - twist.tail<3>()).norm(),
              kOracleTol * twist.norm() + kOracleTol);
  }
}

TEST(DualQuaternion, ExpMatchesMatrixExponentialOnBothSidesOfTheSeries) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, 0.9, -0.4).normalized();
  const Eigen::Vector3d b(0.3, -1.2, 0.8);
  for (double angle : hardAngles()) {
    SCOPED_TRACE(angle);
    const double phi = angle / 2;  // half-angle
    const DualQuaternion x = DualQuaternion::pure(phi * axis, b);
    Vector6d twist;
    twist << 2 * phi * axis, 2 * b;
    const Eigen::Matrix4d oracle = expm(se3Hat(twist));
    const DualQuaternion e = DualQuaternion::exp(x);
    EXPECT_TRUE(e.isUnit(kRoundTripTol));
    EXPECT_LE((e.toMatrix() - oracle).norm(), kOracleTol * oracle.norm());
    // exp(log) returns the dual quaternion itself below half-angle pi.
    if (phi < kPi - 1e-3) {
      EXPECT_LE(e.log().distanceUpToSign(x), kOracleTol * (1 + angle));
    }
  }
}

TEST(DualQuaternion, SeriesAndClosedFormMeetAtTheSwitch) {
  // 2e-14 rad apart across the half-angle threshold, exp and log may differ
  // only by that step times their unit-scale derivative, plus round-off. A
  // missing phi^4 term of sinc or phi/sin(phi) would show as ~1e-11 through
  // the dual part (it multiplies |b| ~ 1).
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 2) / 3.0;
  const Eigen::Vector3d b(0.5, -0.25, 1.0);
  const double below = kDualQuaternionSeriesThreshold * (1 - 1e-12);
  const double above = kDualQuaternionSeriesThreshold * (1 + 1e-12);
  constexpr double kContinuityTol = 1e-13;
  const DualQuaternion eBelow = DualQuaternion::exp(DualQuaternion::pure(below * axis, b));
  const DualQuaternion eAbove = DualQuaternion::exp(DualQuaternion::pure(above * axis, b));
  EXPECT_LE(eBelow.distanceUpToSign(eAbove), kContinuityTol);
  EXPECT_LE(eBelow.log().distanceUpToSign(eAbove.log()), kContinuityTol);
}

TEST(DualQuaternion, LogAtTheAntipodalSingularity) {
  // Real part -1 (half-angle pi) with a translation: no logarithm.
  const DualQuaternion minusOne(Eigen::Quaterniond(-1, 0, 0, 0), Eigen::Quaterniond(0, 0.5, 0, 0));
  EXPECT_THROW(minusOne.log(), DomainError);
  // The motion itself (canonical sign) is a pure translation by (-1, 0, 0).
  const DualQuaternion x = minusOne.canonicalSign().log();
  EXPECT_LE(x.real().vec().norm(), 0.0);
  EXPECT_LE((2 * x.dual().vec() - Eigen::Vector3d(-1, 0, 0)).norm(), kRoundTripTol);
  // Both sides of the 1e-12 guard on |vec(q0)| (w < 0): refused just inside,
  // computed just outside (its rotation part round-trips).
  const Eigen::Quaterniond inside(-1.0, 1e-13, 0, 0), outside(-1.0, 1e-11, 0, 0);
  EXPECT_THROW(DualQuaternion(inside, Eigen::Quaterniond(0, 0, 0, 0)).log(), DomainError);
  const DualQuaternion justOutside(outside.normalized(), Eigen::Quaterniond(0, 0, 0, 0));
  EXPECT_LE(DualQuaternion::exp(justOutside.log()).distanceUpToSign(justOutside), kRoundTripTol);
  // Just inside half-angle pi (w < 0) the log exists and round-trips.
  const DualQuaternion near = DualQuaternion::exp(
      DualQuaternion::pure((kPi - 1e-3) * Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 2, 3)));
  ASSERT_LT(near.real().w(), 0.0);
  EXPECT_LE(DualQuaternion::exp(near.log()).distanceUpToSign(near), kLogNearPiTol);
}

TEST(DualQuaternion, PowerIsTheMatrixPower) {
  std::mt19937 rng(testSeed("DualQuaternion.PowerIsTheMatrixPower"));
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix4d h = randomRigid(rng, kPi - 1e-2, 3);
    const DualQuaternion q = DualQuaternion::fromRigid(h);
    const Eigen::Matrix4d logH = logm(h);
    for (double t : {-0.7, 0.3, 0.5, 2.0}) {
      const Eigen::Matrix4d oracle = expm(t * logH);
      ASSERT_LE((q.power(t).toMatrix() - oracle).norm(), kLogOracleTol * oracle.norm())
          << "sample " << i << " t " << t;
    }
    ASSERT_LE((q.power(0.5) * q.power(0.5)).distanceUpToSign(q), kPowerRoundTripTol);
  }
}

}  // namespace
}  // namespace tetblend
