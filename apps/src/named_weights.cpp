#include "named_weights.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <limits>
#include <optional>

#include "cli_common.h"
#include "tetblend/core/error.h"

namespace tetblend::cli {

namespace {

// Names quoted when a name is unknown; `tetblend inspect` lists them all.
constexpr std::size_t kListedNames = 5;

std::string stemOf(const std::string& source) {
  return std::filesystem::path(source).stem().string();
}

// "3 (poses/frame002.obj)": the 1-based index and the source of example k.
std::string describe(std::size_t k, const std::vector<std::string>& sources) {
  return std::to_string(k + 1) + " (" + sources[k] + ")";
}

std::string describeAll(const std::vector<std::size_t>& examples,
                        const std::vector<std::string>& sources) {
  std::string text;
  for (std::size_t k : examples) text += (text.empty() ? "" : ", ") + describe(k, sources);
  return text;
}

// The examples whose whole source is `key` or, when none is, whose stem is.
std::vector<std::size_t> examplesNamed(const std::string& key,
                                       const std::vector<std::string>& sources) {
  std::vector<std::size_t> whole, stem;
  for (std::size_t k = 0; k < sources.size(); ++k) {
    if (sources[k] == key) whole.push_back(k);
    if (stemOf(sources[k]) == key) stem.push_back(k);
  }
  return whole.empty() ? stem : whole;
}

// The number a key of digits spells (the largest size_t when it overflows);
// nothing for any other key.
std::optional<std::size_t> indexSpelled(const std::string& key) {
  const auto digit = [](unsigned char c) { return std::isdigit(c) != 0; };
  if (key.empty() || !std::all_of(key.begin(), key.end(), digit)) return std::nullopt;
  std::size_t index = 0;
  const auto result = std::from_chars(key.data(), key.data() + key.size(), index);
  return result.ec == std::errc() ? index : std::numeric_limits<std::size_t>::max();
}

std::string indexRange(const std::vector<std::string>& sources) {
  return "1.." + std::to_string(sources.size());
}

[[noreturn]] void throwUnknown(const std::string& key, const std::vector<std::string>& sources,
                               const std::string& where, const std::string& modelPath) {
  std::string names;
  for (std::size_t k = 0; k < std::min(sources.size(), kListedNames); ++k)
    names += (k == 0 ? "" : ", ") + stemOf(sources[k]);
  if (sources.size() > kListedNames) names += ", ...";
  std::string message = where + ": no example is named '" + key + "'; examples: " + names + " (" +
                        std::to_string(sources.size()) +
                        " in all; give a file name without folder and extension, a whole source "
                        "or an index " +
                        indexRange(sources) + ")";
  if (!modelPath.empty()) message += "; 'tetblend inspect " + modelPath + "' lists them all";
  if (key.find('=') != std::string::npos) {
    message += "; give each example its own --weight (--weight 1=0.5 --weight 3=0.25)";
  }
  throw InputError(message);
}

}  // namespace

ExampleWeight parseExampleWeight(const std::string& text, const std::string& where) {
  const std::size_t equals = text.rfind('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError(where + ": give NAME_OR_INDEX=VALUE, e.g. frame012=0.5 or 3=0.25");
  }
  return {text.substr(0, equals), parseFiniteNumber(text.substr(equals + 1), where), where};
}

std::size_t findExample(const std::string& key, const std::vector<std::string>& sources,
                        const std::string& where, const std::string& modelPath) {
  const std::vector<std::size_t> named = examplesNamed(key, sources);
  if (const std::optional<std::size_t> index = indexSpelled(key)) {
    const bool inRange = *index >= 1 && *index <= sources.size();
    if (named.empty()) {
      if (inRange) return *index - 1;
      throw InputError(where + ": there is no example " + key + "; the examples are numbered " +
                       indexRange(sources) + " (as 'tetblend inspect' counts them)");
    }
    if (inRange && named != std::vector<std::size_t>{*index - 1}) {
      throw InputError(where + ": '" + key + "' is the index of example " +
                       describe(*index - 1, sources) + " and also names example" +
                       (named.size() > 1 ? "s " : " ") + describeAll(named, sources) +
                       "; give the whole source of the one you mean");
    }
  }
  if (named.empty()) throwUnknown(key, sources, where, modelPath);
  if (named.size() > 1) {
    throw InputError(where + ": '" + key + "' names " + std::to_string(named.size()) +
                     " examples, " + describeAll(named, sources) +
                     "; give the index of the one you mean instead");
  }
  return named.front();
}

std::vector<double> exampleWeights(const std::vector<ExampleWeight>& entries,
                                   const std::vector<std::string>& sources,
                                   const std::string& modelPath) {
  std::vector<double> weights(sources.size(), 0.0);
  std::vector<const ExampleWeight*> givenBy(sources.size(), nullptr);
  for (const ExampleWeight& entry : entries) {
    const std::size_t k = findExample(entry.example, sources, entry.where, modelPath);
    if (givenBy[k] != nullptr) {
      throw InputError(entry.where + ": example " + describe(k, sources) +
                       " already has a weight, from " + givenBy[k]->where);
    }
    givenBy[k] = &entry;
    weights[k] = entry.weight;
  }
  return weights;
}

}  // namespace tetblend::cli
