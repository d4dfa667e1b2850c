#pragma once
// Shared helpers of the shear-group and Lie-Bodies tests: the printed,
// overridable random seed and random group elements.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <random>

#include "test_seed.h"

namespace tetblend::lie_test {

using test_seed::uniform;

/// Seed of the random samples (test_seed::seedFor, default 20190712u).
inline unsigned testSeed(const char* testName) { return test_seed::seedFor(testName, 20190712u); }

/// A random element of the shear group G_A with diagonal entries in
/// [e^-logRange, e^logRange] and off-diagonal entries in [-offRange, offRange].
inline Eigen::Matrix3d randomShear(std::mt19937& rng, double logRange, double offRange) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(0, 1) = uniform(rng, -offRange, offRange);
  a(0, 2) = uniform(rng, -offRange, offRange);
  a(1, 2) = uniform(rng, -offRange, offRange);
  a(1, 1) = std::exp(uniform(rng, -logRange, logRange));
  a(2, 2) = std::exp(uniform(rng, -logRange, logRange));
  return a;
}

/// A random element of the Lie algebra g_A with entries in [-range, range].
inline Eigen::Matrix3d randomShearAlgebra(std::mt19937& rng, double range) {
  Eigen::Matrix3d x = Eigen::Matrix3d::Zero();
  x(0, 1) = uniform(rng, -range, range);
  x(0, 2) = uniform(rng, -range, range);
  x(1, 1) = uniform(rng, -range, range);
  x(1, 2) = uniform(rng, -range, range);
  x(2, 2) = uniform(rng, -range, range);
  return x;
}

/// A random rotation (independent of so3.h: Eigen's AngleAxis) with angle in
/// [0, maxAngle] about a uniformly random axis.
inline Eigen::Matrix3d randomRotation(std::mt19937& rng, double maxAngle) {
  std::normal_distribution<double> gauss;
  const Eigen::Vector3d axis = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
  return Eigen::AngleAxisd(uniform(rng, 0.0, maxAngle), axis).toRotationMatrix();
}

/// Corners (3 by 4) of a random positively oriented tet with corners in
/// [-1, 1]^3 and |det of the edge matrix| >= 0.05 (well shaped).
inline Eigen::Matrix<double, 3, 4> randomTet(std::mt19937& rng) {
  for (;;) {
    Eigen::Matrix<double, 3, 4> c;
    for (int i = 0; i < 12; ++i) c(i) = uniform(rng, -1.0, 1.0);
    Eigen::Matrix3d e;
    for (int k = 0; k < 3; ++k) e.col(k) = c.col(k + 1) - c.col(0);
    const double det = e.determinant();
    if (std::abs(det) < 0.05) continue;
    if (det < 0) c.col(1).swap(c.col(2));
    return c;
  }
}

/// A random orientation-preserving affine map (4 by 4): linear part with
/// entries in [-1.5, 1.5] and det >= 0.05, translation in [-2, 2]^3.
inline Eigen::Matrix4d randomAffine(std::mt19937& rng) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  for (;;) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t(r, c) = uniform(rng, -1.5, 1.5);
    const double det = t.topLeftCorner<3, 3>().determinant();
    if (std::abs(det) < 0.05) continue;
    if (det < 0) t.row(0).head<3>() *= -1.0;
    break;
  }
  for (int r = 0; r < 3; ++r) t(r, 3) = uniform(rng, -2.0, 2.0);
  return t;
}

}  // namespace tetblend::lie_test
