#pragma once
// Options shared by the subcommands that blend (blend, batch, variations,
// animate): the method, rotation consistency, the nonlinear stitch, and the
// extra surface formats; and the construction of a ShapeBlender from a model.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "model_file.h"
#include "tetblend/blending/shape_blender.h"

namespace tetblend::cli {

/// Blend settings with their command-line defaults.
struct BlendSettings {
  std::string method = "kaji";              ///< a blendMethodName
  std::string consistency = "on";           ///< "on" or "off": consistent rotation logs
  bool nonlinear = false;                   ///< nonlinear stitch pass after the linear one
  std::vector<std::string> surfaceFormats;  ///< extra surface files beside the .vtp
};

/// Adds --method, --consistency, --nonlinear and --surface-format.
void addBlendOptions(CLI::App& command, BlendSettings& settings);

/// The method named in `settings`; InputError listing the valid names.
BlendMethod parseMethod(const std::string& name);

/// Parses "on"/"off"; InputError otherwise.
bool parseOnOff(const std::string& value, const std::string& what);

/// The model's rest mesh without its excluded tets (the tets some example
/// cannot embed): the mesh the blender parametrises and stitches. All
/// vertices are kept, in order; a vertex left in no tet is blended linearly
/// (its own stitch component, placed at its blended position).
TetMesh stitchedMesh(const ModelData& model);

/// A blender for `model` with `methods` prepared (parametrisation and the
/// stitch factorisation happen here); `nonlinearStitch` runs the nonlinear
/// stitch (nonlinear_stitch.h) after the linear one whenever that leaves
/// inverted tets (not for vertex-linear, which has no per-tet maps). InputError/DomainError from
/// the library name the example and tet at fault. The blender works on
/// stitchedMesh(model): tet indices in its results are of that mesh.
ShapeBlender makeBlender(const ModelData& model, const std::vector<BlendMethod>& methods,
                         bool rotationConsistency, bool nonlinearStitch);

}  // namespace tetblend::cli
