#include "blended_shape.h"

#include <cmath>

namespace tetblend::cli {

namespace {

NamedArray cellArray(const std::string& name, const std::vector<double>& values) {
  return NamedArray{name, 1, values};
}

}  // namespace

BlendedShape blendShape(const ShapeBlender& blender, const std::vector<double>& weights,
                        BlendMethod method) {
  BlendResult result = blender.blend(weights, method);
  const TetQuality q =
      tetQuality(blender.rest(), blender.stitch().restData(), result.vertices, result.targets);
  BlendedShape shape;
  shape.quality = summarizeQuality(q);
  shape.cellData.push_back(cellArray("volume_ratio", q.volumeRatio));
  shape.cellData.push_back(
      cellArray("inverted", std::vector<double>(q.inverted.begin(), q.inverted.end())));
  shape.cellData.push_back(cellArray("distortion", q.conditionNumber));
  shape.cellData.push_back(cellArray("rotation_angle", q.rotationAngle));
  if (!result.targets.empty())
    shape.cellData.push_back(cellArray("target_residual", q.stitchResidual));
  shape.vertices = std::move(result.vertices);
  return shape;
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

}  // namespace tetblend::cli
