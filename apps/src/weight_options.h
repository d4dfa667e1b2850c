#pragma once
// The weight vector of one blend on the command line, given either densely,
// -w/--weights 0.2,0,0.5 (one value per example), or sparsely, --weight
// NAME_OR_INDEX=VALUE, repeatable (named_weights.h; the examples not named
// get 0). Exactly one of the two options is required.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "named_weights.h"

namespace tetblend::cli {

/// The weight options as given.
struct WeightOptions {
  std::string dense;                ///< -w/--weights, "" when not given
  std::vector<std::string> sparse;  ///< each --weight NAME_OR_INDEX=VALUE
};

/// Adds -w/--weights and the repeatable --weight to `command`, in an option
/// group that requires exactly one of them.
void addWeightOptions(CLI::App& command, WeightOptions& options);

/// The weight options parsed, before the examples are known.
struct GivenWeights {
  std::vector<double> dense;          ///< -w's values (empty with --weight)
  std::vector<ExampleWeight> sparse;  ///< --weight's entries (empty with -w)
};

/// Parses the values and the NAME=VALUE syntax; InputError naming the
/// option for a bad number or entry.
GivenWeights parseWeightOptions(const WeightOptions& options);

/// One weight per example of `sources` (ModelData::exampleSources).
/// InputError for a -w list of another length, and as exampleWeights for
/// --weight; `modelPath` ("" for surfaces prepared on the fly) is named in
/// the hint of an unknown name.
std::vector<double> weightsForExamples(const GivenWeights& given,
                                       const std::vector<std::string>& sources,
                                       const std::string& modelPath);

/// The weights as given, for messages: "0.5,0" (-w) or "a=0.5 2=1" (--weight).
std::string weightsText(const WeightOptions& options);

}  // namespace tetblend::cli
