#include "tetblend/core/kaji_ochiai.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "core_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using core_test::randomMatrixWithCond;
using core_test::randomRotation;
using core_test::randomUnitVector;
using core_test::relativeError;
using core_test::sqrtm;
using core_test::testSeed;
using core_test::uniform;

// phi(psi(A)) = A, relative Frobenius error of the linear part, by cond(A):
// the required accuracy bands of the design (a few ulps times cond, capped).
constexpr double kRoundTripTolCond1e2 = 1e-13;
constexpr double kRoundTripTolCond1e4 = 1e-11;
constexpr double kRoundTripTolCond1e8 = 1e-7;
// phi(psi(c A)) = c A for cond(A) <= 1e2 and any scale c the double range
// holds: the unit-scale band kRoundTripTolCond1e2 plus this many ulps of
// |log c|, since the stretch log holds log c rounded (ulp(700) = 1.1e-13
// absolute, which exp turns into a relative error) and adds it in a few
// roundings (k ln 2, the diagonal, the eigenvalues' mean).
constexpr double kLogScaleUlps = 8 * 2.220446049250313e-16;
// psi(c A) - log(c) I against psi(A), relative to |log S| (both hold log c
// rounded to its ulp, ~1e-16 relative) plus the cond-1e2 closed-form band.
constexpr double kScaleInvarianceTol = 1e-13;
// Parameter-space and group-property checks on unit-scale data.
constexpr double kParamTol = 1e-12;
// Fréchet iterations stop at |W| <= 1e-12; the fixed point is that close.
constexpr double kFrechetTol = 1e-11;
// phi against exp(hat w) exp(Y) by Eigen's Pade exp: Rodrigues' formula on
// turns up to 20 rad (sin/cos rounded to ulp(20) = 3.6e-15) and a closed-form
// symmetric exp of |Y| up to ~6: a few tens of ulps relative.
constexpr double kPhiOracleTol = 1e-13;
// Plain Blend of two rotations 0.5 to 2.5 rad apart misses the geodesic
// midpoint by the non-commuting part (second order in the angles, ~0.1):
// 1e-3 is far above kFrechetTol and far below that miss.
constexpr double kPlainMissGap = 1e-3;

Eigen::Matrix4d affine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& t) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = t;
  return m;
}

double roundTripTol(double cond) {
  return cond <= 1e2   ? kRoundTripTolCond1e2
         : cond <= 1e4 ? kRoundTripTolCond1e4
                       : kRoundTripTolCond1e8;
}

TEST(KajiOchiai, PhiMatchesMatrixFunctionsOracle) {
  std::mt19937 rng(testSeed("KajiOchiai.PhiMatchesMatrixFunctionsOracle"));
  for (int i = 0; i < 300; ++i) {
    AffineParams p;
    p.translation = core_test::randomUniform<3, 1>(rng);
    p.rotationLog = uniform(rng, 0, 20) * randomUnitVector(rng);
    Eigen::Matrix3d y = core_test::randomUniform<3, 3>(rng);
    p.stretchLog = y + y.transpose();
    const Eigen::Matrix3d oracle = expm(hat(p.rotationLog)) * expm(p.stretchLog);
    const Eigen::Matrix4d m = phi(p);
    ASSERT_LE(relativeError(m.topLeftCorner<3, 3>(), oracle), kPhiOracleTol);
    ASSERT_TRUE((m.topRightCorner<3, 1>() == p.translation));
    ASSERT_EQ(m.row(3), Eigen::RowVector4d(0, 0, 0, 1));
  }
}

TEST(KajiOchiai, PhiPsiRoundTripByConditionBand) {
  std::mt19937 rng(testSeed("KajiOchiai.PhiPsiRoundTripByConditionBand"));
  for (double cond : {1.0, 10.0, 1e2, 1e3, 1e4, 1e6, 1e8}) {
    for (int i = 0; i < 200; ++i) {
      const double scale = std::exp(uniform(rng, -std::log(1e6), std::log(1e6)));
      const Eigen::Matrix4d a = affine(randomMatrixWithCond(rng, cond, scale),
                                       scale * core_test::randomUniform<3, 1>(rng));
      const AffineParams p = psi(a);
      const Eigen::Matrix4d back = phi(p);
      ASSERT_TRUE(back.allFinite()) << a;
      ASSERT_LE(relativeError(back.topLeftCorner<3, 3>(), a.topLeftCorner<3, 3>()),
                roundTripTol(cond))
          << "cond " << cond << "\n"
          << a;
      ASSERT_TRUE((back.topRightCorner<3, 1>() == a.topRightCorner<3, 1>()));
    }
  }
}

TEST(KajiOchiai, PhiPsiRoundTripOnHardCases) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -2).normalized();
  std::mt19937 rng(7);  // fixed: only the eigenbasis of the stretch is random
  const Eigen::Matrix3d stretch =
      core_test::spdWithEigenvalues(rng, Eigen::Vector3d(2, 2, 0.5));  // coincident pair
  struct Case {
    Eigen::Matrix3d linear;
    double cond;
  };
  const std::vector<Case> cases = {
      {Eigen::Matrix3d::Identity(), 1.0},
      {so3Exp(1e-12 * axis), 1.0},
      {so3Exp((kPi - 1e-9) * axis) * stretch, 4.0},
      {2 * axis * axis.transpose() - Eigen::Matrix3d::Identity(), 1.0},  // exactly pi
      {so3Exp(20.0 * axis) * stretch, 4.0},
      {Eigen::Vector3d(1, 1 + 1e-9, 1 - 1e-9).asDiagonal(), 1.0},
      {1e-6 * so3Exp(axis) * stretch, 4.0},
      {1e6 * so3Exp(axis) * stretch, 4.0},
      {Eigen::Vector3d(1, 1e-4, 1e-8).asDiagonal(), 1e8},
      {so3Exp(3.0 * axis) * Eigen::Vector3d(1, 1, 1e-10).asDiagonal(), 1e10}};  // sigma_min
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "A =\n" << c.linear);
    const Eigen::Matrix4d a = affine(c.linear, Eigen::Vector3d(1, -2, 3));
    const Eigen::Matrix4d back = phi(psi(a));
    ASSERT_TRUE(back.allFinite());
    const double cond = c.cond;
    EXPECT_LE(relativeError(back, a), roundTripTol(cond));
  }
}

TEST(KajiOchiai, PsiInvertsPhiOnPrincipalParameters) {
  std::mt19937 rng(testSeed("KajiOchiai.PsiInvertsPhiOnPrincipalParameters"));
  for (int i = 0; i < 300; ++i) {
    AffineParams p;
    p.translation = core_test::randomUniform<3, 1>(rng);
    p.rotationLog = uniform(rng, 0, kPi - 1e-3) * randomUnitVector(rng);
    Eigen::Matrix3d y = core_test::randomUniform<3, 3>(rng);
    p.stretchLog = y + y.transpose();
    const AffineParams q = psi(phi(p));
    ASSERT_LE((q.rotationLog - p.rotationLog).norm(), kParamTol);
    ASSERT_LE((q.stretchLog - p.stretchLog).norm(), kParamTol);
    ASSERT_EQ(q.translation, p.translation);
  }
}

TEST(KajiOchiai, PsiThrowsForNonPositiveDeterminant) {
  EXPECT_THROW(psi(affine(Eigen::Vector3d(1, 1, -1).asDiagonal(), Eigen::Vector3d::Zero())),
               DomainError);
  EXPECT_THROW(psi(affine(Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero())), DomainError);
  EXPECT_THROW(
      psi(affine(-Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), Eigen::Vector3d::Zero()),
      DomainError);
}

TEST(KajiOchiai, PsiRejectsANonFiniteReference) {
  // Regression (issue 14): a NaN reference gave a NaN rotation log.
  const Eigen::Matrix4d a = affine(so3Exp(Eigen::Vector3d(0.1, 0.2, 0.3)), Eigen::Vector3d::Zero());
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      psi(a, Eigen::Vector3d(0.0, bad, 0.0));
      ADD_FAILURE() << "no error for reference component " << bad;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("reference"), std::string::npos) << error.what();
    }
  }
}

/// psi(c A) = psi(A) + (0, 0, log(c) I) and phi(psi(c A)) = c A, checked for
/// the linear part scaled by c (the translation is carried unchanged).
void expectScaleInvariance(const Eigen::Matrix3d& linear, double c, double tol) {
  const Eigen::Vector3d t(1, -2, 3);
  const AffineParams base = psi(affine(linear, t));
  const Eigen::Matrix4d scaled = affine(c * linear, t);
  AffineParams p;
  ASSERT_NO_THROW(p = psi(scaled)) << "c = " << c << ", A =\n" << linear;
  const double logC = std::log(c);
  Eigen::Matrix3d expected = base.stretchLog;
  expected.diagonal().array() += logC;
  // The stretch log holds log c, whose ulp (up to 1.1e-13 at |log c| ~ 700)
  // bounds what any method can return: relative to |log S|.
  ASSERT_LE((p.stretchLog - expected).norm(), tol * (1.0 + expected.norm())) << "c = " << c;
  ASSERT_LE((p.rotationLog - base.rotationLog).norm(), tol) << "c = " << c;
  const Eigen::Matrix4d back = phi(p);
  ASSERT_TRUE(back.allFinite()) << "c = " << c;
  ASSERT_LE(relativeError(back.topLeftCorner<3, 3>(), scaled.topLeftCorner<3, 3>()),
            kRoundTripTolCond1e2 + kLogScaleUlps * std::abs(logC))
      << "c = " << c << ", A =\n"
      << linear;
  ASSERT_EQ(p.translation, t);
}

TEST(KajiOchiai, PsiAndPhiAreExactAtEveryScale) {
  // Regression (issue 14): psi(c A) threw NumericalError for c = 1e77 and
  // 1e-82 on a cond-3 matrix. Scale must never matter: a sweep over the
  // whole double range on fixed and seeded matrices of cond <= 1e2.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -2).normalized();
  std::vector<Eigen::Matrix3d> matrices = {
      Eigen::Matrix3d::Identity(), Eigen::Vector3d(3, 1, 1).asDiagonal(),
      so3Exp(2.0 * axis) * Eigen::Vector3d(1.5, 1.0, 0.5).asDiagonal(),
      so3Exp((kPi - 1e-9) * axis) * Eigen::Vector3d(1e2, 1.0, 1.0).asDiagonal()};
  std::mt19937 rng(testSeed("KajiOchiai.PsiAndPhiAreExactAtEveryScale"));
  for (int i = 0; i < 6; ++i) matrices.push_back(randomMatrixWithCond(rng, i < 3 ? 3.0 : 1e2));
  for (const Eigen::Matrix3d& linear : matrices) {
    for (int j = -300; j <= 300; j += 10) {
      expectScaleInvariance(linear, std::pow(10.0, j), kScaleInvarianceTol);
    }
    for (const double c : {1e77, 1e-82, 1e-305, 1e305}) {
      expectScaleInvariance(linear, c, kScaleInvarianceTol);
    }
  }
}

TEST(KajiOchiai, PsiOfExtremeConditionWithSubnormalDeterminant) {
  // Regression (issue 14): psi(diag(1, 1, 1e-310)) threw NumericalError; the
  // determinant is subnormal and the inverse overflows unless rescaled.
  const AffineParams p =
      psi(affine(Eigen::Vector3d(1, 1, 1e-310).asDiagonal(), Eigen::Vector3d::Zero()));
  EXPECT_LE(p.rotationLog.norm(), kParamTol);
  const Eigen::Matrix3d expected = Eigen::Vector3d(0, 0, std::log(1e-310)).asDiagonal();
  EXPECT_LE((p.stretchLog - expected).norm(), kScaleInvarianceTol * expected.norm());
  // Normwise round trip (the subnormal entry itself is below the normwise
  // round-off of the unit entries).
  const Eigen::Matrix4d back = phi(p);
  ASSERT_TRUE(back.allFinite());
  EXPECT_LE(relativeError(
                back, affine(Eigen::Vector3d(1, 1, 1e-310).asDiagonal(), Eigen::Vector3d::Zero())),
            kParamTol);
}

TEST(KajiOchiai, ConsistentLogKeepsAFourPiTwist) {
  // Kaji–Ochiai Fig. 2: the reference recovers a 4 pi - 0.1 twist, and the
  // half blend is then a 2 pi - 0.05 twist, not the short way round.
  const Eigen::Vector3d axis(0, 0, 1);
  const double angle = 4 * kPi - 0.1;
  const Eigen::Matrix4d a = affine(so3Exp(angle * axis) * 1.5, Eigen::Vector3d::Zero());
  const AffineParams p = psi(a, (angle + 0.3) * axis);
  EXPECT_NEAR(p.rotationLog.z(), angle, kParamTol);
  const Eigen::Matrix4d half = kajiBlend({0.5}, {p});
  EXPECT_LE((half.topLeftCorner<3, 3>() - so3Exp(0.5 * angle * axis) * std::sqrt(1.5)).norm(),
            kParamTol);
  EXPECT_NEAR(psi(a).rotationLog.norm(), 0.1, kParamTol);  // principal: short way
}

TEST(KajiOchiai, BlendInterpolatesTheExamples) {
  std::mt19937 rng(testSeed("KajiOchiai.BlendInterpolatesTheExamples"));
  std::vector<AffineParams> params;
  std::vector<Eigen::Matrix4d> mats;
  for (int k = 0; k < 3; ++k) {
    mats.push_back(affine(randomMatrixWithCond(rng, 10.0), core_test::randomUniform<3, 1>(rng)));
    params.push_back(psi(mats.back()));
  }
  EXPECT_LE((kajiBlend({0, 0, 0}, params) - Eigen::Matrix4d::Identity()).norm(), 0.0);
  for (int k = 0; k < 3; ++k) {
    std::vector<double> w(3, 0.0);
    w[k] = 1.0;
    EXPECT_LE(relativeError(kajiBlend(w, params), mats[k]), kRoundTripTolCond1e2);
  }
  EXPECT_THROW(kajiBlend({1.0}, params), InputError);
}

/// Random matrix of the subgroup, and whether a matrix belongs to it.
Eigen::Matrix4d randomInSubgroup(std::mt19937& rng, AffineSubgroup g) {
  const Eigen::Vector3d t = core_test::randomUniform<3, 1>(rng);
  const Eigen::Matrix3d r = randomRotation(rng);
  const Eigen::Matrix3d s =
      core_test::spdWithEigenvalues(rng, core_test::randomUniform<3, 1>(rng).array().exp());
  switch (g) {
    case AffineSubgroup::Translation:
      return affine(Eigen::Matrix3d::Identity(), t);
    case AffineSubgroup::Rotation:
      return affine(r, Eigen::Vector3d::Zero());
    case AffineSubgroup::Stretch:
      return affine(s, Eigen::Vector3d::Zero());
    case AffineSubgroup::Rigid:
      return affine(r, t);
    case AffineSubgroup::Similarity:
      return affine(std::exp(uniform(rng, -2, 2)) * r, t);
    case AffineSubgroup::General:
      return affine(r * s, t);
  }
  return Eigen::Matrix4d::Identity();
}

void expectMatrixInSubgroup(const Eigen::Matrix4d& m, AffineSubgroup g) {
  const Eigen::Matrix3d l = m.topLeftCorner<3, 3>();
  const Eigen::Matrix3d i = Eigen::Matrix3d::Identity();
  const double scale2 = (l.transpose() * l).trace() / 3.0;
  const bool noTranslation = m.topRightCorner<3, 1>().norm() <= kParamTol;
  switch (g) {
    case AffineSubgroup::Translation:
      EXPECT_LE((l - i).norm(), kParamTol);
      break;
    case AffineSubgroup::Rotation:
      EXPECT_TRUE(noTranslation);
      EXPECT_LE((l.transpose() * l - i).norm(), kParamTol);
      break;
    case AffineSubgroup::Stretch:
      EXPECT_TRUE(noTranslation);
      EXPECT_LE((l - l.transpose()).norm(), kParamTol * l.norm());
      EXPECT_GT(symEigenvalues(l).minCoeff(), 0.0);
      break;
    case AffineSubgroup::Rigid:
      EXPECT_LE((l.transpose() * l - i).norm(), kParamTol);
      break;
    case AffineSubgroup::Similarity:
      EXPECT_LE((l.transpose() * l - scale2 * i).norm(), kParamTol * scale2);
      break;
    case AffineSubgroup::General:
      break;
  }
  EXPECT_GT(l.determinant(), 0.0);
}

TEST(KajiOchiai, EverySubgroupIsClosedUnderBlend) {
  // Property (V): inputs in a subgroup blend (any weights, extrapolation
  // included) to a matrix of the same subgroup.
  std::mt19937 rng(testSeed("KajiOchiai.EverySubgroupIsClosedUnderBlend"));
  for (AffineSubgroup g :
       {AffineSubgroup::Translation, AffineSubgroup::Rotation, AffineSubgroup::Stretch,
        AffineSubgroup::Rigid, AffineSubgroup::Similarity, AffineSubgroup::General}) {
    for (int trial = 0; trial < 50; ++trial) {
      SCOPED_TRACE(testing::Message() << "subgroup " << static_cast<int>(g));
      std::vector<AffineParams> params;
      std::vector<double> weights;
      for (int k = 0; k < 4; ++k) {
        params.push_back(psi(randomInSubgroup(rng, g)));
        EXPECT_TRUE(inSubgroup(params.back(), g, kParamTol));
        weights.push_back(uniform(rng, -0.5, 1.5));
      }
      expectMatrixInSubgroup(kajiBlend(weights, params), g);
      expectMatrixInSubgroup(
          kajiFrechetBlend(weights, std::vector<Eigen::Matrix4d>{phi(params[0]), phi(params[1]),
                                                                 phi(params[2]), phi(params[3])})
              .matrix,
          g);
    }
  }
}

TEST(KajiOchiai, SubgroupMembershipAndProjection) {
  AffineParams p = AffineParams::Zero();
  p.translation = Eigen::Vector3d(1, 0, 0);
  p.stretchLog = 0.5 * Eigen::Matrix3d::Identity();
  EXPECT_TRUE(inSubgroup(p, AffineSubgroup::Similarity, 0.0));
  EXPECT_FALSE(inSubgroup(p, AffineSubgroup::Rigid, 0.1));
  EXPECT_FALSE(inSubgroup(p, AffineSubgroup::Stretch, 0.1));
  EXPECT_TRUE(inSubgroup(projectToSubgroup(p, AffineSubgroup::Rigid), AffineSubgroup::Rigid, 0));
  p.stretchLog(0, 1) = p.stretchLog(1, 0) = 0.2;
  EXPECT_FALSE(inSubgroup(p, AffineSubgroup::Similarity, 0.1));
  EXPECT_EQ(projectToSubgroup(p, AffineSubgroup::Similarity).stretchLog,
            0.5 * Eigen::Matrix3d::Identity());
  const AffineParams sum = 2.0 * p - p + AffineParams::Zero();
  EXPECT_EQ(sum.stretchLog, p.stretchLog);
  EXPECT_EQ((-p).translation, -p.translation);
}

TEST(KajiOchiai, FrechetBlendOfTwoRotationsIsTheSlerpMidpoint) {
  std::mt19937 rng(testSeed("KajiOchiai.FrechetBlendOfTwoRotationsIsTheSlerpMidpoint"));
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix3d r0 = randomRotation(rng);
    const Eigen::Matrix3d r1 = r0 * so3Exp(uniform(rng, 0.5, 2.5) * randomUnitVector(rng));
    // Geodesic midpoint (Eberly eq. (12) at t = 1/2), by the oracle log.
    const Eigen::Matrix3d oracle = r0 * expm(0.5 * logm(r0.transpose() * r1));
    const std::vector<Eigen::Matrix4d> mats = {affine(r0, Eigen::Vector3d::Zero()),
                                               affine(r1, Eigen::Vector3d::Zero())};
    const FrechetBlendResult f = kajiFrechetBlend({0.5, 0.5}, mats);
    ASSERT_TRUE(f.converged);
    ASSERT_LE((f.matrix.topLeftCorner<3, 3>() - oracle).norm(), kFrechetTol);
    // Plain Blend is not bi-invariant: it misses the midpoint in general,
    // which is what makes this test discriminating.
    const Eigen::Matrix4d plain = kajiBlend({0.5, 0.5}, {psi(mats[0]), psi(mats[1])});
    if (i == 0) {
      EXPECT_GT((plain.topLeftCorner<3, 3>() - oracle).norm(), kPlainMissGap);
    }
  }
}

TEST(KajiOchiai, FrechetBlendOfTwoStretchesIsTheAffineInvariantMidpoint) {
  std::mt19937 rng(testSeed("KajiOchiai.FrechetBlendOfTwoStretchesIsTheAffineInvariantMidpoint"));
  const Eigen::Matrix3d s0 = core_test::spdWithEigenvalues(rng, Eigen::Vector3d(3, 1, 0.5));
  const Eigen::Matrix3d s1 = core_test::spdWithEigenvalues(rng, Eigen::Vector3d(0.2, 1, 2));
  const Eigen::Matrix3d h = sqrtm(s0), hi = h.inverse();
  const Eigen::Matrix3d oracle = h * sqrtm(hi * s1 * hi) * h;
  const FrechetBlendResult f = kajiFrechetBlend(
      {0.5, 0.5}, {affine(s0, Eigen::Vector3d::Zero()), affine(s1, Eigen::Vector3d(2, 0, 0))});
  EXPECT_TRUE(f.converged);
  EXPECT_LE(relativeError(f.matrix.topLeftCorner<3, 3>(), oracle), kFrechetTol);
  EXPECT_LE((f.matrix.topRightCorner<3, 1>() - Eigen::Vector3d(1, 0, 0)).norm(), 0.0);
}

TEST(KajiOchiai, FrechetBlendReportsTheIterationCap) {
  const std::vector<Eigen::Matrix4d> mats = {
      affine(so3Exp(Eigen::Vector3d(2.5, 0, 0)), Eigen::Vector3d::Zero()),
      affine(so3Exp(Eigen::Vector3d(0, 2.5, 0)), Eigen::Vector3d::Zero()),
      affine(so3Exp(Eigen::Vector3d(0, 0, 2.5)), Eigen::Vector3d::Zero())};
  // Three non-commuting rotations: unlike two (exact after one step), the
  // Karcher iteration needs several steps.
  const std::vector<double> thirds = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  FrechetBlendOptions options;
  options.maxIterations = 1;
  const FrechetBlendResult capped = kajiFrechetBlend(thirds, mats, options);
  EXPECT_FALSE(capped.converged);
  EXPECT_LE(capped.iterations, 2);
  const FrechetBlendResult full = kajiFrechetBlend(thirds, mats);
  EXPECT_TRUE(full.converged);
  EXPECT_GT(full.iterations, 1);
  // Unit weights give the example itself.
  EXPECT_LE((kajiFrechetBlend({0.0, 1.0, 0.0}, mats).matrix - mats[1]).norm(), kFrechetTol);
}

}  // namespace
}  // namespace tetblend
