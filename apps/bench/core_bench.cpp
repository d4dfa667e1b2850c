// Throughput of the Kaji–Ochiai kernels (one thread): so(3) exp/log, sym(3)
// exp/log, phi and psi, each beside Eigen's MatrixFunctions (.exp()/.log(),
// Padé with scaling and squaring / Schur–Parlett) in the same run, as in
// Kaji–Ochiai §4.4 Table 1, and the polar rotation beside Eigen's SVD.
// Inputs are pre-generated pools of 1e6 random values streamed in order, as
// in a per-element loop. Items = kernel calls.

#include <benchmark/benchmark.h>

#include <Eigen/SVD>
#include <unsupported/Eigen/MatrixFunctions>

#include <random>
#include <vector>

#include "tetblend/core/batch_kernels.h"
#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

constexpr int kPoolSize = 1000000;

struct CorePool {
  std::vector<Eigen::Vector3d> rotationVectors;  // angle uniform in [0, pi)
  std::vector<Eigen::Matrix3d> rotations;        // so3Exp of the above
  std::vector<Eigen::Matrix3d> symmetric;        // entries uniform in [-1, 1]
  std::vector<Eigen::Matrix3d> spd;              // exp of the above
  std::vector<AffineParams> params;              // the three parts above, translation
  std::vector<Eigen::Matrix4d> affine;           // phi of the above
  std::vector<Eigen::Matrix3d> linear;           // its linear parts (rotation × spd)
};

const CorePool& corePool() {
  static const CorePool pool = [] {
    CorePool p;
    std::mt19937 rng(20160204u);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> n;
    for (int i = 0; i < kPoolSize; ++i) {
      const Eigen::Vector3d axis = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
      const Eigen::Vector3d w = 3.14159 * 0.5 * (u(rng) + 1.0) * axis;
      Eigen::Matrix3d y;
      for (int r = 0; r < 3; ++r)
        for (int c = r; c < 3; ++c) y(r, c) = y(c, r) = u(rng);
      p.rotationVectors.push_back(w);
      p.rotations.push_back(so3Exp(w));
      p.symmetric.push_back(y);
      p.spd.push_back(symExp(y));
      p.params.push_back({Eigen::Vector3d(u(rng), u(rng), u(rng)), w, y});
      p.affine.push_back(phi(p.params.back()));
      p.linear.push_back(p.affine.back().topLeftCorner<3, 3>());
    }
    return p;
  }();
  return pool;
}

template <typename Input, typename Kernel>
void runKernel(benchmark::State& state, const std::vector<Input>& inputs, Kernel kernel) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kernel(inputs[i]));
    if (++i == inputs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_so3_exp(benchmark::State& s) {
  runKernel(s, corePool().rotationVectors, [](const Eigen::Vector3d& w) { return so3Exp(w); });
}
void BM_so3_exp_eigen(benchmark::State& s) {
  runKernel(s, corePool().rotationVectors,
            [](const Eigen::Vector3d& w) { return Eigen::Matrix3d(hat(w).exp()); });
}
void BM_so3_log(benchmark::State& s) {
  runKernel(s, corePool().rotations, [](const Eigen::Matrix3d& r) { return so3Log(r); });
}
void BM_so3_log_eigen(benchmark::State& s) {
  runKernel(s, corePool().rotations,
            [](const Eigen::Matrix3d& r) { return Eigen::Matrix3d(r.log()); });
}
void BM_sym_exp(benchmark::State& s) {
  runKernel(s, corePool().symmetric, [](const Eigen::Matrix3d& y) { return symExp(y); });
}
void BM_sym_exp_eigen(benchmark::State& s) {
  runKernel(s, corePool().symmetric,
            [](const Eigen::Matrix3d& y) { return Eigen::Matrix3d(y.exp()); });
}
void BM_sym_log(benchmark::State& s) {
  runKernel(s, corePool().spd, [](const Eigen::Matrix3d& m) { return symLog(m); });
}
void BM_sym_log_eigen(benchmark::State& s) {
  runKernel(s, corePool().spd, [](const Eigen::Matrix3d& m) { return Eigen::Matrix3d(m.log()); });
}
void BM_phi(benchmark::State& s) {
  runKernel(s, corePool().params, [](const AffineParams& p) { return phi(p); });
}
void BM_phi_eigen(benchmark::State& s) {
  runKernel(s, corePool().params, [](const AffineParams& p) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = hat(p.rotationLog).exp() * p.stretchLog.exp();
    m.topRightCorner<3, 1>() = p.translation;
    return m;
  });
}
void BM_psi(benchmark::State& s) {
  runKernel(s, corePool().affine, [](const Eigen::Matrix4d& a) { return psi(a); });
}
// psi's two pieces on the same inputs, for psi's cost against the sum of
// theirs (issue 14 goal 3): the polar decomposition with the stretch's log
// (one eigen-decomposition of A^T A serves both), then so(3) log of the
// rotation (BM_so3_log, on the pool's rotations).
void BM_psi_piece_polar_log(benchmark::State& s) {
  runKernel(s, corePool().affine,
            [](const Eigen::Matrix4d& a) { return polarDecomposeLog(a.topLeftCorner<3, 3>()); });
}
// The polar rotation alone (ARAP's local step, compatible_tets.cpp).
void BM_polar_rotation(benchmark::State& s) {
  runKernel(s, corePool().linear,
            [](const Eigen::Matrix3d& a) { return polarDecompose(a).rotation; });
}
void BM_polar_rotation_eigen(benchmark::State& s) {
  runKernel(s, corePool().linear, [](const Eigen::Matrix3d& a) {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return Eigen::Matrix3d(svd.matrixU() * svd.matrixV().transpose());
  });
}
void BM_psi_eigen(benchmark::State& s) {
  // The diagonalisation-free reference route: S = sqrt(A^T A) and both logs
  // by MatrixFunctions.
  runKernel(s, corePool().affine, [](const Eigen::Matrix4d& a) {
    const Eigen::Matrix3d l = a.topLeftCorner<3, 3>();
    const Eigen::Matrix3d stretch = (l.transpose() * l).sqrt();
    const Eigen::Matrix3d rotation = l * stretch.inverse();
    return AffineParams{a.topRightCorner<3, 1>(), vee(rotation.log()), stretch.log()};
  });
}

// Batched kernels (batch_kernels.h) over the same pools, kBatchChunk
// consecutive elements per call; items = elements.
constexpr std::size_t kBatchChunk = 1024;

template <typename Input, typename Output, typename Batch>
void runBatched(benchmark::State& state, const std::vector<Input>& inputs, Batch batch) {
  std::vector<Output> out(kBatchChunk);
  std::size_t start = 0;
  for (auto _ : state) {
    batch(inputs.data() + start, out.data(), kBatchChunk);
    benchmark::ClobberMemory();
    start += kBatchChunk;
    if (start + kBatchChunk > inputs.size()) start = 0;
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kBatchChunk));
}

void BM_so3_exp_batched(benchmark::State& s) {
  runBatched<Eigen::Vector3d, Eigen::Matrix3d>(s, corePool().rotationVectors, so3ExpBatch);
}
void BM_so3_log_batched(benchmark::State& s) {
  runBatched<Eigen::Matrix3d, Eigen::Vector3d>(s, corePool().rotations, so3LogBatch);
}
void BM_sym_exp_batched(benchmark::State& s) {
  runBatched<Eigen::Matrix3d, Eigen::Matrix3d>(s, corePool().symmetric, symExpBatch);
}
void BM_sym_log_batched(benchmark::State& s) {
  runBatched<Eigen::Matrix3d, Eigen::Matrix3d>(s, corePool().spd, symLogBatch);
}
void BM_phi_batched(benchmark::State& s) {
  runBatched<AffineParams, Eigen::Matrix4d>(s, corePool().params, phiBatch);
}
void BM_psi_batched(benchmark::State& s) {
  runBatched<Eigen::Matrix4d, AffineParams>(s, corePool().affine, psiBatch);
}
void BM_polar_rotation_batched(benchmark::State& s) {
  runBatched<Eigen::Matrix3d, Eigen::Matrix3d>(s, corePool().linear, polarRotationBatch);
}

BENCHMARK(BM_so3_exp);
BENCHMARK(BM_so3_exp_batched);
BENCHMARK(BM_so3_exp_eigen);
BENCHMARK(BM_so3_log);
BENCHMARK(BM_so3_log_batched);
BENCHMARK(BM_so3_log_eigen);
BENCHMARK(BM_sym_exp);
BENCHMARK(BM_sym_exp_batched);
BENCHMARK(BM_sym_exp_eigen);
BENCHMARK(BM_sym_log);
BENCHMARK(BM_sym_log_batched);
BENCHMARK(BM_sym_log_eigen);
BENCHMARK(BM_phi);
BENCHMARK(BM_phi_batched);
BENCHMARK(BM_phi_eigen);
BENCHMARK(BM_psi);
BENCHMARK(BM_psi_piece_polar_log);
BENCHMARK(BM_psi_batched);
BENCHMARK(BM_psi_eigen);
BENCHMARK(BM_polar_rotation);
BENCHMARK(BM_polar_rotation_batched);
BENCHMARK(BM_polar_rotation_eigen);

}  // namespace
}  // namespace tetblend
