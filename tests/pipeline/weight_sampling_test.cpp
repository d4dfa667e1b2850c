// The random weight vectors of variations (pipeline/weight_sampling.h).

#include "tetblend/pipeline/weight_sampling.h"

#include <gtest/gtest.h>

#include "test_seed.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

constexpr unsigned kDefaultSeed = 20240611;
// Unwidened weights are e_k / (e_0 + e_1 + e_2): the sum's two roundings and
// one division per weight leave v0 + v1 within a few ulps of 1 (1 ulp 2.2e-16).
constexpr double kWeightRoundOff = 1e-15;
// The widened weight recomputed here with the library's own two operations
// ((1+X) b - X/3): equal unless FMA contraction differs between the two
// sides, which moves each by ~1 ulp of 2.5 (4.4e-16).
constexpr double kWideningTolerance = 1e-14;

TEST(WeightSampling, UniformOnTheSimplexWithTheDocumentedWidening) {
  const std::uint64_t seed = test_seed::seedFor("WeightSampling", kDefaultSeed);
  constexpr int kSamples = 20000;
  // Mean of a Dirichlet(1,1,1) coordinate is 1/3 with standard deviation
  // sqrt(2/36); over 20000 samples the standard error is ~1.7e-3: 5 sigma.
  constexpr double kMeanTolerance = 5 * 1.7e-3;
  const auto w = sampleSimplexWeights(kSamples, 2, seed, 0.0);
  double mean0 = 0.0;
  for (const auto& v : w) {
    ASSERT_GE(v[0], 0.0);
    ASSERT_GE(v[1], 0.0);
    ASSERT_LE(v[0] + v[1], 1.0 + kWeightRoundOff);
    mean0 += v[0] / kSamples;
  }
  EXPECT_NEAR(mean0, 1.0 / 3.0, kMeanTolerance);
  // Widening by X maps b to (1+X) b - X/3: same seed, exact relation.
  const auto wide = sampleSimplexWeights(kSamples, 2, seed, 1.5);
  for (int s = 0; s < kSamples; s += 97)
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(wide[s][k], 2.5 * w[s][k] - 1.5 / 3.0, kWideningTolerance);
  EXPECT_EQ(sampleSimplexWeights(5, 3, seed, 0.0), sampleSimplexWeights(5, 3, seed, 0.0));
  EXPECT_THROW(sampleSimplexWeights(1, 2, seed, -1.0), InputError);
}

}  // namespace
}  // namespace tetblend
