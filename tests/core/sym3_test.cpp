#include "tetblend/core/sym3.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <limits>
#include <vector>

#include "core_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::randomRotation;
using core_test::relativeError;
using core_test::spdWithEigenvalues;
using core_test::testSeed;
using core_test::uniform;

// exp/log of unit-scale symmetric matrices: a few ulps per unit of eigenvalue
// spread (the Cayley–Hamilton quadratic grows like the spread); ~36 eps.
constexpr double kTolPerSpread = 8e-15;
// Eigenvalues by the cubic formula, absolute, relative to the spectral radius:
// a few ulps when distinct; a (near-)double root is split with an error of
// order sqrt(eps) (the deflated pair sqrt(3 (2 - x)(2 + x)) near x = 2), which
// exp/log do not feel (second order).
constexpr double kEigenvalueTol = 1e-14;
constexpr double kDoubleEigenvalueTol = 1e-7;
// symLog of a matrix built as V diag(mu) V^T (|log mu| up to 5 + spread h)
// against the construction's log: the build rounds s by a few ulps of its
// largest eigenvalue, which the log amplifies by up to cond = e^h; per unit
// of spread, 2.5 times kTolPerSpread since the build's own rounding counts.
constexpr double kBuiltLogTolPerSpread = 2e-14;

/// V diag(f(mu)) V^T from the construction: an oracle independent of the code.
struct SymCase {
  Eigen::Matrix3d v;
  Eigen::Vector3d mu;
  Eigen::Matrix3d matrix() const { return v * mu.asDiagonal() * v.transpose(); }
  Eigen::Matrix3d exp() const { return v * mu.array().exp().matrix().asDiagonal() * v.transpose(); }
  Eigen::Matrix3d log() const { return v * mu.array().log().matrix().asDiagonal() * v.transpose(); }
};

/// Fixed hard spectra of Y (for exp) / log S (for log): zero, all equal,
/// coincident pairs, near-coincident on both sides of the series switches,
/// moderately and widely spread.
std::vector<Eigen::Vector3d> hardLogSpectra() {
  const double se = sym3_detail::kExpSeriesSpread;
  return {Eigen::Vector3d(0, 0, 0),
          Eigen::Vector3d(0.7, 0.7, 0.7),
          Eigen::Vector3d(1, 1, -2),
          Eigen::Vector3d(2, -1, -1),
          Eigen::Vector3d(1e-9, 0, -1e-9),
          Eigen::Vector3d(0.99 * se, 0.3 * se, 0),
          Eigen::Vector3d(1.01 * se, 0.3 * se, 0),
          Eigen::Vector3d(0.5, 0.5 + 1e-7, -0.2),
          Eigen::Vector3d(3, -1, 0.5),
          Eigen::Vector3d(9.2, 0, -9.2),
          Eigen::Vector3d(-18.4, 0, 0)};
}

double spread(const Eigen::Vector3d& v) { return v.maxCoeff() - v.minCoeff(); }

TEST(Sym3, EigenvaluesMatchEigenSolver) {
  std::mt19937 rng(testSeed("Sym3.EigenvaluesMatchEigenSolver"));
  for (int i = 0; i < 500; ++i) {
    Eigen::Vector3d mu(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
    if (i % 3 == 0) mu(1) = mu(0);  // coincident pair
    if (i % 3 != 0 && (std::abs(mu(0) - mu(1)) < 0.1 || std::abs(mu(1) - mu(2)) < 0.1 ||
                       std::abs(mu(0) - mu(2)) < 0.1)) {
      continue;  // near-coincident pairs are covered by the i % 3 == 0 cases
    }
    const Eigen::Matrix3d y = spdWithEigenvalues(rng, mu);
    const Eigen::Vector3d oracle =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(y, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .reverse();
    const Eigen::Vector3d lambda = symEigenvalues(y);
    const double tol = i % 3 == 0 ? kDoubleEigenvalueTol : kEigenvalueTol;
    ASSERT_LE((lambda - oracle).cwiseAbs().maxCoeff(), tol * (1 + y.norm())) << mu.transpose();
    ASSERT_NEAR(lambda.sum(), y.trace(), kEigenvalueTol * (1 + y.norm()));
  }
  EXPECT_EQ(symEigenvalues(2.0 * Eigen::Matrix3d::Identity()), Eigen::Vector3d(2, 2, 2));
}

TEST(Sym3, EigenvaluesSeamlessAcrossCubicRootSwitch) {
  // symEigenvalues solves for the largest root of the normalised cubic when
  // det(Y - tr(Y)/3 I) >= 0 and for the smallest when it is < 0: spectra
  // (1, t, -1) sit on either side of that switch as t changes sign.
  std::mt19937 rng(testSeed("Sym3.EigenvaluesSeamlessAcrossCubicRootSwitch"));
  int positive = 0, negative = 0;
  for (const double t : {-0.3, -1e-3, -1e-12, 0.0, 1e-12, 1e-3, 0.3}) {
    const Eigen::Matrix3d y = spdWithEigenvalues(rng, Eigen::Vector3d(1.0, t, -1.0));
    const double det = (y - y.trace() / 3.0 * Eigen::Matrix3d::Identity()).determinant();
    positive += det > 0.0;
    negative += det < 0.0;
    const Eigen::Vector3d oracle =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(y, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .reverse();
    EXPECT_LE((symEigenvalues(y) - oracle).cwiseAbs().maxCoeff(), kEigenvalueTol * (1 + y.norm()))
        << "t = " << t;
    const Eigen::Matrix3d expOracle = expm(y);
    EXPECT_LE(relativeError(symExp(y), expOracle), kTolPerSpread * (1 + spread(oracle)))
        << "t = " << t;
  }
  EXPECT_GT(positive, 0);
  EXPECT_GT(negative, 0);
}

TEST(Sym3, ExpMatchesOraclesOnHardSpectra) {
  std::mt19937 rng(testSeed("Sym3.ExpMatchesOraclesOnHardSpectra"));
  for (const Eigen::Vector3d& mu : hardLogSpectra()) {
    const SymCase c{randomRotation(rng), mu};
    const Eigen::Matrix3d y = 0.5 * (c.matrix() + c.matrix().transpose());
    SCOPED_TRACE(testing::Message() << "eigenvalues " << mu.transpose());
    const double tol = kTolPerSpread * (1.0 + spread(mu));
    EXPECT_LE(relativeError(symExp(y), c.exp()), tol);
    EXPECT_LE(relativeError(symExp(y), expm(y)), tol);
  }
}

TEST(Sym3, ExpSeriesSwitchIsSeamless) {
  // Eigenvalue spread just below and just above kExpSeriesSpread, with the
  // spread along several directions: both branches agree with the oracle.
  std::mt19937 rng(testSeed("Sym3.ExpSeriesSwitchIsSeamless"));
  for (double factor : {0.999, 1.001, 0.5, 2.0}) {
    for (int i = 0; i < 50; ++i) {
      const double h = factor * sym3_detail::kExpSeriesSpread;
      const double t = uniform(rng, 0.0, 1.0);
      const Eigen::Vector3d mu(h * t, 0.0, -h * (1 - t));
      const SymCase c{randomRotation(rng), mu + Eigen::Vector3d::Constant(uniform(rng, -2, 2))};
      const Eigen::Matrix3d y = c.matrix();
      ASSERT_LE(relativeError(symExp(0.5 * (y + y.transpose())), c.exp()), kTolPerSpread);
    }
  }
}

TEST(Sym3, LogMatchesOraclesOnHardSpectra) {
  std::mt19937 rng(testSeed("Sym3.LogMatchesOraclesOnHardSpectra"));
  for (const Eigen::Vector3d& logMu : hardLogSpectra()) {
    const SymCase c{randomRotation(rng), logMu.array().exp()};
    const Eigen::Matrix3d s = 0.5 * (c.matrix() + c.matrix().transpose());
    SCOPED_TRACE(testing::Message() << "log eigenvalues " << logMu.transpose());
    // Log is well-conditioned in absolute terms relative to 1 + |log S|, with
    // a condition of order cond(S) for the construction round-off of S.
    const double cond = std::exp(spread(logMu));
    const double tol = kTolPerSpread * (1.0 + spread(logMu)) * cond;
    const Eigen::Matrix3d log = symLog(s);
    EXPECT_LE((log - c.log()).norm() / (1.0 + c.log().norm()), tol);
    EXPECT_LE(relativeError(symExp(log), s), kTolPerSpread * (1.0 + spread(logMu)));
  }
}

TEST(Sym3, LogSwitchesAreSeamless) {
  // Both sides of kLogSeriesSpread (relative spread) and of
  // kLogClosedFormMaxCond (closed form vs eigen-decomposition).
  std::mt19937 rng(testSeed("Sym3.LogSwitchesAreSeamless"));
  const double hs = sym3_detail::kLogSeriesSpread;
  const double hc = std::log(sym3_detail::kLogClosedFormMaxCond);
  for (double h : {0.999 * hs, 1.001 * hs, 0.999 * hc, 1.001 * hc}) {
    for (int i = 0; i < 50; ++i) {
      const double t = uniform(rng, 0.0, 1.0);
      const double scale = uniform(rng, -5, 5);
      const Eigen::Vector3d logMu = Eigen::Vector3d(h * t, 0.0, -h * (1 - t)).array() + scale;
      const SymCase c{randomRotation(rng), logMu.array().exp()};
      const Eigen::Matrix3d s = 0.5 * (c.matrix() + c.matrix().transpose());
      const Eigen::Matrix3d log = symLog(s);
      ASSERT_LE((log - c.log()).norm() / (1.0 + c.log().norm()),
                kBuiltLogTolPerSpread * (1.0 + h) * std::exp(h))
          << "spread " << h;
      ASSERT_LE(relativeError(symExp(log), s), kTolPerSpread * (1.0 + h)) << "spread " << h;
    }
  }
}

TEST(Sym3, RandomSamplesAgainstMatrixFunctions) {
  std::mt19937 rng(testSeed("Sym3.RandomSamplesAgainstMatrixFunctions"));
  for (int i = 0; i < 500; ++i) {
    Eigen::Matrix3d y;
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) y(r, c) = y(c, r) = uniform(rng, -2, 2);
    const Eigen::Matrix3d e = symExp(y);
    const double h = spread(symEigenvalues(y));
    ASSERT_LE(relativeError(e, expm(y)), kTolPerSpread * (1 + h)) << y;
    ASSERT_LE((symLog(e) - y).norm() / (1 + y.norm()), kTolPerSpread * (1 + h) * std::exp(h)) << y;
  }
}

TEST(Sym3, ExpOfLogForConditionUpTo1e8) {
  // Exp(log S) = S, errors relative to |S|, for widely spread stretches.
  std::mt19937 rng(testSeed("Sym3.ExpOfLogForConditionUpTo1e8"));
  constexpr double kWideTol = 1e-13;  // ~450 eps: the spread log(1e8) ~ 18
  for (double cond : {1e2, 1e4, 1e6, 1e8, 1e10}) {
    for (int i = 0; i < 50; ++i) {
      const double mid = std::exp(uniform(rng, -std::log(cond), 0.0));
      const Eigen::Matrix3d s = spdWithEigenvalues(rng, Eigen::Vector3d(1.0, mid, 1.0 / cond));
      const Eigen::Matrix3d log = symLog(s);
      ASSERT_TRUE(log.allFinite());
      ASSERT_LE(relativeError(symExp(log), s), kWideTol) << "cond " << cond;
    }
  }
}

TEST(Sym3, LogRejectsNonPositiveDefinite) {
  EXPECT_THROW(symLog(Eigen::Vector3d(1, 2, -1).asDiagonal().toDenseMatrix()), DomainError);
  EXPECT_THROW(symLog(Eigen::Vector3d(1, 0, 1).asDiagonal().toDenseMatrix()), DomainError);
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 2) = nan(2, 1) = std::nan("");
  EXPECT_THROW(symLog(nan), DomainError);
}

TEST(Sym3, ExpOfWideSpreadIsFinite) {
  // Regression (issue 14): symExp(diag(356, -356, -356)) returned NaN
  // (expm1 of the spread 712 overflowed) although exp(Y) ~ 4e154 is finite.
  const Eigen::Vector3d mu(356, -356, -356);
  const Eigen::Matrix3d diag = symExp(mu.asDiagonal().toDenseMatrix());
  EXPECT_LE(relativeError(diag, mu.array().exp().matrix().asDiagonal().toDenseMatrix()),
            kTolPerSpread);
  // Rotated, and both sides of kExpDirectMaxArg (for the spread and for the
  // largest |eigenvalue|), against the construction.
  const double m = sym3_detail::kExpDirectMaxArg;
  std::mt19937 rng(testSeed("Sym3.ExpOfWideSpreadIsFinite"));
  for (const Eigen::Vector3d& spectrum :
       {mu, Eigen::Vector3d(356, 0, -356), Eigen::Vector3d(0.999 * m, 0, -0.5),
        Eigen::Vector3d(1.001 * m, 0, -0.5), Eigen::Vector3d(0.5, 0, -0.999 * m),
        Eigen::Vector3d(0.5, 0, -1.001 * m), Eigen::Vector3d(705, 704, 700),
        Eigen::Vector3d(-701, -705, -706), Eigen::Vector3d(1.0, 0.0, -1e6)}) {
    const SymCase c{randomRotation(rng), spectrum};
    const Eigen::Matrix3d y = 0.5 * (c.matrix() + c.matrix().transpose());
    const Eigen::Matrix3d e = symExp(y);
    SCOPED_TRACE(testing::Message() << "eigenvalues " << spectrum.transpose());
    ASSERT_TRUE(e.allFinite());
    // The construction's round-off in Y is ~eps |Y|, which exp turns into a
    // relative error of the same size: the spread bound plus |Y|.
    const double size = spread(spectrum) + spectrum.cwiseAbs().maxCoeff();
    EXPECT_LE(relativeError(e, c.exp()), kTolPerSpread * (1.0 + size));
  }
  // Entries far beyond the cubic's range (its p^2 overflows).
  const Eigen::Vector3d huge(1.0, 1.0, -1e300);
  EXPECT_LE(relativeError(symExp(huge.asDiagonal().toDenseMatrix()),
                          huge.array().exp().matrix().asDiagonal().toDenseMatrix()),
            kTolPerSpread);
}

TEST(Sym3, ExpOnBothSidesOfTheDirectSpreadIsAccurate) {
  // Just below sym3_detail::kExpDirectMaxSpread the closed form (its error
  // grows to ~10 ulps per unit of spread there), just above the
  // eigen-decomposition (~6 ulps per unit of |Y|), and far above it, where
  // the closed form had reached 40 ulps per unit (seeds 42 and 99991 of
  // ExpOfWideSpreadIsFinite): against the construction, within the suite's
  // bound per unit of spread and size.
  const double limit = sym3_detail::kExpDirectMaxSpread;
  std::mt19937 rng(testSeed("Sym3.ExpOnBothSidesOfTheDirectSpreadIsAccurate"));
  for (const double spreadValue : {0.99 * limit, 1.01 * limit, 3.0 * limit, 6.99 * limit}) {
    for (int i = 0; i < 200; ++i) {
      const double middle = uniform(rng, -0.5, 0.5) * spreadValue;
      const Eigen::Vector3d spectrum(0.5 * spreadValue, middle, -0.5 * spreadValue);
      const SymCase c{randomRotation(rng), spectrum};
      const Eigen::Matrix3d y = 0.5 * (c.matrix() + c.matrix().transpose());
      const double size = spread(spectrum) + spectrum.cwiseAbs().maxCoeff();
      ASSERT_LE(relativeError(symExp(y), c.exp()), kTolPerSpread * (1.0 + size))
          << "eigenvalues " << spectrum.transpose();
    }
  }
}

TEST(Sym3, ExpNearOverflowIsFiniteAndAboveItThrows) {
  // e^710.5 overflows double but exp(710.5 u u^T) = I + (e^710.5 - 1) u u^T,
  // u = (1, 1, 1)/sqrt 3, has entries ~1.2e308: finite, so returned.
  const Eigen::Matrix3d y = Eigen::Matrix3d::Constant(710.5 / 3.0);
  const Eigen::Matrix3d e = symExp(y);
  ASSERT_TRUE(e.allFinite());
  const double entry = std::exp(710.5 - std::log(3.0));
  Eigen::Matrix3d oracle = Eigen::Matrix3d::Constant(entry);
  oracle.diagonal().array() += 1.0;
  EXPECT_LE(relativeError(e, oracle), kTolPerSpread * 710.5);
  // A true result beyond the double range raises, naming the eigenvalue.
  for (const double top : {710.0, 720.0, 1e300}) {
    try {
      symExp(Eigen::Vector3d(top, 0, -1).asDiagonal().toDenseMatrix());
      ADD_FAILURE() << "no error for eigenvalue " << top;
    } catch (const DomainError& error) {
      EXPECT_NE(std::string(error.what()).find("largest eigenvalue"), std::string::npos)
          << error.what();
    }
  }
  EXPECT_THROW(symExp(Eigen::Matrix3d::Constant(std::numeric_limits<double>::infinity())),
               DomainError);
}

TEST(Sym3, LogHandlesConditionUpTo1e15) {
  // Regression (issue 14): symLog refused 11% of positive definite matrices
  // at cond 1e16 (double eigenvalues of either sign). At cond 1e15 every
  // sample is accepted and matches Eigen's solver run in long double on the
  // same (rounded) matrix. The smallest eigenvalue of the stored matrix is
  // determined to ~eps_ld cond ~ 1e-4 relative by either long double method,
  // so its log agrees to that, absolutely; a 10x margin.
  constexpr double kLongDoubleLogTol = 1e-3;
  using Matrix3ld = Eigen::Matrix<long double, 3, 3>;
  std::mt19937 rng(testSeed("Sym3.LogHandlesConditionUpTo1e15"));
  for (const double cond : {1e9, 1e12, 1e15}) {
    for (int i = 0; i < 200; ++i) {
      const double mid = std::exp(uniform(rng, -std::log(cond), 0.0));
      const Eigen::Matrix3d s = spdWithEigenvalues(rng, Eigen::Vector3d(1.0, mid, 1.0 / cond));
      const Eigen::SelfAdjointEigenSolver<Matrix3ld> es(s.cast<long double>());
      ASSERT_GT(es.eigenvalues()(0), 0.0L) << "the stored matrix is not positive definite";
      const Matrix3ld oracle = es.eigenvectors() *
                               es.eigenvalues().array().log().matrix().asDiagonal() *
                               es.eigenvectors().transpose();
      Eigen::Matrix3d log;
      ASSERT_NO_THROW(log = symLog(s)) << "cond " << cond << "\n" << s;
      ASSERT_LE((log - oracle.cast<double>()).norm(), kLongDoubleLogTol) << "cond " << cond;
      const double h = std::log(cond);
      ASSERT_LE(relativeError(symExp(log), s), kTolPerSpread * (1.0 + h)) << "cond " << cond;
    }
  }
}

TEST(Sym3, LogIsExactAtEveryScale) {
  // log(c S) = log(S) + log(c) I for any c the double range holds (S is
  // rescaled by a power of two first). Absolute error: a few ulps of
  // |log c| <= 709 (ulp 1.1e-13), on top of the unit-scale tolerance.
  constexpr double kLogUlpsOfScale = 8 * std::numeric_limits<double>::epsilon();
  std::mt19937 rng(testSeed("Sym3.LogIsExactAtEveryScale"));
  for (int i = 0; i < 5; ++i) {
    const double mid = std::exp(uniform(rng, -std::log(1e2), 0.0));
    const Eigen::Matrix3d s = spdWithEigenvalues(rng, Eigen::Vector3d(1.0, mid, 1e-2));
    const Eigen::Matrix3d log = symLog(s);
    for (int j = -300; j <= 300; j += 10) {
      const double c = std::pow(10.0, j);
      Eigen::Matrix3d expected = log;
      expected.diagonal().array() += std::log(c);
      const double tol =
          kTolPerSpread * (1.0 + std::log(1e2)) * 1e2 + kLogUlpsOfScale * std::abs(std::log(c));
      ASSERT_LE((symLog(c * s) - expected).norm(), tol) << "c = " << c;
    }
  }
  // Subnormal entries: the smallest positive double on the diagonal.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const Eigen::Matrix3d t = symLog(Eigen::Vector3d(tiny, 2 * tiny, 4 * tiny).asDiagonal());
  EXPECT_NEAR(t(0, 0), std::log(tiny), kLogUlpsOfScale * 745);
  EXPECT_NEAR(t(2, 2), std::log(tiny) + std::log(4.0), kLogUlpsOfScale * 745);
}

}  // namespace
}  // namespace tetblend
