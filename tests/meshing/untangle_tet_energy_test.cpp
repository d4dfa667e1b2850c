// The untangler's per-tet energy (Garanzha et al. 2021) and its corner
// Hessian from the closed-form eigensystem (Smith, de Goes & Kim 2019),
// against independent oracles: central differences of the energy and of the
// gradient (in F, and in the corners of a random tet), and a numerical
// eigendecomposition of the 9 by 9 Hessian in F for the projection. The
// Hessian in F is the corner Hessian of the unit corner tet, whose corners
// 1..3 move F's columns one to one. Covered: both branches of χ (J > 0, J <= 0, J = 0), repeated
// singular values, and both eigenvalue paths of the SVD (closed form, Jacobi near rank 1).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../test_seed.h"
#include "tetblend/core/cofactor.h"
#include "untangle_tet_energy.h"

namespace tetblend {
namespace {

unsigned testSeed() { return test_seed::seedOfCurrentTest(20261126u); }

// Central-difference step relative to the scale on which f varies: ‖F‖ (at
// least 1), and near J = 0 the width ε of χ's transition, seen through
// ∂J/∂F = cof F. The truncation error h² f‴ / 6 and the rounding error
// ulp(f) / h balance near h = 1e-5 of that scale.
constexpr double kDifferenceStep = 1e-5;
// Agreement of analytic and central-difference derivatives, relative to the
// largest entry of the analytic derivative plus the function's own size
// (a derivative near 0, at F = I, still carries the rounding of f / h):
// truncation and rounding are both ~1e-10 of that at the step above.
constexpr double kDifferenceTolerance = 1e-6;

double differenceStep(const Eigen::Matrix3d& f, double epsilon) {
  return kDifferenceStep *
         std::min(std::max(1.0, f.norm()), epsilon / std::max(1.0, cofactor(f).norm()));
}
// Projected Hessian against the numerical eigendecomposition, relative to its
// largest entry: both are exact to a few hundred ulp of that entry.
constexpr double kProjectionTolerance = 1e-10;

// Deformation gradients covering the branches: random (both signs of J),
// J = 0 (rank 2), J just either side of 0, repeated singular values, a
// rotation, a reflection, near-rank-1 maps (Jacobi path of the SVD), rank 1
// and 0.
std::vector<Eigen::Matrix3d> sampleGradients(std::mt19937& rng) {
  std::vector<Eigen::Matrix3d> samples;
  for (int k = 0; k < 40; ++k) {
    Eigen::Matrix3d f;
    for (int i = 0; i < 9; ++i) f(i) = test_seed::uniform(rng, -2.0, 2.0);
    samples.push_back(f);
  }
  samples.push_back(Eigen::Matrix3d::Identity());
  samples.push_back(Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal());
  samples.push_back(Eigen::Vector3d(2.0, 0.5, 0.0).asDiagonal());
  samples.push_back(Eigen::Vector3d(2.0, 0.5, 1e-9).asDiagonal());
  samples.push_back(Eigen::Vector3d(2.0, 0.5, -1e-9).asDiagonal());
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(2.0, Eigen::Vector3d(-1, 0.5, 2).normalized()).toRotationMatrix();
  for (double last : {1e-8, -1e-8}) {  // near rank 1: Jacobi eigenvalues, both signs of J
    const Eigen::Matrix3d thin = Eigen::Vector3d(3.0, 1e-7, last).asDiagonal();
    samples.push_back(thin);
    samples.push_back(turn * thin * turn.transpose().eval() * turn);
  }
  samples.push_back(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix());
  samples.push_back(Eigen::Matrix3d::Zero());
  samples.push_back(Eigen::Vector3d(1.0, -2.0, 0.5) * Eigen::RowVector3d(0.3, 1.0, 2.0));  // rank 1
  Eigen::Matrix3d rank2;
  rank2 << 1.0, 2.0, 3.0, 0.5, -1.0, 2.0, 1.5, 1.0, 5.0;  // row 3 = row 1 + row 2
  samples.push_back(rank2);
  return samples;
}

std::string describe(const Eigen::Matrix3d& f, double epsilon) {
  std::ostringstream out;
  out << "F = [" << f.row(0) << "; " << f.row(1) << "; " << f.row(2) << "], det "
      << f.determinant() << ", epsilon " << epsilon;
  return out.str();
}

// Barycentric gradients of the unit corner tet (0, e_0, e_1, e_2): F's
// column j is corner j + 1 minus corner 0.
Eigen::Matrix<double, 3, 4> unitCornerGradients() {
  Eigen::Matrix<double, 3, 4> g;
  g << -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  return g;
}

using Matrix9d = Eigen::Matrix<double, 9, 9>;

Matrix9d hessianInF(const Eigen::Matrix3d& f, double epsilon, bool projected) {
  return untangleCornerHessian(f, unitCornerGradients(), epsilon, projected).bottomRightCorner<9, 9>();
}

Eigen::Matrix3d gradientOf(const Eigen::Matrix3d& f, double epsilon) {
  Eigen::Matrix3d gradient;
  untangleTetEnergy(f, epsilon, &gradient);
  return gradient;
}

TEST(UntangleTetEnergy, GradientMatchesCentralDifferences) {
  std::mt19937 rng(testSeed());
  for (const Eigen::Matrix3d& f : sampleGradients(rng)) {
    for (double epsilon : {1.0, 0.1, 1e-2}) {
      const double h = differenceStep(f, epsilon);
      const Eigen::Matrix3d analytic = gradientOf(f, epsilon);
      Eigen::Matrix3d numeric;
      for (int i = 0; i < 9; ++i) {
        Eigen::Matrix3d plus = f;
        Eigen::Matrix3d minus = f;
        plus(i) += h;
        minus(i) -= h;
        numeric(i) = (untangleTetEnergy(plus, epsilon, nullptr) -
                      untangleTetEnergy(minus, epsilon, nullptr)) /
                     (2.0 * h);
      }
      EXPECT_LE((analytic - numeric).cwiseAbs().maxCoeff(),
                kDifferenceTolerance * (analytic.cwiseAbs().maxCoeff() +
                                        untangleTetEnergy(f, epsilon, nullptr)))
          << describe(f, epsilon);
    }
  }
}

TEST(UntangleTetEnergy, HessianMatchesCentralDifferencesOfTheGradient) {
  std::mt19937 rng(testSeed());
  for (const Eigen::Matrix3d& f : sampleGradients(rng)) {
    for (double epsilon : {1.0, 0.1, 1e-2}) {
      const double h = differenceStep(f, epsilon);
      const Matrix9d analytic = hessianInF(f, epsilon, /*projected=*/false);
      Matrix9d numeric;
      for (int i = 0; i < 9; ++i) {
        Eigen::Matrix3d plus = f;
        Eigen::Matrix3d minus = f;
        plus(i) += h;
        minus(i) -= h;
        const Eigen::Matrix3d difference = (gradientOf(plus, epsilon) - gradientOf(minus, epsilon)) / (2.0 * h);
        numeric.col(i) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(difference.data());
      }
      EXPECT_LE((analytic - numeric).cwiseAbs().maxCoeff(),
                kDifferenceTolerance * (analytic.cwiseAbs().maxCoeff() +
                                        gradientOf(f, epsilon).cwiseAbs().maxCoeff()))
          << describe(f, epsilon);
    }
  }
}

// The corner Hessian of a random tet against central differences of the
// corner gradient ∂f/∂X = (∂f/∂F) G, and its projection against Bᵀ h⁺ B,
// with B = ∂vec(F)/∂X built here and h⁺ the projected Hessian in F.
TEST(UntangleTetEnergy, CornerHessianOfARandomTetIsTheChainRule) {
  std::mt19937 rng(testSeed());
  for (const Eigen::Matrix3d& f : sampleGradients(rng)) {
    Eigen::Matrix3d edges;  // a random rest tet, corner 0 at the origin
    do {
      for (int i = 0; i < 9; ++i) edges(i) = test_seed::uniform(rng, -1.0, 1.0);
    } while (std::abs(edges.determinant()) < 0.1);
    Eigen::Matrix<double, 3, 4> g;
    g.rightCols<3>() = edges.inverse();  // rows of E⁻¹: gradients of corners 1..3
    g.col(0) = -g.rightCols<3>().rowwise().sum();
    for (double epsilon : {1.0, 1e-2}) {
      Eigen::Matrix<double, 9, 12> chain;  // ∂vec(F)/∂X: entry (k + 3j, 3a + k) = G(j, a)
      chain.setZero();
      for (int a = 0; a < 4; ++a) {
        for (int j = 0; j < 3; ++j) {
          for (int k = 0; k < 3; ++k) chain(k + 3 * j, 3 * a + k) = g(j, a);
        }
      }
      const double h = differenceStep(f, epsilon) / std::max(1.0, chain.norm());
      const Matrix12d analytic = untangleCornerHessian(f, g, epsilon, /*projected=*/false);
      Matrix12d numeric;
      for (int c = 0; c < 12; ++c) {
        const Eigen::Matrix3d step = h * (chain.col(c).reshaped(3, 3));
        const Eigen::Matrix<double, 3, 4> difference =
            (gradientOf(f + step, epsilon) - gradientOf(f - step, epsilon)) * g / (2.0 * h);
        numeric.col(c) = difference.reshaped();
      }
      EXPECT_LE((analytic - numeric).cwiseAbs().maxCoeff(),
                kDifferenceTolerance * (analytic.cwiseAbs().maxCoeff() +
                                        (gradientOf(f, epsilon) * g).cwiseAbs().maxCoeff()))
          << describe(f, epsilon);
      const Matrix12d viaF = chain.transpose() * hessianInF(f, epsilon, true) * chain;
      EXPECT_LE((untangleCornerHessian(f, g, epsilon, true) - viaF).cwiseAbs().maxCoeff(),
                kProjectionTolerance * viaF.cwiseAbs().maxCoeff())
          << describe(f, epsilon);
    }
  }
}

TEST(UntangleTetEnergy, ProjectedHessianDropsExactlyTheNegativeEigenvalues) {
  std::mt19937 rng(testSeed());
  int indefinite = 0;
  for (const Eigen::Matrix3d& f : sampleGradients(rng)) {
    for (double epsilon : {1.0, 1e-2, 1e-6}) {
      const Matrix9d exact = hessianInF(f, epsilon, /*projected=*/false);
      const Eigen::SelfAdjointEigenSolver<Matrix9d> eigen(exact);
      if (eigen.eigenvalues().minCoeff() < 0.0) ++indefinite;
      const Matrix9d oracle = eigen.eigenvectors() *
                              eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                              eigen.eigenvectors().transpose();
      const Matrix9d projected = hessianInF(f, epsilon, /*projected=*/true);
      EXPECT_LE((projected - oracle).cwiseAbs().maxCoeff(),
                kProjectionTolerance * exact.cwiseAbs().maxCoeff())
          << describe(f, epsilon);
    }
  }
  // The samples must exercise the projection, not only PSD Hessians.
  EXPECT_GT(indefinite, 10);
}

TEST(UntangleTetEnergy, EnergyIsFiniteAndPositiveAcrossTheChiBranch) {
  for (double j : {-1e3, -1.0, -1e-300, 0.0, 1e-300, 1.0, 1e3}) {
    const Eigen::Matrix3d f = Eigen::Vector3d(1.0, 1.0, j).asDiagonal();
    for (double epsilon : {1.0, 1e-8, 1e-13}) {
      const double value = untangleTetEnergy(f, epsilon, nullptr);
      EXPECT_TRUE(std::isfinite(value) && value > 0.0) << describe(f, epsilon) << ": " << value;
    }
  }
}

}  // namespace
}  // namespace tetblend
