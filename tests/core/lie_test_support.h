#pragma once
// Shared helpers of the shear-group and Lie-Bodies tests: the printed,
// overridable random seed and random group elements.

#include <Eigen/Core>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

namespace tetblend::lie_test {

/// Seed of the random samples: TETBLEND_SEED if set, else a fixed default.
/// Printed by every test that uses it, so a failure can be replayed.
inline unsigned testSeed(const char* testName) {
  constexpr unsigned kDefaultSeed = 20190712u;
  const char* env = std::getenv("TETBLEND_SEED");
  const unsigned seed = env ? static_cast<unsigned>(std::stoul(env)) : kDefaultSeed;
  std::cout << "[ seed     ] " << testName << ": TETBLEND_SEED=" << seed << "\n";
  return seed;
}

inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

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

}  // namespace tetblend::lie_test
