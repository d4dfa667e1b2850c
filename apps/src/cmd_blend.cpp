// tetblend blend: one blended shape from a model (or straight from surface
// files) at one weight vector.

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "blend_options.h"
#include "blend_output.h"
#include "cli_common.h"
#include "commands.h"
#include "prepare_options.h"
#include "progress.h"
#include "quality_arrays.h"
#include "tetblend/core/error.h"
#include "tetblend/pipeline/blended_shape.h"
#include "tetblend/pipeline/make_blender.h"
#include "weight_options.h"

namespace tetblend::cli {

namespace {

// Slack on Σ w ≤ 1: weights read from decimal text (0.1,0.2,0.7) sum to 1
// only to rounding, a few units of 1e-16.
constexpr double kWeightSumSlack = 1e-12;

// Whether an example's weight or the rest's, 1 − Σ w, lies outside [0, 1].
bool extrapolates(const std::vector<double>& weights) {
  double sum = 0.0;
  for (double w : weights) {
    if (w < 0.0 || w > 1.0) return true;
    sum += w;
  }
  return sum > 1.0 + kWeightSumSlack;
}

// The parenthesis of blend's warning about inverted tets: the cell arrays
// `written` to the .vtu that mark them, how many are tets left out of the
// stitch, and whether the weights extrapolate.
std::string invertedWhy(const BlendedShape& shape, const std::vector<double>& weights,
                        const std::vector<NamedArray>& written) {
  const auto has = [&](const std::string& name) {
    return std::any_of(written.begin(), written.end(),
                       [&](const NamedArray& array) { return array.name == name; });
  };
  std::vector<std::string> parts;
  if (has("inverted")) parts.emplace_back("cell array 'inverted'");
  if (shape.invertedExcluded > 0) {
    parts.push_back(std::to_string(shape.invertedExcluded) +
                    " of them are left out of the stitch, since some example cannot embed them" +
                    (has("excluded") ? ": cell array 'excluded'" : ""));
  }
  if (extrapolates(weights)) parts.emplace_back("weights outside [0, 1] extrapolate");
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? " (" : "; ") + part;
  return text.empty() ? text : text + ")";
}

struct BlendArgs {
  std::string model;
  std::string rest;
  std::vector<std::string> examples;
  WeightOptions weights;
  std::string output;
  BlendSettings blend;
  PrepareSettings prepare;
};

void runBlend(const BlendArgs& a) {
  const bool fromModel = !a.model.empty();
  if (fromModel == !a.rest.empty()) {
    throw InputError("give either a MODEL file or --rest with --example files, not both");
  }
  if (!fromModel && a.examples.empty()) throw InputError("--rest needs at least one --example");
  checkBlendOutputPath(a.output, "-o");
  const QualityArrays arrays = parseQualityArrays(a.blend.qualityArrays, "--quality-arrays");
  if (extensionOf(a.output) == ".vtp" && !arrays.all && !arrays.names.empty()) {
    throw InputError("--quality-arrays " + a.blend.qualityArrays + ": -o " + a.output +
                     " writes the surface only, which has no per-tet arrays; write a .vtu");
  }
  const GivenWeights given = parseWeightOptions(a.weights);
  const BlendMethod method = parseMethod(a.blend.method);
  const std::vector<std::string> formats = parseSurfaceFormats(a.blend.surfaceFormats);
  const VtkCompression compression =
      parseVtkCompression(a.blend.compression, a.blend.compressionLevel, "--compression");
  std::vector<std::string> inputs = a.examples;
  inputs.push_back(fromModel ? a.model : a.rest);
  checkOutputs(blendOutputFiles(a.output, formats), inputs);
  const ThreadLimit limit(a.prepare.threads);

  PrepareMessages messages;
  messages.warning = printWarning;
  // Surfaces prepared here are named by the --example paths: bad weights fail before TetGen.
  std::vector<double> weights =
      fromModel ? std::vector<double>{} : weightsForExamples(given, a.examples, "");
  const ModelData model = fromModel ? readModelFile(a.model)
                                    : prepareWithProgress(a.rest, a.examples, a.prepare, messages);
  if (fromModel) weights = weightsForExamples(given, model.exampleSources, a.model);
  ProgressBar progress("blend", 3, a.prepare.quiet);
  const QualityFigures figures = qualityFigures(arrays, extensionOf(a.output) == ".vtu");
  const ShapeBlender blender =
      makeBlender(model, {method}, parseOnOff(a.blend.consistency, "--consistency"),
                  a.blend.nonlinear, figures.targetResidual);
  progress.advance();
  const BlendedShape shape = blendShape(blender, model, weights, method, figures);
  progress.advance();
  const std::vector<NamedArray> written =
      extensionOf(a.output) == ".vtu"
          ? selectQualityArrays(shape.cellData, arrays, "--quality-arrays")
          : std::vector<NamedArray>{};
  writeBlendResult(a.output, model, shape.vertices, written, formats, compression);
  progress.advance();
  progress.finish();
  if (shape.quality.invertedCount > 0) {
    printWarning(a.output + ": " + std::to_string(shape.quality.invertedCount) + " of " +
                 std::to_string(model.rest.tets.rows()) + " tets are inverted at weights " +
                 weightsText(a.weights) + invertedWhy(shape, weights, written));
  }
}

}  // namespace

void registerBlend(CLI::App& root) {
  auto args = std::make_shared<BlendArgs>();
  CLI::App* cmd = root.add_subcommand(
      "blend",
      "Blend the examples at one weight vector. Writes the tets to OUT.vtu (point data "
      "'displacement' from the rest; cell data: per-tet quality, see --quality-arrays) and the "
      "surface, in the rest surface's vertex order, to OUT.vtp beside it; -o OUT.vtp writes the "
      "surface only. Weights: any reals, given for every example (-w) or for some by name or "
      "index (--weight; the others get 0); the rest has weight 1 - sum(w), so all zeros give "
      "the rest and a unit vector an example.");
  cmd->add_option("MODEL", args->model, "model file made by 'tetblend prepare'");
  cmd->add_option("--rest", args->rest, "rest surface (instead of MODEL; prepared on the fly)");
  cmd->add_option("--example", args->examples,
                  "example surface with the rest's triangles (repeat for each example)");
  addWeightOptions(*cmd, args->weights);
  cmd->add_option("-o,--output", args->output,
                  "output .vtu file (the .vtp goes beside it), or .vtp for the surface only")
      ->required();
  addBlendOptions(*cmd, args->blend);
  addPrepareOptions(*cmd, args->prepare);
  addQuietOption(*cmd, args->prepare.quiet);
  cmd->callback([args] { runBlend(*args); });
}

}  // namespace tetblend::cli
