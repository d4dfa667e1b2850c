// bench_meshing: the untangler's per-tet work (untangle_tet_energy.h), the
// projected corner Hessian and the energy with its gradient, in tets per
// second. Deformation gradients as an untangling attempt meets them: a
// random rotation times I plus noise of 0.3, one in ten reflected (an
// inverted tet); barycentric gradients of random tets; ε = 0.1.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "untangle_tet_energy.h"

namespace tetblend {
namespace {

constexpr int kSampleCount = 4096;
constexpr unsigned kSeed = 20261201u;
constexpr double kEpsilon = 0.1;
constexpr double kNoise = 0.3;
constexpr int kInvertedEvery = 10;

struct TetSample {
  Eigen::Matrix3d f;
  Eigen::Matrix<double, 3, 4> g;
};

const std::vector<TetSample>& samples() {
  static const std::vector<TetSample> cached = [] {
    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<TetSample> result;
    while (static_cast<int>(result.size()) < kSampleCount) {
      Eigen::Matrix3d edges;  // rest edges x1 - x0, x2 - x0, x3 - x0 as columns
      for (int i = 0; i < 9; ++i) edges(i) = unit(rng);
      if (!(edges.determinant() > 0.05)) continue;
      TetSample sample;
      const Eigen::Matrix3d inverse = edges.inverse();  // rows: gradients of λ1..λ3
      sample.g.rightCols<3>() = inverse.transpose();
      sample.g.col(0) = -inverse.transpose().rowwise().sum();
      Eigen::Matrix3d noise;
      for (int i = 0; i < 9; ++i) noise(i) = kNoise * unit(rng);
      const Eigen::Quaterniond turn(unit(rng), unit(rng), unit(rng), unit(rng));
      sample.f = turn.normalized().toRotationMatrix() * (Eigen::Matrix3d::Identity() + noise);
      if (result.size() % kInvertedEvery == 0) sample.f.col(0) *= -1.0;
      result.push_back(sample);
    }
    return result;
  }();
  return cached;
}

void BM_untangle_corner_hessian(benchmark::State& state) {
  const std::vector<TetSample>& tets = samples();
  for (auto _ : state) {
    for (const TetSample& tet : tets) {
      benchmark::DoNotOptimize(untangleCornerHessian(tet.f, tet.g, kEpsilon, /*projected=*/true));
    }
  }
  state.SetItemsProcessed(state.iterations() * kSampleCount);
}
BENCHMARK(BM_untangle_corner_hessian);

void BM_untangle_tet_energy_gradient(benchmark::State& state) {
  const std::vector<TetSample>& tets = samples();
  Eigen::Matrix3d gradient;
  for (auto _ : state) {
    for (const TetSample& tet : tets) {
      benchmark::DoNotOptimize(untangleTetEnergy(tet.f, kEpsilon, &gradient));
      benchmark::DoNotOptimize(gradient);
    }
  }
  state.SetItemsProcessed(state.iterations() * kSampleCount);
}
BENCHMARK(BM_untangle_tet_energy_gradient);

}  // namespace
}  // namespace tetblend
