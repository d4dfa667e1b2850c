// tetblend prepare: surfaces in, model file out (prepare_model.h,
// model_file.h).

#include <iomanip>
#include <memory>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "prepare_options.h"
#include "tetblend/core/error.h"
#include "tetblend/pipeline/make_blender.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

namespace {

struct PrepareArgs {
  std::string rest;
  std::vector<std::string> examples;
  std::string output;
  PrepareSettings settings;
  bool fastLoad = false;
};

// --fast-load: the stitch factor and the kaji parameters kept in the model.
// A model whose cache cannot be made (say, its factorisation exceeds a memory
// limit) is still written, without it, so the preparation is not lost.
void addBlendCache(ModelData& model, const std::string& output, bool quiet) {
  try {
    model.blendCache = blendCacheOf(model);
  } catch (const Error& error) {
    printWarning(output + ": --fast-load: " + error.what() +
                 "; the model is written without its blend cache (it loads as a model prepared "
                 "without --fast-load)");
    return;
  }
  const auto megabytes = [](std::size_t doubles) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << 8.0 * static_cast<double>(doubles) / (1 << 20);
    return text.str();
  };
  printNote("fast load: the model keeps the stitch factor (" +
                megabytes(model.blendCache->factor.values.size()) +
                " MB) and the kaji parameters (" + megabytes(model.blendCache->kaji.params.size()) +
                " MB)",
            quiet);
}

void runPrepare(const PrepareArgs& a) {
  std::vector<std::string> inputs = a.examples;
  inputs.push_back(a.rest);
  checkOutputs({a.output}, inputs);
  const ThreadLimit limit(a.settings.threads);
  PrepareMessages messages;
  messages.warning = printWarning;
  messages.note = [&](const std::string& line) { printNote(line, a.settings.quiet); };
  ModelData model = prepareWithProgress(a.rest, a.examples, a.settings, messages);
  if (a.fastLoad) addBlendCache(model, a.output, a.settings.quiet);
  writeModelFile(a.output, model);
}

}  // namespace

void registerPrepare(CLI::App& root) {
  auto args = std::make_shared<PrepareArgs>();
  CLI::App* cmd = root.add_subcommand(
      "prepare",
      "Validate a rest surface and its examples (same vertices and faces), fill the rest with tets "
      "(TetGen, surface kept) or tetrise it, place each example's interior vertices so all "
      "share the rest's tets, and save the model file that blend, batch, variations and "
      "animate read. Parametrisation and the stitch factorisation are redone on load, unless "
      "--fast-load keeps them in the model.");
  cmd->add_option("REST", args->rest, "rest surface (.obj/.off/.ply/.stl/.vtp)")->required();
  cmd->add_option("EXAMPLE", args->examples, "example surfaces with the rest's triangles")
      ->required();
  cmd->add_option("-o,--output", args->output, "model file to write")->required();
  addPrepareOptions(*cmd, args->settings);
  cmd->add_flag("--fast-load", args->fastLoad,
                "also keep the stitch factor and the kaji parameters in the model (a file several "
                "times larger), so that every load skips the factorisation and, for kaji with "
                "rotation consistency, the parametrisation: a one-shot blend of a large model in "
                "a fraction of the time");
  addQuietOption(*cmd, args->settings.quiet);
  cmd->callback([args] { runPrepare(*args); });
}

}  // namespace tetblend::cli
