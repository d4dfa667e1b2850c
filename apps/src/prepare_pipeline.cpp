#include "prepare_pipeline.h"

#include <cmath>

#include "cli_common.h"
#include "progress.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/compatible_tets.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tetgen_mesher.h"
#include "tetblend/meshing/tetrisation.h"

namespace tetblend::cli {
namespace {

/// Volume of a regular tetrahedron whose edge is the mean edge length of the
/// triangles of `surface` (each edge counted once per face): a^3 / (6 sqrt 2).
double autoMaxTetVolume(const SurfaceMesh& surface) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      total += (surface.vertices.row(surface.triangles(f, c)) -
                surface.vertices.row(surface.triangles(f, (c + 1) % 3)))
                   .norm();
    }
  }
  const double edge = total / (3.0 * static_cast<double>(surface.triangles.rows()));
  return edge * edge * edge / (6.0 * std::sqrt(2.0));
}

}  // namespace

void addPrepareOptions(CLI::App& command, PrepareSettings& settings) {
  command
      .add_option("--quality", settings.radiusEdgeRatio,
                  "TetGen quality bound: max circumradius / shortest edge of a tet (> 1; 0 = no "
                  "refinement)")
      ->capture_default_str();
  command
      .add_option("--max-volume", settings.maxVolume,
                  "TetGen volume bound per tet, in mesh units cubed (0 = none; default: auto, "
                  "a regular tet whose edge is the rest surface's mean edge length)")
      ->check(CLI::NonNegativeNumber);
  command.add_flag("--tetrise", settings.tetrise,
                   "one tet per surface triangle (apex along the normal) instead of TetGen: for "
                   "open or non-watertight surfaces (default: off)");
  addThreadsOption(command, settings.threads);
}

ModelData prepareModel(const std::string& restPath, const std::vector<std::string>& examplePaths,
                       const PrepareSettings& settings) {
  if (examplePaths.empty()) throw InputError("give at least one example surface");
  if (settings.radiusEdgeRatio != 0.0 && !(settings.radiusEdgeRatio > 1.0)) {
    throw InputError("--quality must be 0 or greater than 1, got " +
                     formatNumber(settings.radiusEdgeRatio));
  }
  ProgressBar progress("prepare", examplePaths.size() + 2, settings.quiet);
  const SurfaceMesh rest = readSurface(restPath);
  SurfaceValidationOptions validation;
  validation.requireClosed = !settings.tetrise;
  requireValidRest(rest, restPath, validation);
  std::vector<SurfaceMesh> examples;
  for (const std::string& path : examplePaths) {
    examples.push_back(readSurface(path));
    requireCompatibleExample(rest, examples.back(), path);
  }
  progress.advance();

  ModelData model;
  model.surfaceTriangles = rest.triangles;
  model.surfaceVertexCount = static_cast<int>(rest.vertices.rows());
  model.restSource = restPath;
  model.exampleSources = examplePaths;
  if (settings.tetrise) {
    std::vector<TetMesh> meshes = tetriseCompatible(rest, examples, examplePaths);
    model.rest = std::move(meshes.front());
    for (std::size_t k = 1; k < meshes.size(); ++k) model.examples.push_back(meshes[k].vertices);
    progress.advance(examplePaths.size() + 1);
    return model;
  }
  TetGenOptions tetgen;
  tetgen.maxRadiusEdgeRatio = settings.radiusEdgeRatio;
  tetgen.maxTetVolume = settings.maxVolume ? *settings.maxVolume : autoMaxTetVolume(rest);
  model.rest = tetrahedralize(rest, tetgen);
  progress.advance();
  const CompatibleTetBuilder builder(model.rest, model.surfaceVertexCount);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    CompatibleTetResult placed = builder.place(examples[k].vertices);
    if (!placed.invertedTets.empty()) {
      throw InputError(examplePaths[k] + ": " + std::to_string(placed.invertedTets.size()) +
                       " tets stay inverted after placing the interior vertices (first: tet " +
                       std::to_string(placed.invertedTets.front()) + ", signed volume " +
                       formatNumber(placed.invertedVolumes.front()) +
                       "); try a finer rest mesh (--max-volume) or --tetrise");
    }
    model.examples.push_back(std::move(placed.vertices));
    progress.advance();
  }
  return model;
}

}  // namespace tetblend::cli
