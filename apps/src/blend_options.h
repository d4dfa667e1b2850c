#pragma once
// Options shared by the subcommands that blend (blend, batch, variations,
// animate): the method, rotation consistency, the nonlinear stitch, the
// extra surface formats, the quality arrays written and the compressor of
// the VTK files.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "blend_compression.h"
#include "tetblend/blending/blend_method.h"

namespace tetblend::cli {

/// Blend settings with their command-line defaults.
struct BlendSettings {
  std::string method = "kaji";              ///< a blendMethodName
  std::string consistency = "on";           ///< "on" or "off": consistent rotation logs
  bool nonlinear = false;                   ///< nonlinear stitch pass after the linear one
  std::vector<std::string> surfaceFormats;  ///< extra surface files beside the .vtp
  std::string qualityArrays = "all";        ///< parseQualityArrays text: all, none or a,b
  std::string compression =
      vtkCompressorName(kBlendOutputCompression.compressor);  ///< lz4, zlib or none
  int compressionLevel = kBlendOutputCompression.level;       ///< 1 (fastest) .. 9 (smallest)
};

/// Adds --method, --consistency, --nonlinear, --surface-format,
/// --quality-arrays, --compression and --compression-level.
void addBlendOptions(CLI::App& command, BlendSettings& settings);

/// The method named in `settings`; InputError listing the valid names.
BlendMethod parseMethod(const std::string& name);

/// Parses "on"/"off"; InputError otherwise.
bool parseOnOff(const std::string& value, const std::string& what);

}  // namespace tetblend::cli
