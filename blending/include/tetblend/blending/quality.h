#pragma once
// Quality of a blended shape, per tet and summarised: inverted tets, volume
// ratios, how far the stitch is from the blended maps, distortion and
// rotation. Arrays are in tet order, ready to be written as cell data.

#include <Eigen/Core>
#include <vector>

#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Which per-tet figures tetQuality computes besides volume ratio and
/// inversion (always computed: a determinant per tet). Distortion and
/// rotation angle take a singular value or polar decomposition of F_j
/// (tetDistortion); the stitch residual needs the blended maps kept.
struct QualityFigures {
  bool distortion = true;      ///< TetQuality::conditionNumber
  bool rotationAngle = true;   ///< TetQuality::rotationAngle
  bool targetResidual = true;  ///< TetQuality::stitchResidual
};

/// Per-tet quality arrays (#T entries each; empty when not asked for, see
/// QualityFigures) of a result x against the rest. F_j = grad_j(x) is the
/// deformation gradient rest -> result.
struct TetQuality {
  std::vector<char> inverted;          ///< 1 where det F_j <= 0
  std::vector<double> volumeRatio;     ///< det F_j = vol_result / vol_rest (signed)
  std::vector<double> stitchResidual;  ///< ||F_j - B_j||_F (NaN without targets)
  /// Distortion sigma_max / sigma_min of F_j (1 for a similarity, +inf when
  /// sigma_min = 0); for an inverted tet, of |F_j|.
  std::vector<double> conditionNumber;
  /// Angle (radians, [0, pi]) of the polar rotation of F_j; NaN if inverted.
  std::vector<double> rotationAngle;
};

/// Minimum, maximum and mean of the finite entries of one array (NaN for all
/// three when none is finite); +inf entries count in the maximum only.
struct QualityStats {
  double min = 0.0;
  double max = 0.0;
  double mean = 0.0;
};

/// Summary of a TetQuality.
struct QualitySummary {
  int tetCount = 0;
  int invertedCount = 0;
  QualityStats volumeRatio;
  QualityStats stitchResidual;
  QualityStats conditionNumber;
  QualityStats rotationAngle;
};

/// Quality of `result` (#V by 3) for `rest` (#V vertices, #T tets) with rest
/// data `restData` (restTetData(rest)) and the blended maps `targets` (#T,
/// or empty for a blend without maps, e.g. vertex-linear), with the figures
/// `figures` asks for. A tet whose rest volume is NaN (a tet left out of the
/// stitch that the rest itself inverts, see modelRestData) gets NaN figures
/// and counts as not inverted. Parallel over tets. Throws InputError on size
/// mismatches.
TetQuality tetQuality(const TetMesh& rest, const RestTetData& restData, const Vertices& result,
                      const std::vector<Eigen::Matrix3d>& targets,
                      const QualityFigures& figures = {});

/// Counts and min/max/mean of every array of `quality` (NaN stats for an
/// array not computed).
QualitySummary summarizeQuality(const TetQuality& quality);

}  // namespace tetblend
