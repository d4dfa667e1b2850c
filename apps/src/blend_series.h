#pragma once
// Blending a list of weight vectors into one folder with a .pvd collection:
// the common tail of `tetblend variations` and `tetblend animate`.

#include <string>
#include <vector>

#include "blend_options.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

/// One shape of a series.
struct SeriesItem {
  std::string name;             ///< file stem, e.g. "variation_003"
  std::vector<double> weights;  ///< one per example
  double time = 0.0;            ///< its time in the .pvd
};

/// Blends every item with `settings` (method, consistency, nonlinear, quality
/// arrays) on a blender built once, writes <dir>/<name>.vtu and .vtp
/// (+ surface formats) per item, <dir>/<collection>.pvd of all of them and
/// <dir>/weights.csv (name, time, weights). Shows a progress bar unless
/// `quiet`; ends with one warning line when some shapes have inverted tets.
/// Refuses, before blending, outputs that are one of `inputs` or not regular
/// files (checkOutputs).
void blendSeries(const ModelData& model, const BlendSettings& settings,
                 const std::vector<SeriesItem>& items, const std::string& dir,
                 const std::string& collection, const std::vector<std::string>& inputs, bool quiet);

}  // namespace tetblend::cli
