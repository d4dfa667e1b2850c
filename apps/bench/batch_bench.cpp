// bench_batch: wall time of `tetblend batch` runs of N kaji blends of one
// model, reported per 1000 jobs, for several tetblend executables and spec
// variants measured in one run, interleaved (repeat r runs every variant with
// every executable before repeat r + 1), so a baseline and a new build see the
// same load. Each run writes into a fresh folder that is removed afterwards.
//
// Usage:
//   bench_batch MODEL.tbm [--jobs 100] [--repeats 3] [--threads 2]
//               [--exe PATH]... [--variant NAME=JSON]... [--scratch DIR]
// --exe defaults to the tetblend built beside this program; the first one is
// the baseline of the ratios. --variant adds JSON entries to the spec
// (default: full={} and surface={"surface_only":true}); keys an older build
// does not know are ignored by it. Weights are 3 per job (the model must have
// 3 examples), deterministic, in [0, 1].
//
// Output: one line per run (variant, exe, wall seconds, wall and CPU (user +
// system, of the batch process) seconds per 1000 jobs, MB per job, load
// average before the run), then per variant and exe the medians per 1000
// jobs and the wall median's ratio to the first exe's. On a loaded machine
// the CPU time is the steadier figure; CPU / 2 bounds the wall time of the
// 2 cores from below.

#include <sys/resource.h>
#include <sys/wait.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Options {
  std::string model;
  int jobs = 100;
  int repeats = 3;
  int threads = 2;
  std::vector<std::string> exes;
  std::vector<std::pair<std::string, json>> variants;
  std::string scratch = (fs::temp_directory_path() / "tetblend_bench_batch").string();
};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "bench_batch: " << why
            << "\nusage: bench_batch MODEL.tbm [--jobs N] [--repeats R] [--threads T] "
               "[--exe PATH]... [--variant NAME=JSON]... [--scratch DIR]\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--jobs") {
      o.jobs = std::stoi(value());
    } else if (arg == "--repeats") {
      o.repeats = std::stoi(value());
    } else if (arg == "--threads") {
      o.threads = std::stoi(value());
    } else if (arg == "--exe") {
      o.exes.push_back(fs::absolute(value()).string());
    } else if (arg == "--scratch") {
      o.scratch = value();
    } else if (arg == "--variant") {
      const std::string v = value();
      const std::size_t eq = v.find('=');
      if (eq == std::string::npos) usage("--variant wants NAME=JSON");
      o.variants.emplace_back(v.substr(0, eq), json::parse(v.substr(eq + 1)));
    } else if (o.model.empty() && arg.rfind("--", 0) != 0) {
      o.model = fs::absolute(arg).string();
    } else {
      usage("unknown argument " + arg);
    }
  }
  if (o.model.empty()) usage("give the model file");
  if (o.jobs < 1 || o.repeats < 1) usage("--jobs and --repeats must be positive");
  if (o.exes.empty()) o.exes.push_back(TETBLEND_EXE);
  if (o.variants.empty()) {
    o.variants = {{"full", json::object()}, {"surface", {{"surface_only", true}}}};
  }
  return o;
}

/// 3 weights per job in [0, 1] from a fixed linear congruential sequence.
json jobList(int count) {
  json jobs = json::array();
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  for (int i = 0; i < count; ++i) {
    const std::string name = "job" + std::to_string(i);
    jobs.push_back({{"name", name}, {"weights", {next(), next(), next()}}});
  }
  return jobs;
}

double loadAverage() {
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  in >> load;
  return load;
}

std::uintmax_t folderBytes(const fs::path& dir) {
  std::uintmax_t bytes = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) bytes += e.file_size();
  return bytes;
}

/// User + system seconds of the finished child processes so far.
double childCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  fs::create_directories(o.scratch);
  const json jobs = jobList(o.jobs);
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> perThousand, cpuPerThousand;
  std::cout << std::fixed << std::setprecision(2);
  for (int r = 0; r < o.repeats; ++r) {
    for (std::size_t v = 0; v < o.variants.size(); ++v) {
      for (std::size_t e = 0; e < o.exes.size(); ++e) {
        const fs::path out = fs::path(o.scratch) / "out";
        fs::remove_all(out);
        json spec{{"model", o.model},
                  {"output_dir", out.string()},
                  {"threads", o.threads},
                  {"jobs", jobs}};
        spec.update(o.variants[v].second);
        const fs::path specPath = fs::path(o.scratch) / "spec.json";
        std::ofstream(specPath) << spec.dump();
        const std::string command =
            "'" + o.exes[e] + "' batch '" + specPath.string() + "' --quiet > /dev/null";
        const double load = loadAverage();
        const double cpuBefore = childCpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        const int status = std::system(command.c_str());
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
          std::cerr << "bench_batch: failed: " << command << "\n";
          return 1;
        }
        const double cpu = (childCpuSeconds() - cpuBefore) * 1000.0 / o.jobs;
        cpuPerThousand[{v, e}].push_back(cpu);
        const double mbPerJob = static_cast<double>(folderBytes(out)) / 1e6 / o.jobs;
        fs::remove_all(out);
        const double thousand = seconds * 1000.0 / o.jobs;
        perThousand[{v, e}].push_back(thousand);
        std::cout << "run " << r << " " << o.variants[v].first << " exe" << e << ": " << seconds
                  << " s, " << thousand << " s per 1000 jobs (CPU " << cpu << " s), " << mbPerJob
                  << " MB per job, load " << load << std::endl;
      }
    }
  }
  for (std::size_t e = 0; e < o.exes.size(); ++e)
    std::cout << "exe" << e << " = " << o.exes[e] << "\n";
  std::cout << "| variant | exe | median wall s per 1000 jobs | ratio to exe0 | median CPU s per "
               "1000 jobs |\n|---|---|---|---|---|\n";
  for (std::size_t v = 0; v < o.variants.size(); ++v) {
    const double base = median(perThousand[{v, 0}]);
    for (std::size_t e = 0; e < o.exes.size(); ++e) {
      const double m = median(perThousand[{v, e}]);
      std::cout << "| " << o.variants[v].first << " " << o.variants[v].second.dump() << " | exe"
                << e << " | " << m << " | " << m / base << " | " << median(cpuPerThousand[{v, e}])
                << " |\n";
    }
  }
  return 0;
}
