#include "tetblend/pipeline/prepare_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/hole_filling.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tetgen_mesher.h"
#include "tetblend/meshing/tetrisation.h"
#include "tetblend/pipeline/format_number.h"

namespace tetblend {
namespace {

void say(const std::function<void(const std::string&)>& sink, const std::string& line) {
  if (sink) sink(line);
}

void advance(const PrepareMessages& messages, std::size_t steps) {
  if (messages.step) messages.step(steps);
}

// "1.34 M" / "134 k" / "950": a tet count people read at a glance.
std::string roughCount(long long n) {
  if (n >= 1000000) return formatNumber(std::round(n / 1e4) / 100) + " M";
  if (n >= 10000) return formatNumber(std::round(n / 1e3)) + " k";
  return std::to_string(n);
}

std::string threeDigits(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

// Why an example's tets cannot be embedded, in words: its surface intersects
// itself (how many face pairs, the first), or the placement failed.
std::string diagnosis(const SelfIntersections& found) {
  if (found.pairCount == 0) {
    return "its surface does not intersect itself, but the interior could not be placed "
           "without inverting them (a finer rest mesh, --max-volume, may help)";
  }
  return "its surface intersects itself at " + std::to_string(found.pairCount) + " face pair" +
         (found.pairCount > 1 ? "s" : "") + ", first faces " +
         std::to_string(found.pairs.front().first) + " and " +
         std::to_string(found.pairs.front().second);
}

// Smallest signed volume ratio (example / rest) over the listed tets.
double worstVolumeRatio(const TetMesh& rest, const CompatibleTetResult& placed) {
  double worst = INFINITY;
  for (std::size_t i = 0; i < placed.invertedTets.size(); ++i) {
    const double restVolume = tetSignedVolume(rest.vertices, rest.tets.row(placed.invertedTets[i]));
    worst = std::min(worst, placed.invertedVolumes[i] / restVolume);
  }
  return worst;
}

// The checks that need no surface: examples given, a valid quality bound.
void checkPrepareArguments(std::size_t exampleCount, const PrepareOptions& options) {
  if (exampleCount == 0) throw InputError("give at least one example surface");
  if (options.radiusEdgeRatio != 0.0 && !(options.radiusEdgeRatio > 1.0)) {
    throw InputError("quality must be 0 or greater than 1, got " +
                     formatNumber(options.radiusEdgeRatio));
  }
}

// --strict fails fast: an example whose surface intersects itself is refused
// before any meshing, since some of its tets can never be embedded.
void refuseSelfIntersecting(const Triangles& triangles, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames) {
  for (std::size_t k = 0; k < examples.size(); ++k) {
    const SelfIntersections found = findSelfIntersections(examples[k].vertices, triangles, 1);
    if (found.pairCount > 0) {
      throw InputError(exampleNames[k] + ": " + diagnosis(found) +
                       ", so some tets cannot be embedded: repair the pose, or leave out --strict "
                       "to exclude those tets from the stitch");
    }
  }
}

// The rest surface as it is meshed: the user's faces, then the triangles that
// close its holes (none for the tetrisation, or with options.fillHoles off).
// `filling` says what was added.
SurfaceMesh closedRest(const SurfaceMesh& rest, const std::string& restName,
                       const PrepareOptions& options, HoleFilling& filling) {
  if (options.tetrise || !options.fillHoles) return rest;
  filling = fillHoles(rest, restName);
  SurfaceMesh closed{rest.vertices, Triangles(rest.triangles.rows() + filling.triangles.rows(), 3)};
  closed.triangles << rest.triangles, filling.triangles;
  return closed;
}

// requireValidRest of the closed rest, whose faces from `userFaceCount` on
// fill its holes: a fill triangle that intersects the surface is named as
// such, before the problems it may cause (e.g. a wrong nesting).
void requireValidClosedRest(const SurfaceMesh& closed, Eigen::Index userFaceCount,
                            const std::string& restName,
                            const SurfaceValidationOptions& validation) {
  const SurfaceValidation checked = validateSurface(closed, restName, validation);
  if (checked.ok()) return;
  for (const SurfaceProblem& problem : checked.problems) {
    const long long other = static_cast<long long>(problem.value);
    if (problem.kind == SurfaceProblemKind::kSelfIntersection &&
        std::max(problem.element, other) >= userFaceCount) {
      const long long face = std::min(problem.element, other);
      throw InputError(
          restName + ": " +
          (face < userFaceCount
               ? "a triangle filling one of its holes intersects face " + std::to_string(face)
               : std::string("two triangles filling its holes intersect")) +
          ": the holes cannot be closed without new vertices; close them yourself, "
          "or use the per-face tetrisation");
    }
  }
  requireValidRest(closed, restName, validation);
}

}  // namespace

std::size_t prepareStepCount(std::size_t exampleCount) { return exampleCount + 2; }

ModelData prepareModel(const std::string& restPath, const std::vector<std::string>& examplePaths,
                       const PrepareOptions& options, const PrepareMessages& messages) {
  checkPrepareArguments(examplePaths.size(), options);
  const SurfaceMesh rest = readSurface(restPath);
  std::vector<SurfaceMesh> examples;
  for (const std::string& path : examplePaths) examples.push_back(readSurface(path));
  return prepareModel(rest, examples, restPath, examplePaths, options, messages);
}

ModelData prepareModel(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                       const std::string& restName, const std::vector<std::string>& exampleNames,
                       const PrepareOptions& options, const PrepareMessages& messages) {
  checkPrepareArguments(examples.size(), options);
  if (exampleNames.size() != examples.size()) {
    throw InputError("prepare: " + std::to_string(exampleNames.size()) + " names given for " +
                     std::to_string(examples.size()) + " examples");
  }
  SurfaceValidationOptions validation;
  validation.requireClosed = !options.tetrise;
  HoleFilling filling;
  const SurfaceMesh closed = closedRest(rest, restName, options, filling);
  requireValidClosedRest(closed, rest.triangles.rows(), restName, validation);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
    if (examples[k].vertices == rest.vertices) {
      say(messages.warning, exampleNames[k] + ": every vertex equals the rest's (" + restName +
                                "): blending this example changes nothing");
    }
  }
  if (options.strict) refuseSelfIntersecting(closed.triangles, examples, exampleNames);
  advance(messages, 1);

  ModelData model;
  model.surfaceTriangles = rest.triangles;
  model.surfaceVertexCount = static_cast<int>(rest.vertices.rows());
  model.restSource = restName;
  model.exampleSources = exampleNames;
  if (options.tetrise) {
    std::vector<TetMesh> meshes = tetriseCompatible(rest, examples, exampleNames);
    model.rest = std::move(meshes.front());
    for (std::size_t k = 1; k < meshes.size(); ++k) model.examples.push_back(meshes[k].vertices);
    advance(messages, exampleNames.size() + 1);
    return model;
  }
  TetGenOptions tetgen;
  tetgen.maxRadiusEdgeRatio = options.radiusEdgeRatio;
  tetgen.maxTetVolume = options.maxVolume.value_or(0.0);
  tetgen.sourceName = restName;
  const TetMesh tets = tetrahedralize(closed, tetgen);
  advance(messages, 1);
  if (tets.tets.rows() > kLargeMeshWarningTets) {
    say(messages.warning, restName + ": " + roughCount(tets.tets.rows()) +
                              " tets; preparing and each blend need " + "about " +
                              formatNumber(std::round(tets.tets.rows() / 1e5) / 10) +
                              " GB of memory (a coarser mesh: a larger --quality, e.g. 3)");
  }
  std::vector<Vertices> surfaces;
  for (const SurfaceMesh& example : examples) surfaces.push_back(example.vertices);
  CompatibleTetMeshes built = buildCompatibleTetMeshes(
      tets, model.surfaceVertexCount, surfaces, ExampleAwareOptions{}, [&](const char* stage) {
        if (std::string(stage) == "place") advance(messages, 1);
      });
  model.rest = std::move(built.rest);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    CompatibleTetResult& placed = built.examples[k];
    if (!placed.invertedTets.empty()) {
      const std::string what = exampleNames[k] + ": " + std::to_string(placed.invertedTets.size()) +
                               " tets cannot be embedded (worst volume ratio " +
                               threeDigits(worstVolumeRatio(model.rest, placed)) + ", first tet " +
                               std::to_string(placed.invertedTets.front()) + "); " +
                               diagnosis(built.selfIntersections[k]);
      if (options.strict) {
        throw InputError(what + ": leave out --strict to exclude those tets from the stitch");
      }
      say(messages.warning, what + ": they are left out of the stitch of every blend");
      model.excludedTets.insert(model.excludedTets.end(), placed.invertedTets.begin(),
                                placed.invertedTets.end());
    }
    model.examples.push_back(std::move(placed.vertices));
  }
  std::sort(model.excludedTets.begin(), model.excludedTets.end());
  model.excludedTets.erase(std::unique(model.excludedTets.begin(), model.excludedTets.end()),
                           model.excludedTets.end());
  const std::string filled =
      filling.holeCount == 0
          ? ""
          : "; filled " + std::to_string(filling.holeCount) + " hole" +
                (filling.holeCount > 1 ? "s" : "") + " with " +
                std::to_string(filling.triangles.rows()) +
                " triangles, no new vertices (the blended surfaces keep the input's faces)";
  say(messages.note, restName + ": " + roughCount(model.rest.tets.rows()) + " tets, " +
                         std::to_string(model.rest.vertices.rows()) + " vertices (" +
                         std::to_string(built.steinerPoints) +
                         " Steiner points added for the examples in " +
                         std::to_string(built.rounds) + " rounds; " +
                         std::to_string(model.excludedTets.size()) + " tets excluded)" + filled);
  return model;
}

}  // namespace tetblend
