// The closed-form distortion and rotation angle of a tet's gradient
// (tetDistortion) against the reference (tetDistortionReference: Eigen's
// JacobiSVD and polarDecompose's Newton iteration) as the oracle.

#include "tetblend/blending/tet_distortion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>

#include "test_seed.h"
#include "tetblend/core/polar.h"

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
