#include "tetblend/pipeline/blended_shape.h"

#include <cmath>
#include <limits>

#include "tetblend/core/error.h"
#include "tetblend/pipeline/format_number.h"

namespace tetblend {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

NamedArray cellArray(const std::string& name, const std::vector<double>& values) {
  return NamedArray{name, 1, values};
}

// The blended maps of the stitched tets spread over all the model's tets, NaN
// for the excluded ones (empty stays empty: no maps).
std::vector<Eigen::Matrix3d> targetsOfAllTets(const ModelData& model,
                                              const std::vector<Eigen::Matrix3d>& stitched) {
  if (stitched.empty()) return {};
  std::vector<Eigen::Matrix3d> all(static_cast<std::size_t>(model.rest.tets.rows()),
                                   Eigen::Matrix3d::Constant(kNaN));
  std::size_t next = 0;  // model.excludedTets is ascending
  std::size_t kept = 0;
  for (std::size_t t = 0; t < all.size(); ++t) {
    if (next < model.excludedTets.size() && model.excludedTets[next] == static_cast<int>(t)) {
      ++next;
      continue;
    }
    all[t] = stitched[kept++];
  }
  return all;
}

}  // namespace

RestTetData modelRestData(const ModelData& model) {
  return restTetData(model.rest, model.excludedTets);
}

BlendResult checkedBlend(const ShapeBlender& blender, const std::vector<double>& weights,
                         BlendMethod method) {
  std::string list;
  for (double w : weights) list += (list.empty() ? "" : ",") + formatNumber(w);
  BlendResult result;
  try {
    result = blender.blend(weights, method);
  } catch (const DomainError& e) {
    throw DomainError("weights " + list + ": " + e.what());
  }
  if (!result.vertices.allFinite()) {
    throw InputError("weights " + list +
                     ": the blend is not finite (weights this large overflow the blended maps); "
                     "use weights of moderate size");
  }
  return result;
}

BlendedShape blendShape(const ShapeBlender& blender, const ModelData& model,
                        const std::vector<double>& weights, BlendMethod method,
                        const QualityFigures& figures) {
  return blendShape(blender, model, modelRestData(model), weights, method, figures);
}

BlendedShape blendShape(const ShapeBlender& blender, const ModelData& model,
                        const RestTetData& restData, const std::vector<double>& weights,
                        BlendMethod method, const QualityFigures& figures) {
  BlendResult result = checkedBlend(blender, weights, method);
  const bool excludes = !model.excludedTets.empty();
  // Without excluded tets the blender's rest is the model's, maps included.
  const TetQuality q =
      tetQuality(model.rest, restData, result.vertices,
                 excludes ? targetsOfAllTets(model, result.targets) : result.targets, figures);
  BlendedShape shape;
  shape.quality = summarizeQuality(q);
  shape.cellData.push_back(cellArray("volume_ratio", q.volumeRatio));
  shape.cellData.push_back(
      cellArray("inverted", std::vector<double>(q.inverted.begin(), q.inverted.end())));
  if (figures.distortion) shape.cellData.push_back(cellArray("distortion", q.conditionNumber));
  if (figures.rotationAngle) shape.cellData.push_back(cellArray("rotation_angle", q.rotationAngle));
  if (figures.targetResidual && !result.targets.empty())
    shape.cellData.push_back(cellArray("target_residual", q.stitchResidual));
  if (excludes) {
    std::vector<double> excluded(static_cast<std::size_t>(model.rest.tets.rows()), 0.0);
    for (int t : model.excludedTets) {
      excluded[static_cast<std::size_t>(t)] = 1.0;
      shape.invertedExcluded += q.inverted[static_cast<std::size_t>(t)];
    }
    shape.cellData.push_back(cellArray("excluded", excluded));
  }
  shape.vertices = std::move(result.vertices);
  return shape;
}

const std::vector<std::string>& blendCellArrayNames() {
  static const std::vector<std::string> names = {"volume_ratio",   "inverted",        "distortion",
                                                 "rotation_angle", "target_residual", "excluded"};
  return names;
}

std::vector<std::pair<std::string, double>> qualityColumns(const QualitySummary& q) {
  const std::vector<std::pair<std::string, double>> all = {
      {"min_volume_ratio", q.volumeRatio.min},
      {"max_volume_ratio", q.volumeRatio.max},
      {"inverted_tets", static_cast<double>(q.invertedCount)},
      {"mean_target_residual", q.stitchResidual.mean},
      {"max_target_residual", q.stitchResidual.max},
      {"mean_distortion", q.conditionNumber.mean},
      {"max_distortion", q.conditionNumber.max},
      {"mean_rotation_angle", q.rotationAngle.mean},
      {"max_rotation_angle", q.rotationAngle.max}};
  std::vector<std::pair<std::string, double>> finite;
  for (const auto& column : all) {
    if (std::isfinite(column.second)) finite.push_back(column);
  }
  return finite;
}

}  // namespace tetblend
