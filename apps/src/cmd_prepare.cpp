// tetblend prepare: surfaces in, model file out (prepare_model.h,
// model_file.h).

#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "prepare_options.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

namespace {

struct PrepareArgs {
  std::string rest;
  std::vector<std::string> examples;
  std::string output;
  PrepareSettings settings;
};

void runPrepare(const PrepareArgs& a) {
  std::vector<std::string> inputs = a.examples;
  inputs.push_back(a.rest);
  checkOutputs({a.output}, inputs);
  const ThreadLimit limit(a.settings.threads);
  PrepareMessages messages;
  messages.warning = printWarning;
  messages.note = [&](const std::string& line) { printNote(line, a.settings.quiet); };
  const ModelData model = prepareWithProgress(a.rest, a.examples, a.settings, messages);
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
      "animate read. Parametrisation and the stitch factorisation are redone on load.");
  cmd->add_option("REST", args->rest, "rest surface (.obj/.off/.ply/.stl/.vtp)")->required();
  cmd->add_option("EXAMPLE", args->examples, "example surfaces with the rest's triangles")
      ->required();
  cmd->add_option("-o,--output", args->output, "model file to write")->required();
  addPrepareOptions(*cmd, args->settings);
  addQuietOption(*cmd, args->settings.quiet);
  cmd->callback([args] { runPrepare(*args); });
}

}  // namespace tetblend::cli
