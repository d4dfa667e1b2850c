#include "prepare_options.h"

#include "cli_common.h"
#include "progress.h"

namespace tetblend::cli {

void addPrepareOptions(CLI::App& command, PrepareSettings& settings) {
  command
      .add_option("--quality", settings.radiusEdgeRatio,
                  "TetGen quality bound: max circumradius / shortest edge of a tet (> 1; 0 = no "
                  "refinement)")
      ->capture_default_str();
  command
      .add_option("--max-volume", settings.maxVolume,
                  "TetGen volume bound per tet, in mesh units cubed (default: none; the quality "
                  "bound grades the interior from the surface inwards, and the examples refine "
                  "it where they need it)")
      ->check(CLI::NonNegativeNumber);
  command.add_flag(
      "--tetrise", settings.tetrise,
      "one tet per surface triangle (apex along the normal) instead of TetGen: for "
      "open surfaces, without filling their holes and with no interior tets (default: off)");
  command.add_flag_callback(
      "--no-fill-holes", [&settings] { settings.fillHoles = false; },
      "refuse an open rest surface (default: its holes are closed by triangles between its "
      "boundary vertices, no new vertices, before TetGen runs; the blended surfaces keep the "
      "input's faces)");
  command.add_flag("--strict", settings.strict,
                   "refuse an example whose surface folds or intersects itself so that some tets "
                   "cannot be embedded, a rest that intersects itself, and parts of the rest that "
                   "cannot be filled with tets (default: off; such tets are reported and left out "
                   "of the stitch, the rest is meshed on a separated copy, and those parts get one "
                   "tet per face)");
  addThreadsOption(command, settings.threads);
}

ModelData prepareWithProgress(const std::string& restPath,
                              const std::vector<std::string>& examplePaths,
                              const PrepareSettings& settings, PrepareMessages messages) {
  ProgressBar progress("prepare", prepareStepCount(examplePaths.size()), settings.quiet);
  messages.step = [&progress](std::size_t steps) { progress.advance(steps); };
  return prepareModel(restPath, examplePaths, settings, messages);
}

}  // namespace tetblend::cli
