#pragma once
// The command line's side of prepare: the meshing options as flags, and
// prepareModel (pipeline/prepare_model.h) run with a progress bar.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tetblend/pipeline/prepare_model.h"

namespace tetblend::cli {

/// prepare's options on the command line: the meshing options with the
/// run's thread count and --quiet.
struct PrepareSettings : PrepareOptions {
  int threads = 0;     ///< worker threads; 0 = all cores
  bool quiet = false;  ///< no progress bar
};

/// Adds --quality, --max-volume, --tetrise, --no-fill-holes, --strict and --threads to
/// `command`.
void addPrepareOptions(CLI::App& command, PrepareSettings& settings);

/// prepareModel with a "prepare" progress bar on stderr (unless
/// settings.quiet); `messages.step` is replaced by the bar's.
ModelData prepareWithProgress(const std::string& restPath,
                              const std::vector<std::string>& examplePaths,
                              const PrepareSettings& settings, PrepareMessages messages);

}  // namespace tetblend::cli
