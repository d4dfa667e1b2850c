#include "tetblend/pipeline/make_blender.h"

namespace tetblend {

TetMesh stitchedMesh(const ModelData& model) {
  if (model.excludedTets.empty()) return model.rest;
  TetMesh kept;
  kept.vertices = model.rest.vertices;
  kept.tets.resize(model.rest.tets.rows() - static_cast<Eigen::Index>(model.excludedTets.size()),
                   4);
  Eigen::Index row = 0;
  std::size_t next = 0;  // model.excludedTets is ascending
  for (Eigen::Index t = 0; t < model.rest.tets.rows(); ++t) {
    if (next < model.excludedTets.size() && model.excludedTets[next] == t) {
      ++next;
      continue;
    }
    kept.tets.row(row++) = model.rest.tets.row(t);
  }
  return kept;
}

BlendCache blendCacheOf(const ModelData& model) {
  return makeBlender(model, {BlendMethod::kKaji}, true, false, false).exportCache();
}

ShapeBlender makeBlender(const ModelData& model, const std::vector<BlendMethod>& methods,
                         bool rotationConsistency, bool nonlinearStitch, bool keepTargets) {
  ShapeBlenderOptions options;
  options.methods = methods;
  options.rotationConsistency = rotationConsistency;
  options.nonlinearStitch = nonlinearStitch;
  options.keepTargets = keepTargets;
  if (model.blendCache)
    return ShapeBlender(stitchedMesh(model), model.examples, options, *model.blendCache);
  return ShapeBlender(stitchedMesh(model), model.examples, options);
}

}  // namespace tetblend
