#pragma once
// From surface files to a model: validate the rest and the examples, make the
// rest tet mesh (TetGen, or per-face tetrisation), and place the interior
// vertices of each example so every example shares the rest's tets. Used by
// `tetblend prepare` (which saves the result) and by `tetblend blend --rest`
// (which blends it directly).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model_file.h"

namespace tetblend::cli {

/// The meshing options of prepare, with their command-line defaults.
struct PrepareSettings {
  double radiusEdgeRatio = 2.0;  ///< TetGen quality bound (-q), > 1
  /// TetGen volume bound (-a), mesh units³; 0 = none; unset = auto: the
  /// volume of a regular tet whose edge is the rest surface's mean edge
  /// length, so the interior is as fine as the surface (a 4 pi twist or a
  /// 180-degree bend needs interior points; TetGen's quality bound alone adds
  /// few when the surface is already fine).
  std::optional<double> maxVolume;
  bool tetrise = false;          ///< per-face tetrisation instead of TetGen
  int threads = 0;               ///< worker threads; 0 = all cores
  bool quiet = false;            ///< no progress bar
};

/// Adds --quality, --max-volume, --tetrise and --threads to `command`.
void addPrepareOptions(CLI::App& command, PrepareSettings& settings);

/// Builds the model of `restPath` and `examplePaths` (surface files with the
/// same triangles). Throws InputError naming the file and the problem.
ModelData prepareModel(const std::string& restPath, const std::vector<std::string>& examplePaths,
                       const PrepareSettings& settings);

}  // namespace tetblend::cli
