// Rigid-blend throughput (one thread): DLB of 4 rigid maps (Kavan et al. §4)
// beside its baselines in the same run. Inputs are pre-generated: a pool of
// 1e6 random rigid maps (as dual quaternions and as 4x4 matrices) and 1e6
// convex weight 4-tuples; blend i uses maps i..i+3 and weight tuple i, so the
// data streams from memory as in a per-element loop. Items = blends.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <array>
#include <random>
#include <vector>

#include "tetblend/core/dual_quaternion.h"
#include "tetblend/core/dual_quaternion_blend.h"

namespace tetblend {
namespace {

constexpr int kPoolSize = 1000000;
constexpr int kInputs = 4;

struct Pool {
  std::vector<DualQuaternion> dqs;
  std::vector<Eigen::Matrix4d> matrices;
  std::vector<std::array<double, kInputs>> weights;
};

const Pool& pool() {
  static const Pool p = [] {
    Pool out;
    std::mt19937 rng(20070401u);
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(0.05, 1.0);
    out.dqs.reserve(kPoolSize + kInputs);
    out.matrices.reserve(kPoolSize + kInputs);
    for (int i = 0; i < kPoolSize + kInputs; ++i) {
      const Eigen::Quaterniond q = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
      const DualQuaternion d =
          DualQuaternion::fromRotationTranslation(q, Eigen::Vector3d(n(rng), n(rng), n(rng)));
      out.dqs.push_back(d);
      out.matrices.push_back(d.toMatrix());
    }
    out.weights.resize(kPoolSize);
    for (auto& w : out.weights) {
      double sum = 0;
      for (double& x : w) sum += (x = u(rng));
      for (double& x : w) x /= sum;
    }
    return out;
  }();
  return p;
}

// DLB of 4 dual quaternions through the array interface (the fast path).
void BM_dlb4_dualQuaternion(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  for (auto _ : state) {
    DualQuaternion b = dlb(&p.dqs[i], p.weights[i].data(), kInputs);
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_dlb4_dualQuaternion);

// DLB of 4 rigid 4x4 matrices: convert each to a dual quaternion, blend,
// convert back (Kavan Table 1 counts these conversions).
void BM_dlb4_matrixInMatrixOut(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  for (auto _ : state) {
    std::array<DualQuaternion, kInputs> d;
    for (int k = 0; k < kInputs; ++k) {
      const Eigen::Matrix4d& m = p.matrices[i + k];
      d[k] = DualQuaternion::fromRotationTranslation(Eigen::Quaterniond(m.topLeftCorner<3, 3>()),
                                                     m.topRightCorner<3, 1>());
    }
    Eigen::Matrix4d b = dlb(d.data(), p.weights[i].data(), kInputs).toMatrix();
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_dlb4_matrixInMatrixOut);

// Baseline: linear blending of the 4 matrices (linear blend skinning).
void BM_baseline_linearMatrix4(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  for (auto _ : state) {
    Eigen::Matrix4d b = p.weights[i][0] * p.matrices[i];
    for (int k = 1; k < kInputs; ++k) b += p.weights[i][k] * p.matrices[i + k];
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_baseline_linearMatrix4);

// Baseline: Eigen quaternion normalised lerp of the 4 rotations (aligned to
// the first) plus linear translation, from 4x4 matrices (coordinate-dependent
// "decomposition" blend, Kavan §2.2).
void BM_baseline_eigenQuaternionNlerp4(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  for (auto _ : state) {
    Eigen::Vector4d q = Eigen::Vector4d::Zero();
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    Eigen::Vector4d pivot = Eigen::Vector4d::Zero();
    for (int k = 0; k < kInputs; ++k) {
      const Eigen::Matrix4d& m = p.matrices[i + k];
      const Eigen::Vector4d qk = Eigen::Quaterniond(m.topLeftCorner<3, 3>()).coeffs();
      if (k == 0) pivot = qk;
      const double w = qk.dot(pivot) < 0 ? -p.weights[i][k] : p.weights[i][k];
      q += w * qk;
      t += p.weights[i][k] * m.topRightCorner<3, 1>();
    }
    Eigen::Quaterniond r;
    r.coeffs() = q.normalized();
    Eigen::Matrix4d b = Eigen::Matrix4d::Identity();
    b.topLeftCorner<3, 3>() = r.toRotationMatrix();
    b.topRightCorner<3, 1>() = t;
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_baseline_eigenQuaternionNlerp4);

// Baseline: ScLERP of 2 dual quaternions (exp/log path, Kavan §4).
void BM_baseline_scLerp2(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  for (auto _ : state) {
    DualQuaternion b = scLerp(p.weights[i][0], p.dqs[i], p.dqs[i + 1]);
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_baseline_scLerp2);

// Baseline: DIB of 4 dual quaternions at the default precision (Kavan §4).
void BM_baseline_dib4(benchmark::State& state) {
  const Pool& p = pool();
  int i = 0;
  std::vector<DualQuaternion> d(kInputs);
  std::vector<double> w(kInputs);
  for (auto _ : state) {
    for (int k = 0; k < kInputs; ++k) {
      d[k] = p.dqs[i + k];
      w[k] = p.weights[i][k];
    }
    DibResult b = dib(d, w);
    benchmark::DoNotOptimize(b);
    if (++i == kPoolSize) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_baseline_dib4);

}  // namespace
}  // namespace tetblend
