#include "tetblend/core/dual_quaternion_blend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
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
using core_test::rotationAngle;
using core_test::testSeed;
using core_test::uniform;

// Compositions, exp/log chains of unit-scale motions: round-off only.
constexpr double kTol = 1e-12;
// Blends and ScLERPs chained or composed, as absolute matrix distances with |T| up to ~10, not 1.
constexpr double kChainTol = 10 * kTol;
// DIB stops at |x| < 1e-13 (2.8e-13 as a matrix log), plus 4 of Eigen's 4x4 logs within kTol.
constexpr double kDibStationarityTol = 10 * kTol;
// dib(r q_i) vs r dib(q_i): two runs stopped apart at |x| < 1e-13, composed with r (|T| <= 5.2).
constexpr double kDibInvarianceTol = 100 * kTol;
// Kavan §4: DLB and ScLERP rotation angles differ by less than 8.15 degrees.
constexpr double kDlbAngleBound = 8.15 * kPi / 180.0;

DualQuaternion dq(const Eigen::Matrix4d& h) { return DualQuaternion::fromRigid(h); }

double matrixDistance(const DualQuaternion& a, const DualQuaternion& b) {
  return (a.toMatrix() - b.toMatrix()).norm();
}

std::vector<double> randomWeights(std::mt19937& rng, int n) {
  std::vector<double> w(n);
  double sum = 0;
  for (double& x : w) sum += (x = uniform(rng, 0.05, 1.0));
  for (double& x : w) x /= sum;
  return w;
}

TEST(ScLerp, MatchesMatrixGeodesicSlerpAndMatrixFunctions) {
  std::mt19937 rng(testSeed("ScLerp.MatchesMatrixGeodesicSlerpAndMatrixFunctions"));
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix4d h0 = randomRigid(rng, kPi, 3), h1 = randomRigid(rng, kPi, 3);
    if (rotationAngle(h0.inverse() * h1) > kPi - 1e-2) continue;  // oracle log ill-conditioned
    const DualQuaternion p = dq(h0), q = dq(h1);
    const Eigen::Matrix4d logRel = logm(h0.inverse() * h1);
    for (double t : {0.0, 0.2, 0.5, 0.8, 1.0}) {
      const DualQuaternion s = scLerp(t, p, q);
      ASSERT_TRUE(s.isUnit(kTol));
      const Eigen::Matrix4d oracle = h0 * expm(t * logRel);
      ASSERT_LE((s.toMatrix() - oracle).norm(), kTol * oracle.norm()) << i << " t " << t;
      ASSERT_LE((s.toMatrix() - se3Geodesic(t, h0, h1)).norm(), kTol * oracle.norm());
      // Rotation part: Eigen's quaternion slerp (shortest arc).
      const Eigen::Quaterniond slerp = p.real().slerp(t, q.real());
      ASSERT_LE(slerp.angularDistance(s.real()), kTol) << i << " t " << t;
      // Eberly eq. 33 built from the matrix pieces.
      ASSERT_LE(eberlyGeodesic(t, h0, h1).distanceUpToSign(s), kTol * oracle.norm());
    }
  }
}

TEST(ScLerp, ConstantSpeedAlongAFixedScrew) {
  // Equal parameter steps give the same relative motion Phi(t_k)^{-1} Phi(t_k+1)
  // (fixed axis, linear angle and translation: Kavan §2.1 definitions), and
  // the Frobenius speed of the matrix curve is Eberly's constant (eq. 30).
  std::mt19937 rng(testSeed("ScLerp.ConstantSpeedAlongAFixedScrew"));
  constexpr double h = 1e-5;
  constexpr double kFiniteDifferenceTol = 1e-8;  // O(h^2) + eps/h
  for (int i = 0; i < 30; ++i) {
    const Eigen::Matrix4d h0 = randomRigid(rng, kPi, 3), h1 = randomRigid(rng, kPi, 3);
    const DualQuaternion p = dq(h0), q = dq(h1);
    const Eigen::Matrix4d firstStep =
        scLerp(0.0, p, q).conjugate().toMatrix() * scLerp(0.125, p, q).toMatrix();
    const Vector6d xi = se3Log(h1 * rigidInverse(h0));
    const Eigen::Matrix3d s = se3Hat(xi).topLeftCorner<3, 3>();
    const double speed =
        std::sqrt(s.squaredNorm() + (s * h0.topRightCorner<3, 1>() + xi.tail<3>()).squaredNorm());
    for (int k = 1; k < 8; ++k) {
      const double t = k / 8.0;
      const Eigen::Matrix4d step =
          (scLerp(t, p, q).conjugate() * scLerp(t + 0.125, p, q)).toMatrix();
      ASSERT_LE((step - firstStep).norm(), kChainTol) << i << " k " << k;
      const Eigen::Matrix4d d =
          (scLerp(t + h, p, q).toMatrix() - scLerp(t - h, p, q).toMatrix()) / (2 * h);
      ASSERT_NEAR(d.norm(), speed, kFiniteDifferenceTol * (1 + speed)) << i << " k " << k;
    }
  }
}

TEST(ScLerp, ShortestPathIgnoresTheSignOfTheInputs) {
  // M1 = rotation by 3 pi / 2 about z, i.e. -pi/2: the shortest path turns by
  // -pi/4 at t = 1/2, whatever sign the dual quaternions carry.
  const Eigen::Matrix4d h0 = Eigen::Matrix4d::Identity();
  const Eigen::Matrix4d h1 =
      rigidFromAngleAxis(1.5 * kPi, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 2));
  const Eigen::Matrix4d expected =
      rigidFromAngleAxis(-0.25 * kPi, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 1));
  for (double sp : {1.0, -1.0}) {
    for (double sq : {1.0, -1.0}) {
      const DualQuaternion mid = scLerp(0.5, dq(h0) * sp, dq(h1) * sq);
      EXPECT_LE((mid.toMatrix() - expected).norm(), kTol) << sp << " " << sq;
      EXPECT_LE(rotationAngle(mid.toMatrix()), 0.25 * kPi + kTol);
    }
  }
}

TEST(Dib, TwoInputsConvergeToScLerpAfterOneIteration) {
  // Kavan Lemma 3.
  std::mt19937 rng(testSeed("Dib.TwoInputsConvergeToScLerpAfterOneIteration"));
  for (int i = 0; i < 100; ++i) {
    const DualQuaternion p = dq(randomRigid(rng, kPi, 3)), q = dq(randomRigid(rng, kPi, 3));
    const double t = uniform(rng, 0.0, 1.0);
    const DibResult r = dib({p, q}, {1 - t, t});
    ASSERT_TRUE(r.converged);
    ASSERT_EQ(r.iterations, 1) << "sample " << i;
    ASSERT_LE(matrixDistance(r.blend, scLerp(t, p, q)), kChainTol) << "sample " << i;
  }
}

TEST(Dib, ManyInputsReachTheWeightedMeanAndAreBiInvariant) {
  std::mt19937 rng(testSeed("Dib.ManyInputsReachTheWeightedMean"));
  int maxIterations = 0;
  for (int i = 0; i < 50; ++i) {
    std::vector<Eigen::Matrix4d> hs;
    std::vector<DualQuaternion> qs, left, right;
    const Eigen::Matrix4d r = randomRigid(rng, kPi, 3);
    for (int k = 0; k < 4; ++k) {
      hs.push_back(randomRigid(rng, 1.5, 2));
      qs.push_back(dq(hs.back()));
      left.push_back(dq(r) * qs.back());
      right.push_back(qs.back() * dq(r));
    }
    const std::vector<double> w = randomWeights(rng, 4);
    const DibResult b = dib(qs, w);
    ASSERT_TRUE(b.converged);
    maxIterations = std::max(maxIterations, b.iterations);
    // Stationarity checked with the matrix logarithm: sum w_i log(B^{-1} M_i) = 0.
    const Eigen::Matrix4d bInv = b.blend.toMatrix().inverse();
    Eigen::Matrix4d mean = Eigen::Matrix4d::Zero();
    for (int k = 0; k < 4; ++k) mean += w[k] * logm(bInv * hs[k]);
    ASSERT_LE(mean.norm(), kDibStationarityTol) << "sample " << i;
    ASSERT_LE((dib(left, w).blend.toMatrix() - r * b.blend.toMatrix()).norm(), kDibInvarianceTol);
    ASSERT_LE((dib(right, w).blend.toMatrix() - b.blend.toMatrix() * r).norm(), kDibInvarianceTol);
  }
  std::cout << "[ info     ] DIB iterations (max over samples): " << maxIterations << "\n";
}

TEST(Dib, ReportsTheIterationCapAndRejectsUnnormalisedWeights) {
  const std::vector<DualQuaternion> qs = {
      dq(rigidFromAngleAxis(0.1, Eigen::Vector3d::UnitX(), Eigen::Vector3d(1, 0, 0))),
      dq(rigidFromAngleAxis(2.0, Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 1, 0))),
      dq(rigidFromAngleAxis(1.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 1)))};
  const std::vector<double> w = {0.2, 0.5, 0.3};
  DibOptions capped;
  capped.maxIterations = 0;
  const DibResult r = dib(qs, w, capped);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_GT(r.residual, capped.precision);
  EXPECT_LE(r.blend.distanceUpToSign(dlb(qs, w)), 0.0);  // the DLB start
  EXPECT_THROW(dib(qs, {0.2, 0.5, 0.5}), InputError);
  EXPECT_THROW(dib(qs, {0.5, 0.5}), InputError);
}

TEST(Dlb, BiInvariant) {
  std::mt19937 rng(testSeed("Dlb.BiInvariant"));
  for (int i = 0; i < 200; ++i) {
    const DualQuaternion r = dq(randomRigid(rng, kPi, 3));
    std::vector<DualQuaternion> qs, left, right;
    for (int k = 0; k < 4; ++k) {
      qs.push_back(dq(randomRigid(rng, kPi, 3)));
      left.push_back(r * qs.back());
      right.push_back(qs.back() * r);
    }
    const std::vector<double> w = randomWeights(rng, 4);
    const DualQuaternion b = dlb(qs, w);
    ASSERT_TRUE(b.isUnit(kTol));
    ASSERT_LE(matrixDistance(dlb(left, w), r * b), kChainTol) << "sample " << i;
    ASSERT_LE(matrixDistance(dlb(right, w), b * r), kChainTol) << "sample " << i;
  }
}

TEST(Dlb, WithinKavanBoundOfScLerp) {
  // Kavan §4: for two inputs the DLB and ScLERP rotations share the screw
  // axis and their angles differ by < 8.15 degrees; the worst case (relative
  // rotation pi) comes within 0.05 degrees of the bound.
  std::mt19937 rng(testSeed("Dlb.WithinKavanBoundOfScLerp"));
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    const double maxAngle = i % 2 == 0 ? kPi : kPi - 1e-6;
    const Eigen::Matrix4d h0 = randomRigid(rng, kPi, 3);
    const Eigen::Matrix4d h1 =
        h0 * rigidFromAngleAxis(i % 2 == 0 ? uniform(rng, 0, maxAngle) : maxAngle,
                                core_test::randomUnitVector(rng),
                                Eigen::Vector3d(uniform(rng, -3, 3), 0, 1));
    const DualQuaternion p = dq(h0), q = dq(h1);
    for (int k = 1; k < 20; ++k) {
      const double t = k / 20.0;
      const DualQuaternion d = dlb({p, q}, {1 - t, t});
      const double gap = rotationAngle((d.conjugate() * scLerp(t, p, q)).toMatrix());
      ASSERT_LT(gap, kDlbAngleBound) << "sample " << i << " t " << t;
      worst = std::max(worst, gap);
    }
  }
  std::cout << "[ info     ] worst DLB-ScLERP angle gap (deg): " << worst * 180 / kPi << "\n";
  EXPECT_GT(worst, 8.0 * kPi / 180.0);
}

TEST(Dlb, AntipodalInputsAreAligned) {
  std::mt19937 rng(testSeed("Dlb.AntipodalInputsAreAligned"));
  for (int i = 0; i < 50; ++i) {
    const DualQuaternion a = dq(randomRigid(rng, kPi, 3)), b = dq(randomRigid(rng, kPi, 3));
    const std::vector<double> w = {0.3, 0.7};
    ASSERT_LE(matrixDistance(dlb({a, -b}, w), dlb({a, b}, w)), kTol);
    ASSERT_LE(matrixDistance(dlb({-a, b}, w), dlb({a, b}, w)), kTol);
    // The same motion twice with opposite signs: a naive sum would vanish.
    ASSERT_LE(matrixDistance(dlb({a, -a}, {0.5, 0.5}), a), kTol);
    // A unit weight vector returns the input motion.
    ASSERT_LE(matrixDistance(dlb({a, b}, {0.0, 1.0}), b), kTol);
  }
}

TEST(Dlb, RejectsCancellingWeightsAndSizeMismatch) {
  const DualQuaternion a = dq(rigidFromAngleAxis(0.4, Eigen::Vector3d::UnitX(), {1, 2, 3}));
  EXPECT_THROW(dlb({a, a}, {1.0, -1.0}), DomainError);
  EXPECT_THROW(dlb({a, a}, {1.0}), InputError);
  EXPECT_THROW(dlb(std::vector<DualQuaternion>{}, std::vector<double>{}), InputError);
}

}  // namespace
}  // namespace tetblend
