#include "tetblend/pipeline/weight_sampling.h"

#include <cmath>
#include <random>

#include "tetblend/core/error.h"

namespace tetblend {

std::vector<std::vector<double>> sampleSimplexWeights(int count, int exampleCount,
                                                      std::uint64_t seed, double extrapolate) {
  if (count < 0) throw InputError("count must be >= 0, got " + std::to_string(count));
  if (exampleCount < 1) throw InputError("the model has no example shape to vary");
  if (!(extrapolate >= 0.0)) {
    throw InputError("extrapolate must be >= 0, got " + std::to_string(extrapolate));
  }
  std::mt19937_64 engine(seed);
  const auto uniformOpen = [&engine]() {
    // 53 random bits in (0, 1]: never 0, so the logarithm below is finite.
    return (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53;
  };
  const int corners = exampleCount + 1;
  std::vector<std::vector<double>> out;
  out.reserve(static_cast<std::size_t>(count));
  std::vector<double> e(static_cast<std::size_t>(corners));
  for (int s = 0; s < count; ++s) {
    double sum = 0.0;
    for (double& x : e) {
      x = -std::log(uniformOpen());
      sum += x;
    }
    std::vector<double> w(static_cast<std::size_t>(exampleCount));
    for (int k = 0; k < exampleCount; ++k) {
      const double b = e[static_cast<std::size_t>(k + 1)] / sum;
      w[static_cast<std::size_t>(k)] = (1.0 + extrapolate) * b - extrapolate / corners;
    }
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace tetblend
