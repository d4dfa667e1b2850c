#include "tetblend/blending/quality.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>

#include "blend_common.h"
#include "tetblend/blending/tet_distortion.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

QualityStats stats(const std::vector<double>& values) {
  QualityStats s{kInfinity, -kInfinity, 0.0};
  int finite = 0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    s.max = std::max(s.max, v);
    if (!std::isfinite(v)) continue;
    s.min = std::min(s.min, v);
    s.mean += v;
    ++finite;
  }
  if (finite == 0) return {kNaN, kNaN, kNaN};
  s.mean /= finite;
  return s;
}

}  // namespace

TetQuality tetQuality(const TetMesh& rest, const RestTetData& restData, const Vertices& result,
                      const std::vector<Eigen::Matrix3d>& targets, const QualityFigures& figures) {
  const int count = static_cast<int>(rest.tets.rows());
  if (result.rows() != rest.vertices.rows() || static_cast<int>(restData.volumes.size()) != count ||
      (!targets.empty() && static_cast<int>(targets.size()) != count)) {
    std::ostringstream message;
    message << "quality: sizes do not match (" << result.rows() << " result vertices, "
            << rest.vertices.rows() << " rest vertices, " << targets.size() << " targets, " << count
            << " tets)";
    throw InputError(message.str());
  }
  TetQuality q;
  q.inverted.resize(count);
  q.volumeRatio.resize(count);
  if (figures.targetResidual) q.stitchResidual.resize(count);
  if (figures.distortion) q.conditionNumber.resize(count);
  if (figures.rotationAngle) q.rotationAngle.resize(count);
  const bool decompose = figures.distortion || figures.rotationAngle;
  blend_detail::forEachTet(count, [&](int j) {
    if (std::isnan(restData.volumes[j])) {
      q.inverted[j] = 0;
      q.volumeRatio[j] = kNaN;
      if (figures.targetResidual) q.stitchResidual[j] = kNaN;
      if (figures.distortion) q.conditionNumber[j] = kNaN;
      if (figures.rotationAngle) q.rotationAngle[j] = kNaN;
      return;
    }
    const Eigen::Matrix3d f = tetEdgeMatrix(result, rest.tets.row(j)) * restData.inverseEdges[j];
    const double det = f.determinant();
    q.inverted[j] = det <= 0.0 ? 1 : 0;
    q.volumeRatio[j] = det;
    if (figures.targetResidual)
      q.stitchResidual[j] = targets.empty() ? kNaN : (f - targets[j]).norm();
    if (!decompose) return;
    const TetDistortion d = tetDistortion(f, det);
    if (figures.distortion) q.conditionNumber[j] = d.conditionNumber;
    if (figures.rotationAngle) q.rotationAngle[j] = d.rotationAngle;
  });
  return q;
}

QualitySummary summarizeQuality(const TetQuality& quality) {
  QualitySummary s;
  s.tetCount = static_cast<int>(quality.inverted.size());
  for (char inverted : quality.inverted) s.invertedCount += inverted;
  s.volumeRatio = stats(quality.volumeRatio);
  s.stitchResidual = stats(quality.stitchResidual);
  s.conditionNumber = stats(quality.conditionNumber);
  s.rotationAngle = stats(quality.rotationAngle);
  return s;
}

}  // namespace tetblend
