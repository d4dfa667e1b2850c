// bench_model_load: the cold start of a prepared model, what a one-shot
// `tetblend blend MODEL` does before writing: read the model file, build its
// blender (kaji, rotation consistency on) and blend once. Measured for the
// model as given (its blender factors the stitch and parametrises the
// examples) and for the same model with its blend cache (what `prepare
// --fast-load` writes; made once, into a temporary file, before the timing),
// both in every iteration, so the ratio compares them under the same load.
// The files are read from the page cache (the first iteration warms it).
//
// Usage: bench_model_load --model PATH.tbm [Google Benchmark flags]
// Counters (means over the iterations):
//   plain_s, fast_s        read + blender + one blend, seconds
//   read_plain_s, read_fast_s   the file read (and checksum) alone
//   x_fast                 fast_s / plain_s
//   plain_MB, fast_MB      the two files' sizes
//   tets                   the model's tets

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_options.h"
#include "tetblend/pipeline/blended_shape.h"
#include "tetblend/pipeline/make_blender.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string& modelPath() {
  static std::string path;
  return path;
}

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Read, blender, one blend at equal weights; returns the read's seconds.
double coldStart(const std::string& path, double& totalSeconds) {
  const auto start = Clock::now();
  const ModelData model = readModelFile(path);
  const double read = secondsSince(start);
  const ShapeBlender blender = makeBlender(model, {BlendMethod::kKaji}, true, false, false);
  const std::vector<double> weights(model.examples.size(), 1.0 / (model.examples.size() + 1.0));
  const BlendedShape shape = blendShape(blender, model, weights, BlendMethod::kKaji);
  benchmark::DoNotOptimize(shape.vertices.data());
  totalSeconds = secondsSince(start);
  return read;
}

void coldStartBenchmark(benchmark::State& state) {
  const fs::path fast = fs::temp_directory_path() / "tetblend_bench_model_load_fast.tbm";
  ModelData model = readModelFile(modelPath());
  model.blendCache = blendCacheOf(model);
  writeModelFile(fast.string(), model);
  const auto tets = static_cast<double>(model.rest.tets.rows());
  model = ModelData{};
  double plain = 0.0, fastTotal = 0.0, readPlain = 0.0, readFast = 0.0;
  for (auto _ : state) {
    double seconds = 0.0;
    readPlain += coldStart(modelPath(), seconds);
    plain += seconds;
    readFast += coldStart(fast.string(), seconds);
    fastTotal += seconds;
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["plain_s"] = plain / n;
  state.counters["fast_s"] = fastTotal / n;
  state.counters["read_plain_s"] = readPlain / n;
  state.counters["read_fast_s"] = readFast / n;
  state.counters["x_fast"] = fastTotal / plain;
  state.counters["plain_MB"] = static_cast<double>(fs::file_size(modelPath())) / 1e6;
  state.counters["fast_MB"] = static_cast<double>(fs::file_size(fast)) / 1e6;
  state.counters["tets"] = tets;
  fs::remove(fast);
}

}  // namespace
}  // namespace tetblend

int main(int argc, char** argv) {
  tetblend::modelPath() = tetblend::bench::takeOption(argc, argv, "model");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (tetblend::modelPath().empty()) {
    std::fprintf(stderr, "bench_model_load: give --model PATH.tbm (a prepared model)\n");
    return 2;
  }
  benchmark::RegisterBenchmark("cold_start", tetblend::coldStartBenchmark)
      ->Iterations(5)
      ->Unit(benchmark::kSecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
