#pragma once
// Reproducible random weight vectors for `tetblend variations` and the
// Python module's Model.variations.
//
// Distribution: barycentric coordinates (b_0, ..., b_n) uniform on the
// n-simplex (Dirichlet(1, ..., 1), drawn as normalised unit exponentials),
// where b_0 belongs to the rest shape and b_k to example k; the weights are
// w_k = (1 + X) b_k - X / (n + 1), k = 1..n, i.e. the simplex of the rest and
// the examples scaled by (1 + X) about its centroid. X = 0 (the default)
// stays inside the convex hull of the examples in parameter space (every
// w_k >= 0, sum <= 1); X > 0 extrapolates: each w_k ranges over
// [-X/(n+1), 1 + X n/(n+1)].
//
// The random numbers come from std::mt19937_64 (whose output sequence the C++
// standard fixes) turned into doubles by hand, so a seed gives the same
// shapes on every platform and standard library.

#include <cstdint>
#include <vector>

namespace tetblend {

/// `count` weight vectors of length `exampleCount` (see the file comment),
/// from `seed`, widened by `extrapolate` >= 0.
std::vector<std::vector<double>> sampleSimplexWeights(int count, int exampleCount,
                                                      std::uint64_t seed, double extrapolate);

}  // namespace tetblend
