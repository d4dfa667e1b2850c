// The closed-form distortion and rotation angle of a tet's gradient
// (tetDistortion) against the reference (tetDistortionReference: Eigen's
// JacobiSVD) as the oracle, and the reference against polarDecompose.

#include "tetblend/blending/tet_distortion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>

#include "test_seed.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

constexpr double kEps = 2.220446049250313e-16;
// Agreement of the two, per unit of (1 + cond F). The closed form is taken
// only when its residual check holds: F = U S V^T + E with |E|_F <= 32 eps
// |F|_F <= 32 sqrt(3) eps sigma_max (polar_detail::kClosedFormMaxResidual),
// U and V orthonormal to a few ulps. By Weyl's inequality each sigma moves by
// at most |E|_2, so sigma_min, and the ratio sigma_max / sigma_min, move by at
// most 32 sqrt(3) eps (1 + cond) relative (~56 eps (1 + cond)); the polar
// factor moves by |E| / sigma_min, and the angle of the rotation by no more,
// i.e. the same bound in radians. JacobiSVD and the Newton iteration are
// backward stable with errors of a few eps |F|, the same form. 128 eps covers
// both with a factor ~2 to spare: 2.8e-11 at the closed form's largest cond
// (polar_detail::kClosedFormMaxCond = 1e3).
constexpr double kAgreementPerCond = 128 * kEps;

Eigen::Matrix3d randomRotation(std::mt19937& rng, double maxAngle) {
  const Eigen::Vector3d axis(test_seed::uniform(rng, -1, 1), test_seed::uniform(rng, -1, 1),
                             test_seed::uniform(rng, -1, 1));
  return Eigen::AngleAxisd(test_seed::uniform(rng, 0.0, maxAngle), axis.normalized())
      .toRotationMatrix();
}

// U diag(sigma) V^T with sigma spread over [1, cond] (scaled by `scale`),
// every other one with a (near-)double singular value.
Eigen::Matrix3d randomGradient(std::mt19937& rng, double cond, double scale, bool doubled) {
  Eigen::Vector3d sigma(1.0, std::exp(test_seed::uniform(rng, 0.0, std::log(cond))), cond);
  if (doubled) sigma(1) = sigma(2) * (1.0 + test_seed::uniform(rng, -1e-9, 1e-9));
  return scale * randomRotation(rng, M_PI) * sigma.asDiagonal() *
         randomRotation(rng, M_PI).transpose();
}

TEST(TetDistortion, ClosedFormAgreesWithTheJacobiSvdOracle) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(13));
  for (const double cond : {1.0, 1.0 + 1e-12, 1.001, 1.5, 10.0, 100.0, 999.0, 2000.0, 1e6}) {
    int closedForm = 0;
    const int samples = 400;
    for (int i = 0; i < samples; ++i) {
      const double scale = std::exp(test_seed::uniform(rng, -3.0, 3.0));
      const Eigen::Matrix3d f = randomGradient(rng, cond, scale, i % 2 == 1);
      const double det = f.determinant();
      Eigen::Matrix3d u, v;
      Eigen::Vector3d sigma;
      closedForm += polar_detail::svdClosedForm(f, u, sigma, v) ? 1 : 0;
      const TetDistortion got = tetDistortion(f, det);
      const TetDistortion want = tetDistortionReference(f, det);
      const double tolerance = kAgreementPerCond * (1.0 + want.conditionNumber);
      EXPECT_NEAR(got.conditionNumber, want.conditionNumber, tolerance * want.conditionNumber)
          << "cond " << cond << " sample " << i;
      EXPECT_NEAR(got.rotationAngle, want.rotationAngle, tolerance) << "cond " << cond;
    }
    // The closed form must be what was tested: every sample up to cond 100;
    // near its bound (1e3) the residual check declines a few (17 of 400).
    if (cond <= 100.0) {
      EXPECT_EQ(closedForm, samples) << "cond " << cond;
    } else if (cond < polar_detail::kClosedFormMaxCond) {
      EXPECT_GE(closedForm, samples * 9 / 10) << "cond " << cond;
    }
  }
}

// The reference's rotation is polarDecompose's (Newton iteration, an
// independent method) wherever that converges: random F up to cond 1e8.
TEST(TetDistortion, ReferenceRotationIsThePolarFactor) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(15));
  for (const double cond : {1.0, 10.0, 1e4, 1e8}) {
    for (int i = 0; i < 100; ++i) {
      const Eigen::Matrix3d f = randomGradient(rng, cond, 1.0, i % 2 == 1);
      const double angle = so3Log(polarDecompose(f).rotation).norm();
      // The polar factor moves by |E| / sigma_min for a perturbation E of F:
      // both methods are backward stable (a few eps |F|), so per unit of cond.
      EXPECT_NEAR(tetDistortionReference(f, f.determinant()).rotationAngle, angle,
                  kAgreementPerCond * (1.0 + cond))
          << "cond " << cond << " sample " << i;
    }
  }
}

// A blended gradient met in a tet of a part that an example scales to a
// point (a 4π-twisted bar beside a small bar collapsed to its centre),
// blended at that example's weights: its first and last columns are nearly
// parallel, det F = 5 comes from round-off in the 1e14 column, and
// polarDecompose's Newton iteration threw (it now falls back to the SVD),
// refusing the whole blend over a quality figure. The figures must still come out: a huge condition
// number and an angle in [0, pi].
TEST(TetDistortion, NearlySingularGradientWithPositiveDetStillGivesItsFigures) {
  Eigen::Matrix3d f;
  f.col(0) << 1.9623987849021332, -30.000000000000036, -6.9731662109173866;
  f.col(1) << -132469464534782.72, -591730547490293.25, -2840421470030.0571;
  f.col(2) << -1.226499240563832, 18.750000000000004, 4.3582288818233614;
  const double det = f.determinant();
  ASSERT_GT(det, 0.0);
  const TetDistortion got = tetDistortion(f, det);
  EXPECT_GT(got.conditionNumber, 1e15);
  EXPECT_GE(got.rotationAngle, 0.0);
  EXPECT_LE(got.rotationAngle, M_PI + 1e-12);
}

TEST(TetDistortion, InvertedAndFlatGradientsTakeTheReference) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(14));
  Eigen::Matrix3d f = randomGradient(rng, 3.0, 1.0, false);
  f.col(0) = -f.col(0);  // a reflection: det < 0
  const TetDistortion inverted = tetDistortion(f, f.determinant());
  EXPECT_EQ(inverted.conditionNumber, tetDistortionReference(f, f.determinant()).conditionNumber);
  EXPECT_TRUE(std::isnan(inverted.rotationAngle));
  f.col(0).setZero();
  EXPECT_TRUE(std::isinf(tetDistortion(f, 0.0).conditionNumber));
}

}  // namespace
}  // namespace tetblend
