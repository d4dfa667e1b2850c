#pragma once
// One blend as the subcommands use it: blend, then the per-tet quality
// arrays written as cell data and the summary figures of the batch tables.

#include <string>
#include <vector>

#include "tetblend/blending/shape_blender.h"
#include "tetblend/meshing/mesh_data_arrays.h"

namespace tetblend::cli {

/// Summary of the per-tet quality of one blended shape.
struct QualitySummary {
  double minVolumeRatio = 0.0;      ///< min_j det(grad_j x) (unitless, blended/rest)
  double maxVolumeRatio = 0.0;      ///< max_j det(grad_j x)
  int invertedTets = 0;             ///< tets with det(grad_j x) <= 0
  double meanTargetResidual = 0.0;  ///< volume-weighted mean of the relative residual
  double maxTargetResidual = 0.0;   ///< max_j |grad_j x - B_j|_F / |B_j|_F
};

/// A blended shape with its quality.
struct BlendedShape {
  Vertices vertices;                 ///< #V by 3, the model's vertex order
  std::vector<NamedArray> cellData;  ///< per-tet arrays (see blendShape)
  QualitySummary quality;
};

/// Blends `weights` with `method` on a prepared `blender`, and
/// computes per tet j (cell arrays): "volume_ratio" det(grad_j x) (1 = volume
/// kept, <= 0 = inverted), "inverted" (1 or 0), and, for the methods with
/// per-tet targets, "target_residual" |grad_j x - B_j|_F / |B_j|_F (how far
/// the stitch had to move tet j from its blended map; 0 where the blended
/// maps were already compatible). The nonlinear stitch runs when the
/// blender was made with it (makeBlender).
/// Not safe to call concurrently on one blender.
BlendedShape blendShape(const ShapeBlender& blender, const std::vector<double>& weights,
                        BlendMethod method);

/// Column names and values of a QualitySummary, in table order.
std::vector<std::pair<std::string, double>> qualityColumns(const QualitySummary& quality);

}  // namespace tetblend::cli
