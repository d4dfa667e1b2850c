#include "blend_options.h"

#include "tetblend/core/error.h"
#include "tetblend/pipeline/blended_shape.h"

namespace tetblend::cli {

void addBlendOptions(CLI::App& command, BlendSettings& settings) {
  std::string names;
  for (BlendMethod m : allBlendMethods()) names += (names.empty() ? "" : ", ") + blendMethodName(m);
  command
      .add_option("--method", settings.method,
                  "blend method: " + names + " (" + methodAliasNote() + ")")
      ->capture_default_str();
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
  std::string arrays;
  for (const std::string& n : blendCellArrayNames()) arrays += (arrays.empty() ? "" : ", ") + n;
  command
      .add_option("--quality-arrays", settings.qualityArrays,
                  "per-tet cell arrays written to each .vtu: all, none (the fastest to write) or "
                  "a comma-separated list of " +
                      arrays)
      ->capture_default_str();
  command
      .add_option("--compression", settings.compression,
                  "compressor of the .vtu/.vtp data: lz4, zlib (smaller files, slower) or none; "
                  "VTK and ParaView read all three")
      ->capture_default_str();
  command
      .add_option("--compression-level", settings.compressionLevel,
                  "compression level, 1 (fastest) .. 9 (smallest); ignored by none")
      ->capture_default_str();
}

BlendMethod parseMethod(const std::string& name) { return blendMethodFromName(name); }

bool parseOnOff(const std::string& value, const std::string& what) {
  if (value == "on") return true;
  if (value == "off") return false;
  throw InputError(what + ": '" + value + "' is neither on nor off");
}

}  // namespace tetblend::cli
