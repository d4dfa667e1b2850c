#pragma once
// The one seed helper of every test suite: the printed, overridable random
// seed and a uniform draw. Each suite's support header fixes its default.

#include <gtest/gtest.h>

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

/// seedFor with the name of the running GoogleTest test.
inline unsigned seedOfCurrentTest(unsigned defaultSeed) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return seedFor(test != nullptr ? test->name() : "", defaultSeed);
}

/// Uniform draw in [lo, hi).
inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

}  // namespace tetblend::test_seed
