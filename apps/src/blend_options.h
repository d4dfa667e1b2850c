#pragma once
// Options shared by the subcommands that blend (blend, batch, variations,
// animate): the method, rotation consistency, the nonlinear stitch, the
// extra surface formats and the quality arrays written.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tetblend/blending/blend_method.h"

namespace tetblend::cli {

/// Blend settings with their command-line defaults.
struct BlendSettings {
  std::string method = "kaji";              ///< a blendMethodName
  std::string consistency = "on";           ///< "on" or "off": consistent rotation logs
  bool nonlinear = false;                   ///< nonlinear stitch pass after the linear one
  std::vector<std::string> surfaceFormats;  ///< extra surface files beside the .vtp
  std::string qualityArrays = "all";        ///< parseQualityArrays text: all, none or a,b
};

/// Adds --method, --consistency, --nonlinear, --surface-format and
/// --quality-arrays.
void addBlendOptions(CLI::App& command, BlendSettings& settings);

/// The method named in `settings`; InputError listing the valid names.
BlendMethod parseMethod(const std::string& name);

/// Parses "on"/"off"; InputError otherwise.
bool parseOnOff(const std::string& value, const std::string& what);

}  // namespace tetblend::cli
