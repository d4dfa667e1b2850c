#pragma once
// From surface files (or surfaces in memory) to a model: validate the rest
// and the examples, make the rest tet mesh (TetGen, or per-face tetrisation),
// and place the interior vertices of each example so every example shares the
// rest's tets. Used by `tetblend prepare` (which saves the result), by
// `tetblend blend --rest` (which blends it directly) and by the Python module.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// The meshing options of prepare, with their defaults (the command line's).
struct PrepareOptions {
  double radiusEdgeRatio = 2.0;  ///< TetGen quality bound (-q), > 1
  /// TetGen volume bound (-a), mesh units³; unset or 0 = none: the quality
  /// bound alone grades the interior from the surface's own edge lengths
  /// inwards, and the examples refine it where they need it
  /// (example_aware_tets.h).
  std::optional<double> maxVolume;
  bool tetrise = false;  ///< per-face tetrisation instead of TetGen
  /// Close the holes of an open rest (hole_filling.h) and tetrahedralise the
  /// closed surface; false refuses an open rest. The fill's triangles bound
  /// the tets but are not in the model's surfaceTriangles.
  bool fillHoles = true;
  /// Refuse examples with tets that cannot be embedded (default: report them
  /// and leave them out of the stitch), a rest that intersects itself
  /// within a component (default: meshed on a separated copy), and
  /// components that cannot be filled with tets (default: one tet per face,
  /// as with `tetrise`).
  bool strict = false;
};

/// Where prepareModel's messages go, one line each (no prefix, no newline).
/// Every callback may be empty.
struct PrepareMessages {
  /// Something the user must know: excluded tets, a mesh that will need
  /// gigabytes.
  std::function<void(const std::string&)> warning;
  /// What was done: tet count, Steiner points added.
  std::function<void(const std::string&)> note;
  /// Called with the number of steps just done, out of
  /// prepareStepCount(#examples) in all.
  std::function<void(std::size_t)> step;
};

/// Steps prepareModel reports through PrepareMessages::step: reading, the
/// rest's tets, then one per example placed.
std::size_t prepareStepCount(std::size_t exampleCount);

/// Rest meshes above this many tets get a memory warning before the
/// examples are placed: preparing and each blend hold about 1 KB per tet
/// (README, Benchmarks), so this is where a run starts to need gigabytes.
constexpr long long kLargeMeshWarningTets = 1000000;

/// Builds the model of `restPath` and `examplePaths` (surface files with the
/// same triangles, all read before any is validated). Tets that an example inverts whatever the
/// placement (its surface folds or intersects itself) become the model's excluded tets, with one
/// warning per such example; options.strict refuses them instead. An example equal to the rest is
/// warned about, and so is a rest mesh above kLargeMeshWarningTets before the long steps start; a
/// note gives the holes filled, the tet count and the Steiner points added. Throws InputError
/// naming the file and the problem (also when the triangles filling a hole intersect the rest's
/// surface).
ModelData prepareModel(const std::string& restPath, const std::vector<std::string>& examplePaths,
                       const PrepareOptions& options, const PrepareMessages& messages = {});

/// As above, from surfaces in memory (the Python module's prepare): `rest`
/// and `examples` (the rest's triangles, #V by 3 positions each), with
/// `restName` and `exampleNames` (one per example) standing for the file
/// names in messages and in the model's sources.
ModelData prepareModel(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                       const std::string& restName, const std::vector<std::string>& exampleNames,
                       const PrepareOptions& options, const PrepareMessages& messages = {});

}  // namespace tetblend
