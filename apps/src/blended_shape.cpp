#include "blended_shape.h"

#include <Eigen/LU>
#include <algorithm>
#include <limits>

#include "tetblend/core/error.h"

namespace tetblend::cli {

BlendedShape blendShape(const ShapeBlender& blender, const std::vector<double>& weights,
                        BlendMethod method) {
  BlendResult result = blender.blend(weights, method);
  const StitchSolver& stitch = blender.stitch();
  const RestTetData& rest = stitch.restData();
  const auto tets = static_cast<std::size_t>(stitch.tetCount());
  const bool hasTargets = result.targets.size() == tets;

  NamedArray ratio{"volume_ratio", 1, std::vector<double>(tets)};
  NamedArray inverted{"inverted", 1, std::vector<double>(tets)};
  NamedArray residual{"target_residual", 1, std::vector<double>(tets)};
  QualitySummary q;
  q.minVolumeRatio = std::numeric_limits<double>::infinity();
  q.maxVolumeRatio = -std::numeric_limits<double>::infinity();
  double weightedResidual = 0.0, totalVolume = 0.0;
  for (std::size_t j = 0; j < tets; ++j) {
    const Eigen::Matrix3d g = stitch.gradient(result.vertices, static_cast<int>(j));
    const double det = g.determinant();
    ratio.values[j] = det;
    inverted.values[j] = det <= 0.0 ? 1.0 : 0.0;
    q.minVolumeRatio = std::min(q.minVolumeRatio, det);
    q.maxVolumeRatio = std::max(q.maxVolumeRatio, det);
    q.invertedTets += det <= 0.0 ? 1 : 0;
    if (hasTargets) {
      const Eigen::Matrix3d& b = result.targets[j];
      const double r = (g - b).norm() / std::max(b.norm(), std::numeric_limits<double>::min());
      residual.values[j] = r;
      q.maxTargetResidual = std::max(q.maxTargetResidual, r);
      weightedResidual += rest.volumes[j] * r;
      totalVolume += rest.volumes[j];
    }
  }
  if (tets == 0) q.minVolumeRatio = q.maxVolumeRatio = 0.0;
  q.meanTargetResidual = totalVolume > 0.0 ? weightedResidual / totalVolume : 0.0;
  BlendedShape shape{std::move(result.vertices), {std::move(ratio), std::move(inverted)}, q};
  if (hasTargets) shape.cellData.push_back(std::move(residual));
  return shape;
}

std::vector<std::pair<std::string, double>> qualityColumns(const QualitySummary& q) {
  return {{"min_volume_ratio", q.minVolumeRatio},
          {"max_volume_ratio", q.maxVolumeRatio},
          {"inverted_tets", static_cast<double>(q.invertedTets)},
          {"mean_target_residual", q.meanTargetResidual},
          {"max_target_residual", q.maxTargetResidual}};
}

}  // namespace tetblend::cli
