// bench_meshing: compatible tet meshes for a rest bar and 3 examples (2π
// twist, 180° bend, 170° dual-quaternion-skinned elbow) at about 10k, 100k
// and 1M tets, split into the one-off factorisation (CompatibleTetBuilder
// construction) and the per-example placement (harmonic, ARAP, untangling).
// Counters: tets, ARAP iterations, inverted tets left, peak RSS (getrusage
// ru_maxrss, whole process so far).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <map>
#include <memory>
#include <vector>

#include "tetblend/meshing/compatible_tets.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLength = 6.0;

double peakRssMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

// Bar of n × n × 6n cubes (36 n³ tets), boundary vertices first.
const BoundaryFirstMesh& restBar(int n) {
  static std::map<int, BoundaryFirstMesh> cache;
  auto it = cache.find(n);
  if (it == cache.end()) {
    it = cache
             .emplace(n, reorderBoundaryFirst(
                             boxTetMesh(6 * n, n, n, Eigen::Vector3d(kLength, 1.0, 1.0))))
             .first;
  }
  return it->second;
}

Vertices exampleSurface(const BoundaryFirstMesh& rest, int example) {
  const Vertices& v = rest.mesh.vertices;
  Vertices deformed;
  if (example == 0) {
    deformed = twistAboutAxis(v, Eigen::Vector3d(-kLength / 2, 0, 0), Eigen::Vector3d::UnitX(),
                              2 * kPi, kLength);
  } else if (example == 1) {
    deformed = bendAboutAxis(v, Eigen::Vector3d(-kLength / 2, 0, 0), Eigen::Vector3d::UnitX(),
                             Eigen::Vector3d::UnitY(), kPi, kLength);
  } else {
    const Eigen::MatrixXd weights =
        twoBoneWeights(v, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1.5);
    deformed = dualQuaternionSkinning(
        v, weights,
        {Eigen::Isometry3d::Identity(),
         rotationAboutLine(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 170 * kPi / 180)});
  }
  return deformed.topRows(rest.boundaryVertexCount);
}

void BM_Factorise(benchmark::State& state) {
  const BoundaryFirstMesh& rest = restBar(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    CompatibleTetBuilder builder(rest.mesh, rest.boundaryVertexCount);
    benchmark::DoNotOptimize(&builder);
  }
  state.counters["tets"] = static_cast<double>(rest.mesh.tets.rows());
  state.counters["peak_rss_MB"] = peakRssMegabytes();
}

void BM_PlaceExample(benchmark::State& state) {
  const BoundaryFirstMesh& rest = restBar(static_cast<int>(state.range(0)));
  const int example = static_cast<int>(state.range(1));
  const CompatibleTetBuilder builder(rest.mesh, rest.boundaryVertexCount);
  const Vertices surface = exampleSurface(rest, example);
  CompatibleTetResult result;
  for (auto _ : state) {
    result = builder.place(surface);
    benchmark::DoNotOptimize(result.vertices.data());
  }
  state.counters["tets"] = static_cast<double>(rest.mesh.tets.rows());
  state.counters["arap_iterations"] = result.arapIterations;
  state.counters["inverted_left"] = static_cast<double>(result.invertedTets.size());
  state.counters["harmonic_inverted"] = result.harmonicInvertedCount;
  state.counters["peak_rss_MB"] = peakRssMegabytes();
}

// n = 6, 13, 28: 7 776, 79 092 and 790 272 tets.
BENCHMARK(BM_Factorise)->Arg(6)->Arg(13)->Arg(28)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PlaceExample)
    ->ArgsProduct({{6, 13, 28}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace tetblend
