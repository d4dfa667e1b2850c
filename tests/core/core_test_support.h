#pragma once
// Shared helpers of the so3 / sym3 / polar / Kaji–Ochiai tests: the printed,
// overridable random seed and random matrices with a prescribed condition.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

#include "test_seed.h"

namespace tetblend::core_test {

using test_seed::uniform;

/// Seed of the random samples (test_seed::seedFor, default 20130703u).
inline unsigned testSeed(const char* testName) { return test_seed::seedFor(testName, 20130703u); }

/// Entries uniform in [-1, 1] drawn from rng (Eigen's Random() uses
/// std::rand, which the printed seed does not reach).
template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> randomUniform(std::mt19937& rng) {
  return Eigen::Matrix<double, Rows, Cols>::NullaryExpr([&] { return uniform(rng, -1.0, 1.0); });
}

inline Eigen::Vector3d randomUnitVector(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Vector3d v;
  do {
    v = Eigen::Vector3d(n(rng), n(rng), n(rng));
  } while (v.norm() < 1e-3);
  return v.normalized();
}

/// Uniformly distributed rotation (Eigen's quaternion of a unit 4-vector).
inline Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

/// U diag(sigma) V^T with random rotations U, V, sigma_max = scale,
/// sigma_min = scale / cond, the middle singular value log-uniform in
/// [max(1e-2, 1/cond), 1] * scale, so that det A >= 1e-2 scale^3 / cond keeps a
/// sign that round-off cannot flip (for cond <= 1e12).
inline Eigen::Matrix3d randomMatrixWithCond(std::mt19937& rng, double cond, double scale = 1.0) {
  const double middle = std::exp(uniform(rng, -std::min(std::log(cond), std::log(100.0)), 0.0));
  const Eigen::Vector3d sigma = scale * Eigen::Vector3d(1.0, middle, 1.0 / cond);
  return randomRotation(rng) * sigma.asDiagonal() * randomRotation(rng).transpose();
}

/// Symmetric positive definite V diag(mu) V^T with a random rotation V.
inline Eigen::Matrix3d spdWithEigenvalues(std::mt19937& rng, const Eigen::Vector3d& mu) {
  const Eigen::Matrix3d v = randomRotation(rng);
  const Eigen::Matrix3d s = v * mu.asDiagonal() * v.transpose();
  return 0.5 * (s + s.transpose());
}

/// Relative Frobenius distance |a - b| / |b| (stableNorm: entries may be
/// near the ends of the double range).
inline double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).stableNorm() / b.stableNorm();
}

}  // namespace tetblend::core_test
