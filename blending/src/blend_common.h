#pragma once
// Helpers shared by the blend-method families (private to tetblend_blending).

#include <Eigen/Core>
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "ordered_parallel.h"
#include "tetblend/blending/blend_method.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace blend_detail {

/// Tets per TBB task in the per-tet loops.
constexpr int kTetGrain = kTetMapChunk;

/// Runs body(begin, end) in parallel on the fixed chunks [c kTetGrain,
/// min((c + 1) kTetGrain, count)) covering [0, count); each chunk writes only
/// its own tets' outputs. The chunk boundaries do not depend on the schedule,
/// so a body may hand a chunk's contiguous parameters to a batched kernel
/// (whose rounding may depend on an element's place in the batch) and still
/// give the same result on every run; an exception is the first chunk's
/// (parallelForFirstError).
template <typename Body>
void forEachTetChunk(int count, const Body& body) {
  const int chunks = (count + kTetGrain - 1) / kTetGrain;
  parallelForFirstError(chunks,
                        [&](int c) { body(c * kTetGrain, std::min(count, (c + 1) * kTetGrain)); });
}

/// Runs body(j) for j in [0, count) in parallel, in order within each fixed
/// chunk; each j writes only its own outputs, so neither the result nor the
/// tet an exception names depends on the schedule.
template <typename Body>
void forEachTet(int count, const Body& body) {
  forEachTetChunk(count, [&](int begin, int end) {
    for (int j = begin; j < end; ++j) body(j);
  });
}

/// Number of tets and examples of a BlendInput, after checking it is complete.
struct InputSizes {
  int tets = 0;
  int examples = 0;
};
InputSizes checkInput(const BlendInput& input);

/// The rest weight 1 - sum(w).
inline double restWeight(const std::vector<double>& weights) {
  double sum = 0.0;
  for (double w : weights) sum += w;
  return 1.0 - sum;
}

/// Writes the upper triangle of symmetric `m` as (xx, xy, xz, yy, yz, zz)
/// into out[0..6): the packed stretch layout of the prepared methods.
inline void packSymmetric(const Eigen::Matrix3d& m, double* out) {
  out[0] = m(0, 0);
  out[1] = m(0, 1);
  out[2] = m(0, 2);
  out[3] = m(1, 1);
  out[4] = m(1, 2);
  out[5] = m(2, 2);
}

/// The symmetric matrix packed by packSymmetric.
inline Eigen::Matrix3d unpackSymmetric(const double* y) {
  Eigen::Matrix3d m;
  m << y[0], y[1], y[2],  //
      y[1], y[3], y[4],   //
      y[2], y[4], y[5];
  return m;
}

/// The 4 by 4 homogeneous matrix of a linear map (no translation).
inline Eigen::Matrix4d homogeneous(const Eigen::Matrix3d& linear) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a.topLeftCorner<3, 3>() = linear;
  return a;
}

/// The deformation gradients of `input` re-laid tet-major (#T * #examples:
/// all examples of tet j at [j * examples, (j + 1) * examples)), so one tet's
/// blend reads contiguous memory.
std::vector<Eigen::Matrix3d> tetMajorGradients(const BlendInput& input, const InputSizes& sizes);

/// The weights with the rest's weight 1 - sum(w) prepended: index 0 is the
/// rest, index k the k-th example.
inline std::vector<double> withRestWeight(const std::vector<double>& weights) {
  std::vector<double> all(weights.size() + 1);
  all[0] = restWeight(weights);
  std::copy(weights.begin(), weights.end(), all.begin() + 1);
  return all;
}

/// Rethrows a DomainError from a core kernel with the method, example (or -1
/// for a blend) and tet named.
[[noreturn]] void rethrowForTet(const std::string& method, int example, int tet,
                                const std::exception& error);

}  // namespace blend_detail
}  // namespace tetblend
