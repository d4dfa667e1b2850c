// tetblend animate: a time series through key weight vectors
// (weight_spline.h; Kaji–Ochiai §6.3).

#include <cstdio>
#include <memory>

#include "blend_series.h"
#include "cli_common.h"
#include "commands.h"
#include "weight_spline.h"

namespace tetblend::cli {

namespace {

struct AnimateArgs {
  std::string model;
  std::string keys;
  std::string output;
  int frames = 24;
  std::string spline = "catmull-rom";
  double duration = 1.0;
  BlendSettings blend;
  int threads = 0;
  bool quiet = false;
};

void runAnimate(const AnimateArgs& a) {
  const auto keys = parseWeightKeys(a.keys, "--keys");
  const auto frames = splineFrames(keys, a.frames, parseSplineKind(a.spline));
  const ModelData model = readModelFile(a.model);
  const ThreadLimit limit(a.threads);
  std::vector<SeriesItem> items;
  for (int f = 0; f < a.frames; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", f);
    const double t = a.frames == 1 ? 0.0 : a.duration * f / (a.frames - 1);
    items.push_back({name, frames[static_cast<std::size_t>(f)], t});
  }
  blendSeries(model, a.blend, items, a.output, "animation", {a.model}, a.quiet);
}

}  // namespace

void registerAnimate(CLI::App& root) {
  auto args = std::make_shared<AnimateArgs>();
  CLI::App* cmd = root.add_subcommand(
      "animate",
      "Animate through key weight vectors (Kaji-Ochiai 6.3): a spline through the keys in "
      "weight space, which for kaji is the same spline of the per-tet parameters (Blend is "
      "linear in the weights). Frames are spread evenly from the first key to the last. Writes "
      "DIR/frame_NNNN.vtu/.vtp, DIR/animation.pvd (times 0..--duration) and DIR/weights.csv.");
  cmd->add_option("MODEL", args->model, "model file made by 'tetblend prepare'")->required();
  cmd->add_option("--keys", args->keys,
                  "key weight vectors, ';' between keys, ',' between weights: \"0,0;1,0;0,1\"")
      ->required();
  cmd->add_option("-f,--frames", args->frames, "number of frames")->capture_default_str();
  cmd->add_option("--spline", args->spline,
                  "linear (through keys), catmull-rom (C1, through keys), bspline (C2, "
                  "approximating; starts and ends on the end keys)")
      ->capture_default_str();
  cmd->add_option("--duration", args->duration, "time of the last frame in the .pvd")
      ->capture_default_str();
  cmd->add_option("-o,--output", args->output, "output directory (created if missing)")->required();
  addBlendOptions(*cmd, args->blend);
  addThreadsOption(*cmd, args->threads);
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runAnimate(*args); });
}

}  // namespace tetblend::cli
