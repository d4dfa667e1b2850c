#include "blend_setup.h"

#include "tetblend/core/error.h"

namespace tetblend::cli {

void addBlendOptions(CLI::App& command, BlendSettings& settings) {
  std::string names;
  for (BlendMethod m : allBlendMethods()) names += (names.empty() ? "" : ", ") + blendMethodName(m);
  command.add_option("--method", settings.method, "blend method: " + names)->capture_default_str();
  command
      .add_option("--consistency", settings.consistency,
                  "consistent rotation logarithms across neighbouring tets (Kaji-Ochiai Alg. 1; "
                  "kaji, kaji-frechet, liebodies): on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command.add_flag("--nonlinear", settings.nonlinear,
                   "when the linear stitch leaves inverted tets, run the nonlinear stitch (Ceres) "
                   "that removes them (default: off)");
  command.add_option("--surface-format", settings.surfaceFormats,
                     "also write the surface as obj, ply and/or off beside the .vtp (repeatable; "
                     "default: .vtp only)");
}

BlendMethod parseMethod(const std::string& name) { return blendMethodFromName(name); }

bool parseOnOff(const std::string& value, const std::string& what) {
  if (value == "on") return true;
  if (value == "off") return false;
  throw InputError(what + ": '" + value + "' is neither on nor off");
}

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

ShapeBlender makeBlender(const ModelData& model, const std::vector<BlendMethod>& methods,
                         bool rotationConsistency, bool nonlinearStitch) {
  ShapeBlenderOptions options;
  options.methods = methods;
  options.rotationConsistency = rotationConsistency;
  options.nonlinearStitch = nonlinearStitch;
  options.keepTargets = true;  // the target_residual quality array needs the blended maps
  return ShapeBlender(stitchedMesh(model), model.examples, options);
}

}  // namespace tetblend::cli
