// Per-blend cost of the prepared shape blender with three examples, split
// into the per-tet blend, the stitch right-hand side and the
// back-substitution, against refactoring the stitch every time and against
// vertex-linear blending, measured in the same run. Two kinds of rest mesh:
//   box/N         a box bar of 6 tets per cube (11k, 106k, 125k, 1M tets),
//                 vertices and tets in grid order (local by construction);
//   tetgen/N      TetGen's mesh of a surface given with --surface PATH (e.g.
//                 CGAL's armadillo.off), at about N tets (from a volume
//                 bound), in tetrahedralize's order: what `tetblend prepare`
//                 hands the blender.
// The examples bend and twist the bar (or the surface's mesh about its
// longest bounding-box axis): a twist by π, a bend by π/2, and both.
// Counters (milliseconds per blend):
//   blend_ms, rhs_ms, solve_ms   parts of one prepared blend (mean)
//   ns_per_tet                   their sum / tets, the figure that compares
//                                meshes of different sizes and orders
//   refactor_ms                  StitchSolver construction + solve, once
//   vertex_linear_ms             one vertex-linear blend (mean of 20)
//   x_refactor, x_vertex_linear  ratios to the prepared blend's time
//   prepare_s                    ShapeBlender construction, once
//   rss_B_per_tet                growth of the resident set from before the
//                                model was built to after the blends (both
//                                after malloc_trim, before the refactor
//                                comparison) / tets: the prepared blender's
//                                steady memory (its stitch keeps the rest
//                                mesh and it keeps the examples; the bench
//                                keeps none) plus one BlendResult (vertices
//                                only: keepTargets is off)
//   anon_B_per_tet               the same growth of the anonymous resident
//                                memory only (RssAnon: without the pages of
//                                the program and shared libraries, e.g. the
//                                BLAS and CHOLMOD code first run while
//                                preparing)
//   maxrss_B_per_tet             process peak RSS (ru_maxrss) / tets, which
//                                includes preparation and the refactor's
//                                second factor
//   factor_nnz                   stored entries of the stitch's Cholesky factor
//   factor_B_per_tet             their bytes (8 each) / tets
//   stitch_B_per_tet             StitchSolver::memoryBytes() / tets: the
//                                factor with its indices, the rest mesh and
//                                the per-vertex index arrays
// Run: bench_blending [--surface PATH] [--benchmark_filter=...]

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench_options.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double peakRssBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);  // Linux: kilobytes
}

// Resident set now, after returning freed heap pages to the system.
double currentRssBytes() {
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// Anonymous resident memory now (RssAnon of /proc/self/status: heap and
// private mappings, without the file-backed pages of the program and its
// shared libraries), after malloc_trim.
double anonymousRssBytes() {
  malloc_trim(0);
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "RssAnon:") {
      double kilobytes = 0.0;
      status >> kilobytes;
      return 1024.0 * kilobytes;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0.0;
}

struct Model {
  std::unique_ptr<ShapeBlender> blender;
  double prepareSeconds = 0.0;
  double rssBeforeBytes = 0.0;   // resident set before the model was built
  double anonBeforeBytes = 0.0;  // its anonymous part
};

// The surface of the tetgen rows (--surface), empty when not given.
std::string& surfacePath() {
  static std::string path;
  return path;
}

// A twist by π, a bend by π/2 and both, along `axis` from `base` over `length`.
std::vector<Vertices> threeExamples(const Vertices& rest, const Eigen::Vector3d& base,
                                    const Eigen::Vector3d& axis, const Eigen::Vector3d& across,
                                    double length) {
  const Vertices twisted = twistAboutAxis(rest, base, axis, kPi, length);
  return {twisted, bendAboutAxis(rest, base, axis, across, kPi / 2, length),
          bendAboutAxis(twisted, base, axis, across.cross(axis), kPi / 3, length)};
}

// nx = ny = n, nz = 2.6 n cubes of 6 tets: 6 * 2.6 n^3 tets.
std::pair<TetMesh, std::vector<Vertices>> boxBar(int n) {
  const int nz = static_cast<int>(std::lround(2.6 * n));
  const double length = 2.6;
  TetMesh rest = boxTetMesh(n, n, nz, Eigen::Vector3d(1.0, 1.0, length));
  std::vector<Vertices> examples =
      threeExamples(rest.vertices, Eigen::Vector3d(0.0, 0.0, -length / 2), Eigen::Vector3d::UnitZ(),
                    Eigen::Vector3d::UnitX(), length);
  return {std::move(rest), std::move(examples)};
}

// TetGen's quality refinement (radius-edge 2) makes more tets than (solid
// volume) / (volume bound): the bound is this factor times volume / N. For
// CGAL's armadillo N = 1e6 gives 1.1 M tets; N = 1e5 gives 199 k (the
// quality bound alone makes 134 k).
constexpr double kTetsPerBoundedVolume = 1.6;

// TetGen's mesh of the --surface file with about `tets` tets, deformed about
// its bounding box's longest axis.
std::pair<TetMesh, std::vector<Vertices>> tetgenMesh(int tets) {
  const SurfaceMesh surface = readSurface(surfacePath());
  TetGenOptions options;
  options.maxTetVolume = kTetsPerBoundedVolume * enclosedVolume(surface) / tets;
  TetMesh rest = tetrahedralize(surface, options);
  const Eigen::Vector3d low = rest.vertices.colwise().minCoeff();
  const Eigen::Vector3d extent = Eigen::Vector3d(rest.vertices.colwise().maxCoeff()) - low;
  Eigen::Index longest = 0;
  extent.maxCoeff(&longest);
  const Eigen::Vector3d axis = Eigen::Vector3d::Unit(longest);
  const Eigen::Vector3d across = Eigen::Vector3d::Unit((longest + 1) % 3);
  const Eigen::Vector3d base = low + 0.5 * (extent - extent(longest) * axis);
  std::vector<Vertices> examples =
      threeExamples(rest.vertices, base, axis, across, extent(longest));
  return {std::move(rest), std::move(examples)};
}

enum class Mesh { kBox, kTetGen };

Model& model(Mesh kind, int size, BlendMethod method) {
  static std::map<std::tuple<Mesh, int, BlendMethod>, std::unique_ptr<Model>> cache;
  auto& slot = cache[{kind, size, method}];
  if (slot) return *slot;
  cache.clear();  // keep one model alive at a time: the RSS counter measures one
  const double rssBefore = currentRssBytes();
  auto m = std::make_unique<Model>();
  m->rssBeforeBytes = rssBefore;
  m->anonBeforeBytes = anonymousRssBytes();
  {
    // The mesh and examples live only until the blender has copied them.
    const auto [rest, examples] = kind == Mesh::kBox ? boxBar(size) : tetgenMesh(size);
    ShapeBlenderOptions options;
    options.methods = {method, BlendMethod::kVertexLinear};
    const auto start = Clock::now();
    m->blender = std::make_unique<ShapeBlender>(rest, examples, options);
    m->prepareSeconds = secondsSince(start);
  }
  auto& stored = cache[{kind, size, method}];
  stored = std::move(m);
  return *stored;
}

void blendBenchmark(benchmark::State& state, Mesh kind, BlendMethod method) {
  Model& m = model(kind, static_cast<int>(state.range(0)), method);
  const double tets = static_cast<double>(m.blender->rest().tets.rows());
  BlendResult result;
  // One untimed blend first: the result's buffers are then allocated and
  // touched, as they are for a caller that reuses its result.
  m.blender->blendInto({0.5, 0.25, 0.25}, method, result);
  double blend = 0.0, rhs = 0.0, solve = 0.0;
  int count = 0;
  for (auto _ : state) {
    const double t = 0.1 + 0.8 * (count % 7) / 6.0;
    m.blender->blendInto({t, 0.5 * (1.0 - t), 0.25}, method, result);
    blend += result.timings.blendSeconds;
    rhs += result.timings.rhsSeconds;
    solve += result.timings.solveSeconds;
    ++count;
    benchmark::DoNotOptimize(result.vertices.data());
  }
  const double perBlend = (blend + rhs + solve) / count;
  const double steadyRss = currentRssBytes();
  const double steadyAnon = anonymousRssBytes();
  // Same run, outside the timed loop: vertex-linear and a refactored solve.
  BlendResult linear;
  const auto linearStart = Clock::now();
  constexpr int kLinearRepeats = 20;
  for (int i = 0; i < kLinearRepeats; ++i) {
    m.blender->blendInto({0.3, 0.3, 0.3}, BlendMethod::kVertexLinear, linear);
  }
  const double vertexLinear = secondsSince(linearStart) / kLinearRepeats;
  // The refactored solve's maps (its cost does not depend on them): the
  // blended shape's own gradients, computed outside the timed part.
  const std::vector<Eigen::Matrix3d> targets =
      deformationGradients(m.blender->rest(), m.blender->stitch().restData(), result.vertices, 0);
  const auto refactorStart = Clock::now();
  const StitchSolver fresh(m.blender->rest());
  const Vertices refactored = fresh.solve(targets, m.blender->blendedCentroids({0.3, 0.3, 0.3}));
  benchmark::DoNotOptimize(refactored.data());
  const double refactor = secondsSince(refactorStart) + (blend + rhs) / count;
  state.counters["tets"] = tets;
  state.counters["factor_nnz"] = m.blender->stitch().factorNonzeros();
  state.counters["factor_B_per_tet"] = 8.0 * m.blender->stitch().factorNonzeros() / tets;
  state.counters["stitch_B_per_tet"] = m.blender->stitch().memoryBytes() / tets;
  state.counters["blend_ms"] = 1e3 * blend / count;
  state.counters["rhs_ms"] = 1e3 * rhs / count;
  state.counters["solve_ms"] = 1e3 * solve / count;
  state.counters["ns_per_tet"] = 1e9 * perBlend / tets;
  state.counters["refactor_ms"] = 1e3 * refactor;
  state.counters["vertex_linear_ms"] = 1e3 * vertexLinear;
  state.counters["x_refactor"] = refactor / perBlend;
  state.counters["x_vertex_linear"] = perBlend / vertexLinear;
  state.counters["prepare_s"] = m.prepareSeconds;
  state.counters["rss_B_per_tet"] = (steadyRss - m.rssBeforeBytes) / tets;
  state.counters["anon_B_per_tet"] = (steadyAnon - m.anonBeforeBytes) / tets;
  state.counters["maxrss_B_per_tet"] = peakRssBytes() / tets;
}

// n = 9, 19, 20, 24, 40 give 11 178, 106 134, 124 800, 214 272 and 998 400
// tets (24: the size of the armadillo's tetgen/100000 row).
BENCHMARK_CAPTURE(blendBenchmark, kaji, Mesh::kBox, BlendMethod::kKaji)
    ->Name("box/kaji")
    ->Arg(9)
    ->Arg(19)
    ->Arg(20)
    ->Arg(24)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(blendBenchmark, dq, Mesh::kBox, BlendMethod::kDualQuaternion)
    ->Name("box/dq")
    ->Arg(9)
    ->Arg(20)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(blendBenchmark, linear, Mesh::kBox, BlendMethod::kLinear)
    ->Name("box/linear")
    ->Arg(9)
    ->Arg(20)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The tetgen rows exist only with --surface (read before Google Benchmark's
// own flags).
void registerTetGenRows() {
  benchmark::RegisterBenchmark("tetgen/kaji", blendBenchmark, Mesh::kTetGen, BlendMethod::kKaji)
      ->Arg(100000)
      ->Arg(1000000)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

}  // namespace
}  // namespace tetblend

int main(int argc, char** argv) {
  tetblend::surfacePath() = tetblend::bench::takeOption(argc, argv, "surface");
  if (!tetblend::surfacePath().empty()) tetblend::registerTetGenRows();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
