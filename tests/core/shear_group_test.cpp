#include "tetblend/core/shear_group.h"

#include <gtest/gtest.h>

#include <vector>

#include "lie_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using lie_test::randomShear;
using lie_test::randomShearAlgebra;
using lie_test::testSeed;

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Closed forms against Eigen's MatrixFunctions (Pade + scaling and squaring for
// exp, Schur-Parlett + inverse scaling and squaring for log): both sides are
// accurate to a few hundred ulps of the result's norm for unit-scale inputs
// (entries up to ~e^5 here), so 1e-13 relative leaves a margin of ~2x.
constexpr double kOracleTol = 1e-13;
// Exact group identities (inverse, one-parameter subgroup, round trips):
// a few dozen roundings of unit-scale quantities.
constexpr double kRoundTripTol = 1e-13;
// The paper's literal case formulas (App. A.2.3/A.2.4) at their exact cases:
// the general-case formula divides by differences like (a2 - a5), which costs
// at most ~1/|a2 - a5| ~ 10 times the round-off for the inputs used here.
constexpr double kPaperTol = 1e-12;
// Largest jump allowed across the series switch of f[x, y, z]: the
// difference quotient loses ~4 bits at the switch (see kShearSeriesSpread),
// the series is exact to round-off: 64 ulps.
constexpr double kSwitchJumpTol = 64 * kEps;

double relErr(const Eigen::Matrix3d& got, const Eigen::Matrix3d& want) {
  return (got - want).norm() / std::max(1.0, want.norm());
}

Eigen::Matrix3d algebra(double b1, double b2, double b3, double b4, double b5) {
  Eigen::Matrix3d x;
  x << 0, b1, b3, 0, b2, b4, 0, 0, b5;
  return x;
}

Eigen::Matrix3d group(double a1, double a2, double a3, double a4, double a5) {
  Eigen::Matrix3d a;
  a << 1, a1, a3, 0, a2, a4, 0, 0, a5;
  return a;
}

// Bansal & Tatu App. A.2.3, transcribed case by case (cases chosen by the
// caller, exact equalities only).
Eigen::Matrix3d paperExp(int paperCase, double b1, double b2, double b3, double b4, double b5) {
  const double e2 = std::exp(b2), e5 = std::exp(b5);
  switch (paperCase) {
    case 1:  // b2 = 0, b5 != 0
      return group(b1, 1.0,
                   (b1 * b4 * e5 + b3 * b5 * e5 - b1 * b4 * b5 - b1 * b4 - b3 * b5) / (b5 * b5),
                   b4 * (e5 - 1) / b5, e5);
    case 2:  // b5 = 0, b2 != 0
      return group(b1 * (e2 - 1) / b2, e2,
                   (b1 * b4 * e2 - b1 * (1 + b2) * b4 + b2 * b2 * b3) / (b2 * b2),
                   b4 * (e2 - 1) / b2, 1.0);
    case 3:  // b2 = b5 = 0
      return group(b1, 1.0, b3 + b1 * b4 / 2, b4, 1.0);
    case 4:  // b2 = b5 != 0
      return group(b1 * (e2 - 1) / b2, e2,
                   (((b1 * b4 + b3) * b2 - b1 * b4) * e2 + b1 * b4 - b2 * b3) / (b2 * b2), b4 * e2,
                   e2);
    default:  // general
      return group(b1 * (e2 - 1) / b2, e2,
                   (-b2 * (b1 * b4 - b2 * b3 + b3 * b5) * e5 + b1 * b4 * b5 * e2 +
                    (b2 - b5) * (b1 * b4 - b2 * b3)) /
                       (b2 * b5 * (b2 - b5)),
                   b4 * (e2 - e5) / (b2 - b5), e5);
  }
}

// Bansal & Tatu App. A.2.4, transcribed case by case.
Eigen::Matrix3d paperLog(int paperCase, double a1, double a2, double a3, double a4, double a5) {
  const double l2 = std::log(a2), l5 = std::log(a5);
  switch (paperCase) {
    case 1:  // a2 = 1, a5 != 1
      return algebra(a1, 0.0,
                     l5 * (a3 * a5 - a3 + a1 * a4) / ((a5 - 1) * (a5 - 1)) - a1 * a4 / (a5 - 1),
                     a4 * l5 / (a5 - 1), l5);
    case 2:  // a5 = 1, a2 != 1
      return algebra(a1 * l2 / (a2 - 1), l2,
                     a1 * a4 * l2 / ((a2 - 1) * (a2 - 1)) - (a3 - a2 * a3 + a1 * a4) / (a2 - 1),
                     a4 * l2 / (a2 - 1), 0.0);
    case 3:  // a2 = a5 = 1
      return algebra(a1, 0.0, a3 - a1 * a4 / 2, a4, 0.0);
    case 4:  // a2 = a5 != 1
      return algebra(
          a1 * l2 / (a2 - 1), l2,
          a3 * l2 / (a2 - 1) + a1 * a4 / (a2 * (a2 - 1)) - a1 * a4 * l2 / ((a2 - 1) * (a2 - 1)),
          a4 / a2, l2);
    default:  // general
      return algebra(a1 * l2 / (a2 - 1), l2,
                     a1 * a4 * l2 / ((a2 - a5) * (a2 - 1)) -
                         (a1 * a4 - a2 * a3 + a3 * a5) * l5 / ((a2 - a5) * (a5 - 1)),
                     a4 * (l2 - l5) / (a2 - a5), l5);
  }
}

struct DiagonalCase {
  int paperCase;
  double d2;  // b2 (exp) or log a2 (log)
  double d5;  // b5 (exp) or log a5 (log)
};

// One representative per case of App. A.2.3 (and, through a = e^b, A.2.4).
const std::vector<DiagonalCase> kExactCases = {
    {1, 0.0, 1.3}, {2, -0.8, 0.0}, {3, 0.0, 0.0}, {4, 0.7, 0.7}, {5, -0.6, 1.1}};

TEST(ShearGroup, ExpMatchesPaperAndOracleAtTheFiveCases) {
  const double b1 = 0.9, b3 = -1.7, b4 = 2.3;
  for (const DiagonalCase& c : kExactCases) {
    SCOPED_TRACE("paper case " + std::to_string(c.paperCase));
    const Eigen::Matrix3d x = algebra(b1, c.d2, b3, b4, c.d5);
    const Eigen::Matrix3d got = shearExp(x);
    EXPECT_LE(relErr(got, expm(x)), kOracleTol);
    EXPECT_LE(relErr(got, paperExp(c.paperCase, b1, c.d2, b3, b4, c.d5)), kPaperTol);
  }
}

TEST(ShearGroup, LogMatchesPaperAndOracleAtTheFiveCases) {
  const double a1 = -1.2, a3 = 0.4, a4 = 3.1;
  for (const DiagonalCase& c : kExactCases) {
    SCOPED_TRACE("paper case " + std::to_string(c.paperCase));
    const double a2 = std::exp(c.d2), a5 = std::exp(c.d5);
    const Eigen::Matrix3d a = group(a1, a2, a3, a4, a5);
    const Eigen::Matrix3d got = shearLog(a);
    EXPECT_LE(relErr(got, logm(a)), kOracleTol);
    EXPECT_LE(relErr(got, paperLog(c.paperCase, a1, a2, a3, a4, a5)), kPaperTol);
  }
}

// Offsets that put an input on both sides of each case switch: at it, just off
// it (round-off scale), well off it, and on both sides of the series switch.
std::vector<double> switchOffsets() {
  const double tau = kShearSeriesSpread;
  std::vector<double> out = {0.0};
  for (double d : {1e-300, 1e-15, 1e-11, 1e-7, 1e-4, 0.5 * tau * (1 - 1e-6), 0.5 * tau * (1 + 1e-6),
                   tau * (1 - 1e-6), tau * (1 + 1e-6), 0.5}) {
    out.push_back(d);
    out.push_back(-d);
  }
  return out;
}

// The diagonal (b2, b5) near each case of the paper, as a function of offset d.
std::vector<std::pair<std::string, Eigen::Vector2d>> nearCaseDiagonals(double d) {
  return {{"case 1: b2 -> 0", {d, 1.3}},
          {"case 2: b5 -> 0", {-0.8, d}},
          {"case 3: b2 = 0, b5 -> 0", {0.0, d}},
          {"case 3: b2 -> 0, b5 = 0", {d, 0.0}},
          {"case 3: b2 = d, b5 = 2d", {d, 2 * d}},
          {"case 3: b2 = d, b5 = -d", {d, -d}},
          {"case 4: b5 -> b2 = 0.7", {0.7, 0.7 + d}},
          {"case 4: b5 -> b2 = -1.9", {-1.9 + d, -1.9}}};
}

TEST(ShearGroup, ExpMatchesOracleOnBothSidesOfEverySwitch) {
  for (double d : switchOffsets()) {
    for (const auto& [name, diag] : nearCaseDiagonals(d)) {
      SCOPED_TRACE(name + ", offset " + std::to_string(d));
      const Eigen::Matrix3d x = algebra(-1.4, diag(0), 0.8, 1.9, diag(1));
      EXPECT_LE(relErr(shearExp(x), expm(x)), kOracleTol);
    }
  }
}

TEST(ShearGroup, LogMatchesOracleOnBothSidesOfEverySwitch) {
  for (double d : switchOffsets()) {
    for (const auto& [name, diag] : nearCaseDiagonals(d)) {
      SCOPED_TRACE(name + ", log-offset " + std::to_string(d));
      const Eigen::Matrix3d a = group(2.2, std::exp(diag(0)), -0.6, -1.3, std::exp(diag(1)));
      EXPECT_LE(relErr(shearLog(a), logm(a)), kOracleTol);
    }
  }
}

TEST(ShearGroup, DividedDifferencesMatchTheExponentialOfAJordanChain) {
  // f[x, y] and f[x, y, z] are the corner entries of exp of the bidiagonal
  // matrices with diagonal (x, y, z) and unit superdiagonal.
  const double tau = kShearSeriesSpread;
  std::vector<Eigen::Vector3d> nodes = {{0, 0, 0},           {0.3, 0.3, 0.3},   {0, 0, tau * 0.999},
                                        {0, 0, tau * 1.001}, {-2, 1e-9, 3},     {1, 1, -1},
                                        {-1, 1, 1},          {0, tau / 2, tau}, {5, -5, 0.1}};
  std::mt19937 rng(testSeed("DividedDifferencesMatchTheExponentialOfAJordanChain"));
  for (int i = 0; i < 200; ++i) {
    const double scale = std::pow(10.0, lie_test::uniform(rng, -8, 0.5));
    nodes.emplace_back(scale * lie_test::uniform(rng, -1, 1), scale * lie_test::uniform(rng, -1, 1),
                       scale * lie_test::uniform(rng, -1, 1));
  }
  for (const Eigen::Vector3d& n : nodes) {
    SCOPED_TRACE("nodes " + std::to_string(n(0)) + ", " + std::to_string(n(1)) + ", " +
                 std::to_string(n(2)));
    Eigen::Matrix3d j;
    j << n(0), 1, 0, 0, n(1), 1, 0, 0, n(2);
    const Eigen::Matrix3d e = expm(j);
    EXPECT_NEAR(expDividedDifference(n(0), n(1)), e(0, 1), kOracleTol * e(0, 1));
    EXPECT_NEAR(expDividedDifference(n(0), n(1), n(2)), e(0, 2), kOracleTol * e(0, 2));
  }
}

TEST(ShearGroup, SecondDividedDifferenceIsContinuousAtTheSeriesSwitch) {
  const double tau = kShearSeriesSpread;
  for (const Eigen::Vector3d& base :
       {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0.5, 1), Eigen::Vector3d(-1, 0, 0)}) {
    const Eigen::Vector3d below = base * tau * (1 - 4 * kEps);
    const Eigen::Vector3d above = base * tau * (1 + 4 * kEps);
    const double fb = expDividedDifference(below(0), below(1), below(2));
    const double fa = expDividedDifference(above(0), above(1), above(2));
    EXPECT_LE(std::abs(fa - fb), kSwitchJumpTol * fb);
  }
}

TEST(ShearGroup, RandomExpAndLogMatchOracleAndRoundTrip) {
  std::mt19937 rng(testSeed("RandomExpAndLogMatchOracleAndRoundTrip"));
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const Eigen::Matrix3d x = randomShearAlgebra(rng, 2.5);
    const Eigen::Matrix3d a = shearExp(x);
    EXPECT_LE(relErr(a, expm(x)), kOracleTol);
    EXPECT_LE(relErr(shearLog(a), x), kRoundTripTol * std::max(1.0, a.norm()));
    const Eigen::Matrix3d g = randomShear(rng, 2.5, 3.0);
    const Eigen::Matrix3d lg = shearLog(g);
    EXPECT_LE(relErr(lg, logm(g)), kOracleTol);
    EXPECT_LE(relErr(shearExp(lg), g), kRoundTripTol);
  }
}

TEST(ShearGroup, ExpIsAOneParameterSubgroupAndInverseIsExact) {
  std::mt19937 rng(testSeed("ExpIsAOneParameterSubgroupAndInverseIsExact"));
  for (int i = 0; i < 100; ++i) {
    const Eigen::Matrix3d x = randomShearAlgebra(rng, 1.5);
    const double s = lie_test::uniform(rng, -1.5, 1.5), t = lie_test::uniform(rng, -1.5, 1.5);
    const Eigen::Matrix3d prod = shearExp(s * x) * shearExp(t * x);
    EXPECT_LE(relErr(prod, shearExp((s + t) * x)), kRoundTripTol * prod.norm());
    const Eigen::Matrix3d a = randomShear(rng, 2.0, 3.0);
    EXPECT_LE(relErr(shearInverse(a), a.inverse()), kRoundTripTol * a.inverse().norm());
    EXPECT_LE(relErr(shearLog(shearInverse(a)), -shearLog(a)), kRoundTripTol);
  }
}

TEST(ShearGroup, LogRejectsMatricesOutsideTheGroup) {
  EXPECT_THROW(shearLog(group(0, 0.0, 0, 0, 1)), DomainError);
  EXPECT_THROW(shearLog(group(0, 1, 0, 0, -2)), DomainError);
  EXPECT_THROW(shearLog(group(std::nan(""), 1, 0, 0, 1)), DomainError);
}

}  // namespace
}  // namespace tetblend
