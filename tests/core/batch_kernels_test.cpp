// The batched kernels (batch_kernels.h) against their scalar versions, which
// the other core tests check against Eigen's MatrixFunctions: fixed hard
// cases on both sides of every branch threshold the lanes replicate, the
// cases the lanes hand back to the scalar kernel, errors, and seeded random
// samples in counts that leave a partial last block.

#include "tetblend/core/batch_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/SVD>

#include "core_test_support.h"
#include "test_seed.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/lane_math.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

// Batched and scalar kernels evaluate the same formulas; they differ by the
// elementary functions (lane_math, within 3 ulp of libm) and FMA contraction,
// i.e. a few ulps per operation, amplified by the kernel's conditioning: up to
// cond(S) <= 1e2 for the closed-form log (sym3.h) and the divided differences
// near the series switches. Relative to 1 + |scalar result|_F.
constexpr double kBatchVsScalarTol = 1e-13;
// phi(psi(A)) = A through the batched pair, relative Frobenius error of the
// linear part: the design's accuracy bands by cond(A), as for the scalar pair
// (kaji_ochiai_test.cpp).
constexpr double kRoundTripTolCond1e2 = 1e-13;
constexpr double kRoundTripTolCond1e4 = 1e-11;
constexpr double kRoundTripTolCond1e8 = 1e-7;
// Random samples per kernel: 15 full blocks of 64 and a partial one.
constexpr int kRandomCount = 1000;

unsigned seed(const char* name) { return test_seed::seedFor(name, 7031u); }

Eigen::Matrix3d randomRotation(std::mt19937& rng, double maxAngle) {
  std::normal_distribution<double> n;
  const Eigen::Vector3d axis = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
  return so3Exp(test_seed::uniform(rng, 0.0, maxAngle) * axis);
}

Eigen::Matrix3d randomSymmetric(std::mt19937& rng, double range) {
  Eigen::Matrix3d y;
  for (int r = 0; r < 3; ++r)
    for (int c = r; c < 3; ++c) y(r, c) = y(c, r) = test_seed::uniform(rng, -range, range);
  return y;
}

/// V diag(values) V^T with a random rotation V.
Eigen::Matrix3d withEigenvalues(std::mt19937& rng, const Eigen::Vector3d& values) {
  const Eigen::Matrix3d v = randomRotation(rng, 3.0);
  return v * values.asDiagonal() * v.transpose();
}

/// |batched - scalar| / (1 + |scalar|), Frobenius (stableNorm: results may be
/// near the ends of the double range).
template <typename A, typename B>
double relativeGap(const A& batched, const B& scalar) {
  return (batched - scalar).stableNorm() / (1.0 + scalar.stableNorm());
}

TEST(BatchKernels, So3ExpMatchesScalar) {
  std::mt19937 rng(seed("So3ExpMatchesScalar"));
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  const double small = so3_detail::kSmallAngle;
  const double laneMax = 2.0 * lane_math::kSinCosMaxArg;  // |omega| the lanes take
  std::vector<Eigen::Vector3d> in;
  // Zero, tiny angles, both sides of the Taylor switch kSmallAngle, pi, turns
  // beyond 2 pi, both sides of the lanes' sin/cos range (the scalar kernel
  // takes over above it) and a huge angle.
  for (double theta : {0.0, 1e-12, 0.5 * small, 2.0 * small, 1.0, kPi, 7.0, 40.0, 0.999 * laneMax,
                       1.001 * laneMax, 1e155}) {
    in.push_back(theta * axis);
  }
  std::normal_distribution<double> normal;
  for (int i = 0; i < kRandomCount; ++i) {
    in.push_back(test_seed::uniform(rng, 0.0, 30.0) *
                 Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
  }
  std::vector<Eigen::Matrix3d> out(in.size());
  so3ExpBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], so3Exp(in[i])), kBatchVsScalarTol) << "element " << i;
  }
}

TEST(BatchKernels, So3LogMatchesScalar) {
  std::mt19937 rng(seed("So3LogMatchesScalar"));
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  const double small = so3_detail::kSmallAngle;
  std::vector<Eigen::Matrix3d> in;
  // Identity, tiny angles, both sides of kSmallAngle and of the axis switch at
  // theta = pi/2 (cos = 0), pi - 1e-9, and exactly pi about coordinate axes.
  for (double theta : {0.0, 1e-12, 0.5 * small, 2.0 * small, 1.0, 0.5 * kPi - 1e-9,
                       0.5 * kPi + 1e-9, 3.0, kPi - 1e-9, kPi}) {
    in.push_back(so3Exp(theta * axis));
  }
  in.push_back(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal());
  in.push_back(Eigen::Vector3d(-1.0, 1.0, -1.0).asDiagonal());
  in.push_back(Eigen::Vector3d(-1.0, -1.0, 1.0).asDiagonal());
  for (int i = 0; i < kRandomCount; ++i) in.push_back(randomRotation(rng, kPi));
  std::vector<Eigen::Vector3d> out(in.size());
  so3LogBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], so3Log(in[i])), kBatchVsScalarTol) << "element " << i;
  }
}

TEST(BatchKernels, SymExpMatchesScalar) {
  std::mt19937 rng(seed("SymExpMatchesScalar"));
  const double spread = sym3_detail::kExpSeriesSpread;
  std::vector<Eigen::Matrix3d> in = {Eigen::Matrix3d::Zero(), 2.5 * Eigen::Matrix3d::Identity()};
  // Eigenvalue spread on both sides of the series switch, a double
  // eigenvalue, and eigenvalues beyond the lanes' exp range (scalar path).
  for (double h : {0.5 * spread, 0.99 * spread, 1.01 * spread, 2.0 * spread, 1e-10}) {
    in.push_back(withEigenvalues(rng, Eigen::Vector3d(0.3 + h, 0.3 + 0.4 * h, 0.3)));
  }
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(1.0, 1.0, -2.0)));
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(705.0, 1.0, -2.0)));
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(1.0, 0.0, -710.0)));
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(400.0, 0.0, -400.0)));
  for (int i = 0; i < kRandomCount; ++i) in.push_back(randomSymmetric(rng, i % 2 ? 1.0 : 20.0));
  std::vector<Eigen::Matrix3d> out(in.size());
  symExpBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], symExp(in[i])), kBatchVsScalarTol) << "element " << i;
  }
}

TEST(BatchKernels, SymLogMatchesScalarAndThrowsLikeIt) {
  std::mt19937 rng(seed("SymLogMatchesScalarAndThrowsLikeIt"));
  const double spread = sym3_detail::kLogSeriesSpread;
  const double maxCond = sym3_detail::kLogClosedFormMaxCond;
  std::vector<Eigen::Matrix3d> in = {Eigen::Matrix3d::Identity(),
                                     3.0 * Eigen::Matrix3d::Identity()};
  // Relative spread on both sides of the series switch; cond on both sides of
  // the closed-form limit (above: the scalar eigen-decomposition path).
  for (double h : {0.5 * spread, 0.99 * spread, 1.01 * spread, 2.0 * spread, 1e-10}) {
    in.push_back(
        withEigenvalues(rng, Eigen::Vector3d(2.0 * (1.0 + h), 2.0 * (1.0 + 0.3 * h), 2.0)));
  }
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(0.99 * maxCond, 1.0, 1.0)));
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(1.01 * maxCond, 1.0, 1.0)));
  in.push_back(withEigenvalues(rng, Eigen::Vector3d(1e-3, 1e-3, 1e-5)));
  for (int i = 0; i < kRandomCount; ++i) in.push_back(symExp(randomSymmetric(rng, 1.0)));
  std::vector<Eigen::Matrix3d> out(in.size());
  symLogBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], symLog(in[i])), kBatchVsScalarTol) << "element " << i;
  }
  in[in.size() / 2] = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  EXPECT_THROW(symLogBatch(in.data(), out.data(), in.size()), DomainError);
}

std::vector<AffineParams> phiInputs(std::mt19937& rng) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.2, -1.0).normalized();
  const double small = so3_detail::kSmallAngle;
  std::vector<AffineParams> in;
  // Rotation angles on both sides of kSmallAngle, through pi and past 2 pi
  // (20-30 rad), and beyond the lanes' sin/cos range (scalar path).
  for (double theta : {0.0, 0.5 * small, 2.0 * small, kPi, 2.0 * kPi, 20.0, 30.0, 3e5}) {
    in.push_back({Eigen::Vector3d(1.0, 2.0, 3.0), theta * axis, randomSymmetric(rng, 1.0)});
  }
  in.push_back(
      {Eigen::Vector3d::Zero(), axis, withEigenvalues(rng, Eigen::Vector3d(1.0, 1.0, 0.2))});
  for (int i = 0; i < kRandomCount; ++i) {
    const Eigen::Vector3d t(test_seed::uniform(rng, -1, 1), test_seed::uniform(rng, -1, 1),
                            test_seed::uniform(rng, -1, 1));
    in.push_back({t, so3Log(randomRotation(rng, kPi)), randomSymmetric(rng, 1.0)});
  }
  return in;
}

TEST(BatchKernels, PhiMatchesScalar) {
  std::mt19937 rng(seed("PhiMatchesScalar"));
  const std::vector<AffineParams> in = phiInputs(rng);
  std::vector<Eigen::Matrix4d> out(in.size());
  phiBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], phi(in[i])), kBatchVsScalarTol) << "element " << i;
  }
}

TEST(BatchKernels, PhiLinearMatchesScalar) {
  std::mt19937 rng(seed("PhiLinearMatchesScalar"));
  const std::vector<AffineParams> in = phiInputs(rng);
  std::vector<double> logs;
  for (const AffineParams& p : in) {
    const Eigen::Matrix3d& y = p.stretchLog;
    for (double v : {p.rotationLog(0), p.rotationLog(1), p.rotationLog(2), y(0, 0), y(0, 1),
                     y(0, 2), y(1, 1), y(1, 2), y(2, 2)}) {
      logs.push_back(v);
    }
  }
  std::vector<Eigen::Matrix3d> out(in.size());
  phiLinearBatch(logs.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Eigen::Matrix3d want = phi(in[i]).topLeftCorner<3, 3>();
    EXPECT_LE(relativeGap(out[i], want), kBatchVsScalarTol) << "element " << i;
  }
}

void expectParamsClose(const AffineParams& got, const AffineParams& want, std::size_t i) {
  EXPECT_EQ(got.translation, want.translation) << "element " << i;
  EXPECT_LE(relativeGap(got.rotationLog, want.rotationLog), kBatchVsScalarTol) << "element " << i;
  EXPECT_LE(relativeGap(got.stretchLog, want.stretchLog), kBatchVsScalarTol) << "element " << i;
}

/// 4x4 homogeneous map with the given linear part and a fixed translation.
Eigen::Matrix4d affine(const Eigen::Matrix3d& linear) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a.topLeftCorner<3, 3>() = linear;
  a.topRightCorner<3, 1>() << 0.5, -1.0, 2.0;
  return a;
}

std::vector<Eigen::Matrix4d> psiInputs(std::mt19937& rng) {
  const double maxCond = polar_detail::kClosedFormMaxCond;
  std::vector<Eigen::Matrix4d> in = {Eigen::Matrix4d::Identity(),
                                     affine(2.0 * randomRotation(rng, kPi))};
  // Coincident and near-coincident singular values, a rotation by pi, cond(A)
  // on both sides of the closed-form limit (above: Newton in the scalar psi).
  const Eigen::Matrix3d r = randomRotation(rng, kPi);
  for (const Eigen::Vector3d& sigma :
       {Eigen::Vector3d(2.0, 2.0, 1.0), Eigen::Vector3d(1.0, 1.0 + 1e-9, 1.0 - 1e-9),
        Eigen::Vector3d(0.9 * maxCond, 1.0, 1.0), Eigen::Vector3d(1.1 * maxCond, 1.0, 1.0),
        Eigen::Vector3d(1e8, 1.0, 1.0)}) {
    in.push_back(affine(r * withEigenvalues(rng, sigma)));
  }
  in.push_back(affine(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal()));
  in.push_back(affine(so3Exp((kPi - 1e-9) * Eigen::Vector3d(0.6, 0.8, 0.0)) *
                      withEigenvalues(rng, Eigen::Vector3d(3.0, 1.0, 0.5))));
  for (int i = 0; i < kRandomCount; ++i) {
    in.push_back(affine(randomRotation(rng, kPi) * symExp(randomSymmetric(rng, 1.0))));
  }
  return in;
}

TEST(BatchKernels, PsiMatchesScalarAndThrowsLikeIt) {
  std::mt19937 rng(seed("PsiMatchesScalarAndThrowsLikeIt"));
  std::vector<Eigen::Matrix4d> in = psiInputs(rng);
  std::vector<AffineParams> out(in.size());
  psiBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) expectParamsClose(out[i], psi(in[i]), i);
  in[in.size() - 3] = affine(Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal());
  EXPECT_THROW(psiBatch(in.data(), out.data(), in.size()), DomainError);
}

TEST(BatchKernels, PolarDecomposeLogMatchesScalarAndThrowsLikeIt) {
  std::mt19937 rng(seed("PolarDecomposeLogMatchesScalarAndThrowsLikeIt"));
  std::vector<Eigen::Matrix3d> in;
  for (const Eigen::Matrix4d& a : psiInputs(rng)) in.push_back(a.topLeftCorner<3, 3>());
  std::vector<PolarLogDecomposition> out(in.size());
  polarDecomposeLogBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const PolarLogDecomposition want = polarDecomposeLog(in[i]);
    EXPECT_LE(relativeGap(out[i].rotation, want.rotation), kBatchVsScalarTol) << "element " << i;
    EXPECT_LE(relativeGap(out[i].stretchLog, want.stretchLog), kBatchVsScalarTol)
        << "element " << i;
  }
  in[in.size() - 3] = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  EXPECT_THROW(polarDecomposeLogBatch(in.data(), out.data(), in.size()), DomainError);
}

/// The polar rotation's forward error per unit of relative backward error:
/// perturbing A by dA moves R by about |dA| / (sigma_2 + sigma_3) (Higham,
/// Functions of Matrices, Thm. 8.9), i.e. cond(A) / 2 relative; the SVD
/// oracle and the lanes each carry a backward error of a few ulps.
constexpr double kRotationUlpsPerCond = 16 * 2.220446049250313e-16;

TEST(BatchKernels, PolarRotationMatchesScalarAndAnSvdAndThrowsLikeIt) {
  std::mt19937 rng(seed("PolarRotationMatchesScalarAndAnSvdAndThrowsLikeIt"));
  std::vector<Eigen::Matrix3d> in;
  for (const Eigen::Matrix4d& a : psiInputs(rng)) in.push_back(a.topLeftCorner<3, 3>());
  // det outside [kUnscaledMinDet, kUnscaledMaxDet]: the scalar kernel rescales.
  in.push_back(1e-40 * randomRotation(rng, kPi));
  in.push_back(1e40 * randomRotation(rng, kPi) * withEigenvalues(rng, {2.0, 1.0, 0.5}));
  std::vector<Eigen::Matrix3d> out(in.size());
  polarRotationBatch(in.data(), out.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LE(relativeGap(out[i], polarDecompose(in[i]).rotation), kBatchVsScalarTol)
        << "element " << i;
    // Independent oracle: U V^T of Eigen's Jacobi SVD (det A > 0 here, so no
    // reflection to remove).
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(in[i], Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma = svd.singularValues();
    const Eigen::Matrix3d want = svd.matrixU() * svd.matrixV().transpose();
    EXPECT_LE((out[i] - want).norm(),
              kBatchVsScalarTol + kRotationUlpsPerCond * sigma(0) / sigma(2))
        << "element " << i;
    EXPECT_LE((out[i].transpose() * out[i] - Eigen::Matrix3d::Identity()).norm(), kBatchVsScalarTol)
        << "element " << i;
  }
  in[in.size() - 3] = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  EXPECT_THROW(polarRotationBatch(in.data(), out.data(), in.size()), DomainError);
}

/// kBatchVsScalarTol plus the relative error exp makes of the rounding of its
/// argument, a few ulps of the largest |eigenvalue| (lanes and libm round
/// eigenvalues near 700 differently).
double extremeTol(const Eigen::Matrix3d& y) {
  constexpr double kExpArgumentUlps = 4 * 2.220446049250313e-16;
  const double largest = symEigenvalues(y).cwiseAbs().maxCoeff();
  return kBatchVsScalarTol + kExpArgumentUlps * (std::isfinite(largest) ? largest : 0.0);
}

TEST(BatchKernels, ExtremeSpreadsAndScalesMatchScalar) {
  // Issue 14: inputs outside the closed forms' ranges (eigenvalue spread or
  // |eigenvalue| beyond kExpDirectMaxArg, det or diagonal outside the
  // unscaled ranges) are handed to the scalar kernels, which return finite
  // results; batched and scalar agree element by element, and overflow throws
  // from both.
  std::mt19937 rng(seed("ExtremeSpreadsAndScalesMatchScalar"));
  const double m = sym3_detail::kExpDirectMaxArg;
  std::vector<Eigen::Matrix3d> y = {Eigen::Vector3d(356, -356, -356).asDiagonal()};
  for (const Eigen::Vector3d& mu :
       {Eigen::Vector3d(356, -356, -356), Eigen::Vector3d(0.999 * m, 0, -0.5),
        Eigen::Vector3d(1.001 * m, 0, -0.5), Eigen::Vector3d(0.3, 0.0, -1.001 * m),
        Eigen::Vector3d(1.0, 0.0, -1e6)}) {
    y.push_back(withEigenvalues(rng, mu));
  }
  for (int i = 0; i < 100; ++i) y.push_back(randomSymmetric(rng, 1.0));
  std::vector<Eigen::Matrix3d> e(y.size());
  symExpBatch(y.data(), e.data(), y.size());
  std::vector<AffineParams> params;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ASSERT_TRUE(e[i].allFinite()) << "element " << i;
    EXPECT_LE(relativeGap(e[i], symExp(y[i])), extremeTol(y[i])) << "element " << i;
    // Every other rotation log beyond the double range of its square.
    params.push_back(
        {Eigen::Vector3d::Zero(), Eigen::Vector3d(i % 2 ? 1e155 : 0.5, 0.0, 0.0), y[i]});
  }
  std::vector<Eigen::Matrix4d> a(params.size());
  phiBatch(params.data(), a.data(), params.size());
  for (std::size_t i = 0; i < params.size(); ++i) {
    ASSERT_TRUE(a[i].allFinite()) << "element " << i;
    EXPECT_LE(relativeGap(a[i], phi(params[i])), extremeTol(y[i])) << "element " << i;
  }
  y[y.size() / 2] = Eigen::Vector3d(720, 0, 0).asDiagonal();
  EXPECT_THROW(symExpBatch(y.data(), e.data(), y.size()), DomainError);

  // Scaled matrices: det(c A) far outside the unscaled range for the outer
  // scales, inside it for c near 1.
  std::vector<Eigen::Matrix3d> linear;
  std::vector<Eigen::Matrix3d> stretch;
  for (int j = -300; j <= 300; j += 25) {
    const double c = std::pow(10.0, j);
    linear.push_back(c * withEigenvalues(rng, Eigen::Vector3d(3.0, 1.0, 1.0)));
    linear.push_back(c * randomRotation(rng, kPi) *
                     withEigenvalues(rng, Eigen::Vector3d(2, 1, 0.1)));
    stretch.push_back(c * withEigenvalues(rng, Eigen::Vector3d(3.0, 1.0, 0.5)));
  }
  linear.push_back(Eigen::Vector3d(1.0, 1.0, 1e-310).asDiagonal());
  std::vector<PolarLogDecomposition> polar(linear.size());
  polarDecomposeLogBatch(linear.data(), polar.data(), linear.size());
  std::vector<Eigen::Matrix4d> homogeneous;
  for (std::size_t i = 0; i < linear.size(); ++i) {
    const PolarLogDecomposition want = polarDecomposeLog(linear[i]);
    EXPECT_LE(relativeGap(polar[i].rotation, want.rotation), kBatchVsScalarTol) << "element " << i;
    EXPECT_LE(relativeGap(polar[i].stretchLog, want.stretchLog), kBatchVsScalarTol)
        << "element " << i;
    homogeneous.push_back(affine(linear[i]));
  }
  std::vector<AffineParams> out(homogeneous.size());
  psiBatch(homogeneous.data(), out.data(), homogeneous.size());
  for (std::size_t i = 0; i < homogeneous.size(); ++i) {
    expectParamsClose(out[i], psi(homogeneous[i]), i);
  }
  std::vector<Eigen::Matrix3d> logs(stretch.size());
  symLogBatch(stretch.data(), logs.data(), stretch.size());
  for (std::size_t i = 0; i < stretch.size(); ++i) {
    EXPECT_LE(relativeGap(logs[i], symLog(stretch[i])), kBatchVsScalarTol) << "element " << i;
  }
}

TEST(BatchKernels, PhiPsiRoundTripByConditionBand) {
  std::mt19937 rng(seed("PhiPsiRoundTripByConditionBand"));
  std::vector<Eigen::Matrix4d> in;
  std::vector<double> tol;
  for (double cond : {1.0, 10.0, 1e2, 1e3, 1e4, 1e6, 1e8}) {
    for (int i = 0; i < 200; ++i) {
      const double scale = std::exp(test_seed::uniform(rng, -std::log(1e6), std::log(1e6)));
      Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
      a.topLeftCorner<3, 3>() = core_test::randomMatrixWithCond(rng, cond, scale);
      a.topRightCorner<3, 1>() = scale * core_test::randomUniform<3, 1>(rng);
      in.push_back(a);
      tol.push_back(cond <= 1e2   ? kRoundTripTolCond1e2
                    : cond <= 1e4 ? kRoundTripTolCond1e4
                                  : kRoundTripTolCond1e8);
    }
  }
  std::vector<AffineParams> params(in.size());
  std::vector<Eigen::Matrix4d> back(in.size());
  psiBatch(in.data(), params.data(), in.size());
  phiBatch(params.data(), back.data(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    ASSERT_TRUE(back[i].allFinite()) << "element " << i;
    EXPECT_LE(core_test::relativeError(back[i].topLeftCorner<3, 3>(), in[i].topLeftCorner<3, 3>()),
              tol[i])
        << "element " << i;
    EXPECT_TRUE((back[i].topRightCorner<3, 1>() == in[i].topRightCorner<3, 1>()))
        << "element " << i;
  }
}

TEST(BatchKernels, EmptyAndSingleElementCalls) {
  std::vector<Eigen::Matrix4d> in = {Eigen::Matrix4d::Identity()};
  std::vector<AffineParams> out(1);
  psiBatch(in.data(), out.data(), 0);
  psiBatch(in.data(), out.data(), 1);
  expectParamsClose(out[0], psi(in[0]), 0);
}

}  // namespace
}  // namespace tetblend
