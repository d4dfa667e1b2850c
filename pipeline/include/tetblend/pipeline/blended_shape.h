#pragma once
// One blend as the subcommands use it: blend, then the per-tet quality
// arrays (the blending library's tetQuality) written as cell data and the
// summary figures (summarizeQuality) of the batch tables.

#include <string>
#include <utility>
#include <vector>

#include "tetblend/blending/quality.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// A blended shape with its quality.
struct BlendedShape {
  Vertices vertices;                 ///< #V by 3, the model's vertex order
  std::vector<NamedArray> cellData;  ///< per-tet arrays (see blendShape)
  QualitySummary quality;            ///< summarizeQuality of the cell arrays
  /// Inverted tets among the model's excluded ones (ModelData::excludedTets:
  /// tets that cannot be embedded in some example, so blends near that
  /// example invert them too).
  int invertedExcluded = 0;
};

/// blender.blend(weights, method), with the weights named in a DomainError
/// and an InputError when the result is not finite (weights so large that
/// the blended maps overflow).
BlendResult checkedBlend(const ShapeBlender& blender, const std::vector<double>& weights,
                         BlendMethod method);

/// Blends `weights` with `method` on `blender` (makeBlender of `model`) and
/// computes the per-tet quality of the result over all the model's tets
/// (tetQuality, with F_j = grad_j x), as cell arrays: "volume_ratio" det F_j (1 = volume kept, <= 0
/// = inverted), "inverted" (1 or 0), "distortion" sigma_max / sigma_min of F_j (1 = no shape
/// change), "rotation_angle" of the polar rotation of F_j in radians (NaN where inverted) and, for
/// the methods with per-tet targets, "target_residual" ||F_j - B_j||_F (how far the stitch had to
/// move tet j from its blended map; 0 where the blended maps were already compatible; NaN for
/// excluded tets) and, when the model has excluded tets, "excluded" (1 for the tets left out of the
/// stitch). "distortion", "rotation_angle" and "target_residual" (and their summary figures) are
/// made only when `figures` asks for them: they are most of the quality's cost (target_residual
/// also needs a blender that keeps its maps: makeBlender's keepTargets). The nonlinear stitch runs
/// when the blender was made with it (makeBlender). Safe to call from several threads on one
/// blender, as ShapeBlender::blend is.
BlendedShape blendShape(const ShapeBlender& blender, const ModelData& model,
                        const std::vector<double>& weights, BlendMethod method,
                        const QualityFigures& figures = {});

/// restTetData(model.rest, model.excludedTets): an excluded tet that the rest
/// itself leaves flat or inverted (a rest that intersects itself, embedded in
/// tets made on a separated copy: prepare_model.h) gets a NaN volume and
/// inverse, so its quality figures are NaN. Throws InputError naming a
/// stitched tet that is not positively oriented (a damaged model).
RestTetData modelRestData(const ModelData& model);

/// blendShape with the rest data of the quality given: `restData` =
/// modelRestData(model), which every blend of the model shares (computing
/// it takes an inverse per tet), so many blends compute it once.
BlendedShape blendShape(const ShapeBlender& blender, const ModelData& model,
                        const RestTetData& restData, const std::vector<double>& weights,
                        BlendMethod method, const QualityFigures& figures = {});

/// The names of every cell array blendShape can make, in its order:
/// volume_ratio, inverted, distortion, rotation_angle, target_residual,
/// excluded.
const std::vector<std::string>& blendCellArrayNames();

/// Column names and values of a QualitySummary, in table order:
/// min/max_volume_ratio, inverted_tets, mean/max_target_residual,
/// mean/max_distortion, mean/max_rotation_angle (radians). A value that is
/// not finite (no targets for vertex-linear; a flat tet makes the distortion
/// infinite; a figure not computed) is left out, so tables show it as
/// missing; inverted_tets tells the flat and inverted tets apart.
std::vector<std::pair<std::string, double>> qualityColumns(const QualitySummary& quality);

}  // namespace tetblend
