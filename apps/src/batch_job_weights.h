#pragma once
// The "weights" of a batch job (batch_spec.h), checked when the job runs so
// that a bad job fails alone: an array of one number per example, or an
// object of some examples' weights, {"frame012": 0.5, "3": 0.25}, keyed as
// --weight names examples (named_weights.h; the others get 0).

#include <string>
#include <vector>

#include "batch_spec.h"

namespace tetblend::cli {

/// The weights of `job`, one per example of a model whose examples are
/// recorded as `sources` (ModelData::exampleSources), read from `modelPath`.
/// InputError for weights that are neither an array of one number per
/// example nor an object of numbers keyed by example (exampleWeights).
std::vector<double> jobWeights(const BatchJob& job, const std::vector<std::string>& sources,
                               const std::string& modelPath);

/// The weights of `job` as one text field of summary.csv: "0.5 0" for an
/// array, "3=0.25 frame012=0.5" for an object.
std::string jobWeightsText(const BatchJob& job);

}  // namespace tetblend::cli
