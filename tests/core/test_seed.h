#pragma once
// The one seed helper of the core tests: the printed, overridable random seed
// and a uniform draw. Each test support header fixes its own default seed.

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

namespace tetblend::test_seed {

/// Seed of the random samples: TETBLEND_SEED if set, else `defaultSeed`.
/// Printed for `testName`, so a failure can be replayed.
inline unsigned seedFor(const char* testName, unsigned defaultSeed) {
  const char* env = std::getenv("TETBLEND_SEED");
  const unsigned seed = env ? static_cast<unsigned>(std::stoul(env)) : defaultSeed;
  std::cout << "[ seed     ] " << testName << ": TETBLEND_SEED=" << seed << "\n";
  return seed;
}

/// Uniform draw in [lo, hi).
inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

}  // namespace tetblend::test_seed
