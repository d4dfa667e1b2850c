// The C^1 multi-key scheme of Bansal & Tatu §4.1 (eq. 5-6).

#include "tetblend/core/lie_body_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "lie_test_support.h"
#include "tetblend/core/error.h"
#include "tetblend/core/shear_group.h"

namespace tetblend {
namespace {

using lie_test::randomRotation;
using lie_test::randomShear;
using lie_test::testSeed;
using lie_test::uniform;

// Keys and the two-key geodesic: a few hundred roundings of unit-scale values.
// A key reached through segment i is p_i exp(B_i) exp(C_i) with C_i the log of
// exp(-B_i) p_i^-1 p_{i+1} (eq. 5): its shear factor is recovered by
// multiplying by exp(B_i) what was computed after multiplying by exp(-B_i),
// so round-off is amplified by cond(exp(B_i)) = |exp(B_i)| |exp(-B_i)|, which
// grows with the shear tangent that eq. 6 accumulates along the chain
// (keyConditioning). kKeyTol applies after that factor.
constexpr double kKeyTol = 1e-12;
// One-sided second-order finite differences with step kStep: truncation
// ~kStep^2 |f'''| / 3 ~ 1e-8 for the unit-scale curves here, round-off
// ~eps |f| / kStep ~ 1e-12; left and right derivatives must agree to 1e-6
// relative. A piecewise geodesic (no C^1 construction) misses by > kKinkGap.
constexpr double kStep = 1e-4;
constexpr double kDerivativeTol = 1e-6;
constexpr double kKinkGap = 1e-2;

// All components of a Lie body as one vector (E: 12 entries, A: 5, s).
Eigen::VectorXd flatten(const LieBody& p) {
  Eigen::VectorXd v(18);
  v.head<12>() = Eigen::Map<const Eigen::VectorXd>(p.rigid.data(), 16).head<12>();
  v.segment<5>(12) << p.shear(0, 1), p.shear(0, 2), p.shear(1, 1), p.shear(1, 2), p.shear(2, 2);
  v(17) = p.scale;
  return v;
}

// Random keys along a wandering path: consecutive keys differ by rotations
// up to 1.2 rad, shears, scales and translations of order 1.
std::vector<LieBody> randomKeys(std::mt19937& rng, int count) {
  std::vector<LieBody> keys;
  Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
  for (int k = 0; k < count; ++k) {
    Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
    step.topLeftCorner<3, 3>() = randomRotation(rng, 1.2);
    step.topRightCorner<3, 1>() << uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1);
    e = step * e;
    keys.push_back({e, randomShear(rng, 0.7, 1.0), std::exp(uniform(rng, -0.7, 0.7))});
  }
  return keys;
}

// Conditioning of reaching key k (> 0) through segment k - 1: cond_F of the
// shear factor exp(B_{k-1}) (the rigid and scale factors are orthogonal or
// scalar and add no amplification beyond the unit-scale tolerance).
double keyConditioning(const LieBodySpline& spline, int k) {
  const Eigen::Matrix3d b = spline.segmentVelocity(k - 1).shear;
  return shearExp(b).norm() * shearExp(-b).norm() / 3.0;
}

// Largest relative mismatch of the left and right derivatives at u.
double derivativeJump(const std::function<LieBody(double)>& curve, double u) {
  const Eigen::VectorXd f0 = flatten(curve(u));
  const Eigen::VectorXd left =
      (3 * f0 - 4 * flatten(curve(u - kStep)) + flatten(curve(u - 2 * kStep))) / (2 * kStep);
  const Eigen::VectorXd right =
      (-3 * f0 + 4 * flatten(curve(u + kStep)) - flatten(curve(u + 2 * kStep))) / (2 * kStep);
  return (left - right).norm() / (1.0 + right.norm());
}

TEST(LieBodySpline, PassesThroughTheKeysWithContinuousDerivative) {
  std::mt19937 rng(testSeed("PassesThroughTheKeysWithContinuousDerivative"));
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<LieBody> keys = randomKeys(rng, 5);
    const LieBodySpline spline(keys);
    ASSERT_EQ(spline.segmentCount(), 4);
    for (int k = 0; k < 5; ++k) {
      const double scale =
          (1.0 + flatten(keys[k]).norm()) * (k > 0 ? keyConditioning(spline, k) : 1.0);
      EXPECT_LE((flatten(spline.evaluate(k)) - flatten(keys[k])).norm(), kKeyTol * scale);
    }
    for (int k = 1; k < 4; ++k) {
      EXPECT_LE(derivativeJump([&](double u) { return spline.evaluate(u); }, k), kDerivativeTol);
    }
    // The piecewise geodesic through the same keys has kinks at the keys.
    const auto piecewise = [&](double u) {
      const int i = std::min(3, static_cast<int>(std::floor(u)));
      return lieBodyInterpolate(keys[i], keys[i + 1], u - i);
    };
    double worstKink = 0.0;
    for (int k = 1; k < 4; ++k) worstKink = std::max(worstKink, derivativeJump(piecewise, k));
    EXPECT_GT(worstKink, kKinkGap);
  }
}

TEST(LieBodySpline, EndOfEachSegmentIsTheNextKey) {
  std::mt19937 rng(testSeed("EndOfEachSegmentIsTheNextKey"));
  const std::vector<LieBody> keys = randomKeys(rng, 4);
  const LieBodySpline spline(keys);
  // u = 3 is the end of the last segment (t = 1), not a new segment.
  EXPECT_LE((flatten(spline.evaluate(3.0)) - flatten(keys[3])).norm(),
            kKeyTol * (1.0 + flatten(keys[3]).norm()));
  // Just below each interior key, the segment ending there is evaluated.
  for (int k = 1; k < 3; ++k) {
    const double u = std::nextafter(static_cast<double>(k), 0.0);
    EXPECT_LE((flatten(spline.evaluate(u)) - flatten(keys[k])).norm(),
              kKeyTol * (1.0 + flatten(keys[k]).norm()));
  }
}

TEST(LieBodySpline, TwoKeysGiveTheGeodesic) {
  std::mt19937 rng(testSeed("TwoKeysGiveTheGeodesic"));
  const std::vector<LieBody> keys = randomKeys(rng, 2);
  const LieBodySpline spline(keys);
  for (double u : {-0.3, 0.2, 0.5, 0.9, 1.4}) {
    const Eigen::VectorXd want = flatten(lieBodyInterpolate(keys[0], keys[1], u));
    EXPECT_LE((flatten(spline.evaluate(u)) - want).norm(), kKeyTol * (1.0 + want.norm()));
  }
}

TEST(LieBodySpline, RejectsFewerThanTwoKeys) {
  EXPECT_THROW(LieBodySpline({LieBody::Identity()}), InputError);
}

}  // namespace
}  // namespace tetblend
