#include "weight_options.h"

#include "cli_common.h"

namespace tetblend::cli {

void addWeightOptions(CLI::App& command, WeightOptions& options) {
  CLI::Option_group* group = command.add_option_group(
      "Weights", "exactly one of -w/--weights (every example) or --weight (some examples)");
  group->add_option("-w,--weights", options.dense,
                    "comma-separated weights, one per example: 0.2,0,0.5");
  group
      ->add_option("--weight", options.sparse,
                   "NAME_OR_INDEX=VALUE: the weight of one example, named by its file name "
                   "without folder and extension (frame012=0.5), by its source as 'tetblend "
                   "inspect' shows it, or by its 1-based index (3=0.25); repeat for more "
                   "examples; the others get 0")
      ->allow_extra_args(false);
  group->require_option(1);
}

GivenWeights parseWeightOptions(const WeightOptions& options) {
  GivenWeights given;
  if (options.sparse.empty()) given.dense = parseWeights(options.dense, "--weights");
  for (const std::string& entry : options.sparse) {
    given.sparse.push_back(parseExampleWeight(entry, "--weight " + entry));
  }
  return given;
}

std::vector<double> weightsForExamples(const GivenWeights& given,
                                       const std::vector<std::string>& sources,
                                       const std::string& modelPath) {
  if (!given.sparse.empty()) return exampleWeights(given.sparse, sources, modelPath);
  requireWeightCount(given.dense, sources.size(), "--weights");
  return given.dense;
}

std::string weightsText(const WeightOptions& options) {
  if (options.sparse.empty()) return options.dense;
  std::string text;
  for (const std::string& entry : options.sparse) text += (text.empty() ? "" : " ") + entry;
  return text;
}

}  // namespace tetblend::cli
