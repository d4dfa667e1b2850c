#include "cli_common.h"

#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"

namespace tetblend::cli {

namespace fs = std::filesystem;

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace

double parseFiniteNumber(const std::string& text, const std::string& what) {
  const std::string t = trim(text);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) {
    throw InputError(what + ": '" + t + "' is not a finite number");
  }
  return value;
}

std::vector<double> parseWeights(const std::string& text, const std::string& what) {
  if (trim(text).empty()) throw InputError(what + ": give at least one weight, e.g. 0.5,0.5");
  std::vector<double> weights;
  for (const std::string& token : split(text, ','))
    weights.push_back(parseFiniteNumber(token, what));
  return weights;
}

std::vector<std::vector<double>> parseWeightKeys(const std::string& text, const std::string& what) {
  std::vector<std::vector<double>> keys;
  for (const std::string& key : split(text, ';')) keys.push_back(parseWeights(key, what));
  if (keys.empty()) throw InputError(what + ": give key weight vectors, e.g. \"0,0;1,0;0,1\"");
  return keys;
}

void requireWeightCount(const std::vector<double>& weights, std::size_t exampleCount,
                        const std::string& what) {
  if (weights.size() != exampleCount) {
    throw InputError(what + ": " + std::to_string(weights.size()) +
                     " weights given, the model has " + std::to_string(exampleCount) +
                     " examples (one weight per example)");
  }
}

std::string withExtension(const std::string& path, const std::string& extension) {
  return fs::path(path).replace_extension(extension).string();
}

std::string extensionOf(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void ensureDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(dir + ": cannot create the output directory (" + ec.message() + ")");
  }
}

void addQuietOption(CLI::App& command, bool& quiet) {
  command.add_flag("-q,--quiet", quiet,
                   "no progress bars (they are drawn only when stderr is a terminal anyway)");
}

void addThreadsOption(CLI::App& command, int& threads) {
  command
      .add_option("--threads", threads,
                  "worker threads; 0 = all cores, at most " + std::to_string(kMaxThreads))
      ->check(CLI::Range(0, kMaxThreads))
      ->capture_default_str();
}

ThreadLimit::ThreadLimit(int threads) {
  if (threads > 0) {
    control_ = std::make_shared<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                     static_cast<std::size_t>(threads));
  }
}

ThreadLimit::~ThreadLimit() = default;

int resolveThreads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void checkOutputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  for (const std::string& output : outputs) {
    const std::string reason = nonRegularOutputReason(output);
    if (!reason.empty()) throw InputError(output + ": " + reason + "; choose another output name");
    for (const std::string& input : inputs) {
      std::error_code ec;
      if (fs::equivalent(output, input, ec) && !ec) {
        throw InputError(output + ": is the same file as the input " + input +
                         "; writing it would destroy the input: choose another output name");
      }
    }
  }
}

std::string outOfMemoryMessage(const std::vector<std::string>& args) {
  std::string files;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "-o" || args[i] == "--output") {
      ++i;
      continue;
    }
    std::error_code ec;
    if (args[i].rfind("-", 0) != 0 && fs::is_regular_file(args[i], ec)) {
      files += (files.empty() ? "" : ", ") + args[i];
    }
  }
  const std::string command = args.empty() ? "tetblend" : "'tetblend " + args.front() + "'";
  return "out of memory in " + command + (files.empty() ? "" : " on " + files) +
         ": an input is damaged (a wrong count) or too large for this machine";
}

void printWarning(const std::string& line) {
  std::fprintf(stderr, "tetblend: warning: %s\n", line.c_str());
}

void printNote(const std::string& line, bool quiet) {
  if (!quiet) std::fprintf(stderr, "tetblend: %s\n", line.c_str());
}

}  // namespace tetblend::cli
