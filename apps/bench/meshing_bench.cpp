// bench_meshing: preparing compatible tet meshes for a rest bar and 3
// examples, split into the stages a user pays for. Two example sets:
//   easy  2π twist, 180° bend, 170° dual-quaternion-skinned elbow (the
//         harmonic extension is already valid);
//   hard  the pose corpus's twist720, dqsTwist300 and dqsBend170 of the same
//         bar (pose_corpus.h): all-surface tets inverted up front, ARAP,
//         untangling and refinement needed.
// Stages:
//   read      readSurface of the 4 binary PLY files (written once, untimed);
//   validate  requireValidRest (incl. CGAL self-intersections) of the rest
//             and requireCompatibleExample of the 3 examples;
//   tetgen    tetrahedralize of the rest surface, maxTetVolume chosen for
//             about 10k, 100k or 1M tets;
//   embed     buildCompatibleTetMeshes (example_aware_tets.h): the examples'
//             self-intersection checks, refinement of all-surface tets,
//             factorisation, placement of each example (harmonic, then ARAP,
//             untangling and refinement rounds only where tets invert).
// Counters are milliseconds per stage, the ratio (validate + embed) / tetgen,
// tets (TetGen's, and after refinement), Steiner points added, inverted tets
// left over the examples whose surface does not intersect itself, the number
// of examples whose surface does ("intersecting") and their inverted tets
// (excluded by prepare), and peak RSS (getrusage ru_maxrss of the whole
// process so far; sizes run in increasing order, so it is the peak of the
// largest size run yet). The reported time is the sum of the four stages.

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/pose_corpus.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tet_boundary.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {
namespace {

constexpr double kLength = 6.0;         // bar is kLength × 1 × 1
constexpr double kBarVolume = kLength;  // units³
constexpr int kExampleCount = 3;
// TetGen's tets average about this fraction of the -a bound (measured on this
// bar with -q2.0), so maxTetVolume = kMeanToMaxVolume⁻¹ · volume / target.
constexpr double kMeanToMaxVolume = 0.55;

double peakRssMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// Surface cells across the bar's 1 × 1 section for a target tet count: the
// surface edge then matches the edge of a regular tet of mean volume
// kBarVolume / target (regular tet volume = a³ / (6√2)).
int surfaceCellsFor(long long targetTets) {
  const double meanVolume = kBarVolume / static_cast<double>(targetTets);
  const double edge = std::cbrt(meanVolume * 6.0 * std::sqrt(2.0));
  return std::max(2, static_cast<int>(std::lround(1.0 / edge)));
}

// Directory holding the four surface files, removed at exit.
class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "bench_meshing_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw Error("bench_meshing: mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct SurfaceFiles {
  std::string rest;
  std::vector<std::string> examples;
};

enum ExampleSet { kEasy = 0, kHard = 1 };

// The three examples of `set` for the rest bar `rest` (see the top).
std::vector<Vertices> barExamples(const SurfaceMesh& rest, ExampleSet set) {
  const Vertices& v = rest.vertices;
  if (set == kHard) {
    std::vector<Vertices> chosen;
    for (const NamedPose& pose : hardPoses(v, rest.triangles)) {
      if (pose.name == "twist720" || pose.name == "dqsTwist300" || pose.name == "dqsBend170") {
        chosen.push_back(pose.vertices);
      }
    }
    return chosen;
  }
  const Eigen::Vector3d start(-kLength / 2, 0, 0);
  const Eigen::MatrixXd weights =
      twoBoneWeights(v, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1.5);
  return {twistAboutAxis(v, start, Eigen::Vector3d::UnitX(), 2 * kPi, kLength),
          bendAboutAxis(v, start, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), kPi, kLength),
          dualQuaternionSkinning(v, weights,
                                 {Eigen::Isometry3d::Identity(),
                                  rotationAboutLine(Eigen::Vector3d::Zero(),
                                                    Eigen::Vector3d::UnitZ(), 170 * kPi / 180)})};
}

// Writes (once per size and set) the rest bar surface of m × m × 6m cells and
// its 3 examples as binary little-endian PLY (exact doubles).
const SurfaceFiles& surfaceFiles(int cells, ExampleSet set) {
  static TempDir dir;
  static std::map<std::pair<int, int>, SurfaceFiles> cache;
  auto it = cache.find({cells, set});
  if (it != cache.end()) return it->second;

  const SurfaceMesh full =
      boundarySurface(boxTetMesh(6 * cells, cells, cells, Eigen::Vector3d(kLength, 1.0, 1.0)));
  const SurfaceMesh rest = removeVertices(full, unreferencedVertices(full));
  const std::vector<Vertices> deformed = barExamples(rest, set);
  const std::string prefix =
      (dir.path() / ("bar" + std::to_string(cells) + (set == kHard ? "_hard_" : "_easy_")))
          .string();
  SurfaceFiles files;
  files.rest = prefix + "rest.ply";
  writeSurface(files.rest, rest);
  for (int e = 0; e < kExampleCount; ++e) {
    files.examples.push_back(prefix + "example" + std::to_string(e) + ".ply");
    writeSurface(files.examples.back(), SurfaceMesh{deformed[e], rest.triangles});
  }
  return cache.emplace(std::make_pair(cells, static_cast<int>(set)), std::move(files))
      .first->second;
}

void BM_PrepareCompatibleMeshes(benchmark::State& state) {
  const long long targetTets = state.range(0);
  const ExampleSet set = static_cast<ExampleSet>(state.range(1));
  const SurfaceFiles& files = surfaceFiles(surfaceCellsFor(targetTets), set);
  TetGenOptions tetgenOptions;
  tetgenOptions.maxTetVolume = kBarVolume / (kMeanToMaxVolume * static_cast<double>(targetTets));
  tetgenOptions.sourceName = files.rest;

  double readMs = 0, validateMs = 0, tetgenMs = 0, embedMs = 0;
  long long tets = 0, refinedTets = 0, steiner = 0, surfaceFaces = 0, invertedLeft = 0,
            intersecting = 0, invertedIntersecting = 0;
  invertedIntersecting = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    const SurfaceMesh rest = readSurface(files.rest);
    std::vector<SurfaceMesh> examples;
    for (const std::string& path : files.examples) examples.push_back(readSurface(path));
    readMs = millisecondsSince(start);

    start = std::chrono::steady_clock::now();
    requireValidRest(rest, files.rest);
    for (int e = 0; e < kExampleCount; ++e) {
      requireCompatibleExample(rest, examples[e], files.examples[e]);
    }
    validateMs = millisecondsSince(start);

    start = std::chrono::steady_clock::now();
    const TetMesh restTets = tetrahedralize(rest, tetgenOptions);
    tetgenMs = millisecondsSince(start);

    // tetrahedralize keeps the input vertices first and in order, so the
    // surface vertices are rows 0..#S-1 as the builder requires.
    start = std::chrono::steady_clock::now();
    std::vector<Vertices> surfaces;
    for (const SurfaceMesh& example : examples) surfaces.push_back(example.vertices);
    const CompatibleTetMeshes built =
        buildCompatibleTetMeshes(restTets, static_cast<int>(rest.vertices.rows()), surfaces);
    embedMs = millisecondsSince(start);
    invertedLeft = 0;
    intersecting = 0;
    invertedIntersecting = 0;
    for (std::size_t k = 0; k < built.examples.size(); ++k) {
      if (built.selfIntersections[k].pairCount > 0) {
        ++intersecting;
        invertedIntersecting += static_cast<long long>(built.examples[k].invertedTets.size());
      } else {
        invertedLeft += static_cast<long long>(built.examples[k].invertedTets.size());
      }
    }
    refinedTets = built.rest.tets.rows();
    steiner = built.steinerPoints;

    tets = restTets.tets.rows();
    surfaceFaces = rest.triangles.rows();
    state.SetIterationTime((readMs + validateMs + tetgenMs + embedMs) / 1000.0);
  }
  state.counters["tets"] = static_cast<double>(tets);
  state.counters["tets_refined"] = static_cast<double>(refinedTets);
  state.counters["steiner"] = static_cast<double>(steiner);
  state.counters["surf_faces"] = static_cast<double>(surfaceFaces);
  state.counters["read_ms"] = readMs;
  state.counters["validate_ms"] = validateMs;
  state.counters["tetgen_ms"] = tetgenMs;
  state.counters["embed_ms"] = embedMs;
  state.counters["val+emb/tetgen"] = (validateMs + embedMs) / tetgenMs;
  state.counters["inverted_left"] = static_cast<double>(invertedLeft);
  state.counters["intersecting"] = static_cast<double>(intersecting);
  state.counters["inverted_intersecting"] = static_cast<double>(invertedIntersecting);
  state.counters["peak_rss_MB"] = peakRssMegabytes();
}

// Targets 10k, 100k and 1M tets (9.6k, 99k and 999k measured), second
// argument 0 = easy, 1 = hard examples. The 1M easy size alone takes about
// 20 s and 0.85 GB on 2 shared cores (most of it TetGen and the Cholesky
// factorisation); skip it with --benchmark_filter='/(10000|100000)/'.
BENCHMARK(BM_PrepareCompatibleMeshes)
    ->ArgsProduct({{10000, 100000, 1000000}, {kEasy, kHard}})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(1);

}  // namespace
}  // namespace tetblend
