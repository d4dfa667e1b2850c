// tetblend variations: reproducible random shapes (weight_sampling.h) or
// principal-component variations in Kaji–Ochiai's parameter space
// (parameter_pca.h).

#include <cstdio>
#include <memory>

#include "blend_options.h"
#include "blend_series.h"
#include "cli_common.h"
#include "commands.h"
#include "tetblend/core/error.h"
#include "tetblend/pipeline/parameter_pca.h"
#include "tetblend/pipeline/weight_sampling.h"

namespace tetblend::cli {

namespace {

struct VariationsArgs {
  std::string model;
  std::string output;
  int count = 10;
  std::uint64_t seed = 1;
  double extrapolate = 0.0;
  bool pca = false;
  int components = 2;
  double range = 2.0;
  BlendSettings blend;
  int threads = 0;
  bool quiet = false;
};

std::string numbered(const std::string& prefix, int i) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%03d", i);
  return prefix + buffer;
}

std::vector<SeriesItem> pcaItems(const ModelData& model, const VariationsArgs& a) {
  if (a.count < 1) throw InputError("--count must be >= 1 with --pca");
  if (a.components < 1) throw InputError("--components must be >= 1");
  if (!(a.range > 0.0)) throw InputError("--range must be > 0");
  const bool consistent = parseOnOff(a.blend.consistency, "--consistency");
  const ParameterPca pca = modelPca(model, consistent);
  std::vector<SeriesItem> items;
  const auto toStd = [](const Eigen::VectorXd& v) {
    return std::vector<double>(v.data(), v.data() + v.size());
  };
  items.push_back({"pca_mean", toStd(pca.meanWeights), 0.0});
  const int used = std::min<int>(a.components, static_cast<int>(pca.steps.size()));
  for (int c = 0; c < used; ++c) {
    for (int i = 0; i < a.count; ++i) {
      const double t = a.count == 1 ? a.range : -a.range + 2.0 * a.range * i / (a.count - 1);
      const Eigen::VectorXd w = pca.meanWeights + t * pca.steps[static_cast<std::size_t>(c)];
      items.push_back({numbered("pc" + std::to_string(c + 1) + "_", i), toStd(w),
                       static_cast<double>(items.size())});
    }
  }
  return items;
}

void runVariations(const VariationsArgs& a) {
  const ModelData model = readModelFile(a.model);
  const ThreadLimit limit(a.threads);
  std::vector<SeriesItem> items;
  if (a.pca) {
    items = pcaItems(model, a);
  } else {
    const auto weights = sampleSimplexWeights(a.count, static_cast<int>(model.examples.size()),
                                              a.seed, a.extrapolate);
    for (int i = 0; i < a.count; ++i)
      items.push_back({numbered("variation_", i), weights[static_cast<std::size_t>(i)],
                       static_cast<double>(i)});
  }
  blendSeries(model, a.blend, items, a.output, "variations", {a.model}, a.quiet);
}

}  // namespace

void registerVariations(CLI::App& root) {
  auto args = std::make_shared<VariationsArgs>();
  CLI::App* cmd = root.add_subcommand(
      "variations",
      "Make shapes between (or beyond) the examples. Random (default): --count shapes whose "
      "barycentric coordinates (rest, example 1..n) are uniform on the simplex (Dirichlet(1)); "
      "--extrapolate X scales that simplex by 1+X about its centroid, so weights range over "
      "[-X/(n+1), 1+Xn/(n+1)]; the same --seed gives the same shapes everywhere. --pca: the "
      "mean and --count shapes from -range to +range standard deviations along each of the "
      "first --components principal components of the rest and examples in Kaji-Ochiai's "
      "parameter space (Euclidean, so means and components are meaningful; exact for --method "
      "kaji). Writes DIR/<name>.vtu/.vtp, DIR/variations.pvd and DIR/weights.csv.");
  cmd->add_option("MODEL", args->model, "model file made by 'tetblend prepare'")->required();
  cmd->add_option("-o,--output", args->output, "output directory (created if missing)")->required();
  cmd->add_option("-n,--count", args->count, "shapes (per component with --pca)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed")->capture_default_str();
  cmd->add_option("--extrapolate", args->extrapolate, "widen the weight simplex by this factor")
      ->capture_default_str();
  cmd->add_flag("--pca", args->pca, "principal-component variations instead of random ones");
  cmd->add_option("--components", args->components, "principal components used with --pca")
      ->capture_default_str();
  cmd->add_option("--range", args->range, "standard deviations either side with --pca")
      ->capture_default_str();
  addBlendOptions(*cmd, args->blend);
  addThreadsOption(*cmd, args->threads);
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runVariations(*args); });
}

}  // namespace tetblend::cli
