#include "batch_job_weights.h"

#include "cli_common.h"
#include "named_weights.h"
#include "tetblend/core/error.h"

namespace tetblend::cli {

namespace {

using nlohmann::json;

constexpr const char* kWeightsShapes =
    "give an array of one number per example, or an object of example names or 1-based "
    "indices and numbers";

// A weight of a job; JSON numbers are finite (the parser refuses 1e999).
double weightNumber(const json& value, const std::string& where) {
  if (!value.is_number()) {
    throw InputError(where + " is " + value.dump() + ": not a number; " + kWeightsShapes);
  }
  return value.get<double>();
}

}  // namespace

std::vector<double> jobWeights(const BatchJob& job, const std::vector<std::string>& sources,
                               const std::string& modelPath) {
  const std::string where = "\"weights\"";
  if (job.weights.is_object()) {
    std::vector<ExampleWeight> entries;
    for (const auto& [example, value] : job.weights.items()) {
      const std::string entry = where + ": \"" + example + "\"";
      entries.push_back({example, weightNumber(value, entry), entry});
    }
    return exampleWeights(entries, sources, modelPath);
  }
  if (!job.weights.is_array()) {
    throw InputError(where + " is " + job.weights.dump() + "; " + kWeightsShapes);
  }
  std::vector<double> weights;
  for (std::size_t k = 0; k < job.weights.size(); ++k) {
    weights.push_back(weightNumber(job.weights[k], where + "[" + std::to_string(k) + "]"));
  }
  requireWeightCount(weights, sources.size(), where);
  return weights;
}

std::string jobWeightsText(const BatchJob& job) {
  std::string text;
  const auto add = [&text](const std::string& item) { text += (text.empty() ? "" : " ") + item; };
  if (job.weights.is_object()) {
    for (const auto& [example, value] : job.weights.items()) add(example + "=" + value.dump());
  } else if (job.weights.is_array()) {
    for (const json& value : job.weights) add(value.dump());
  }
  return text;
}

}  // namespace tetblend::cli
