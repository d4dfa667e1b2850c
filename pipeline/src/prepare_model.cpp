#include "tetblend/pipeline/prepare_model.h"

#include <algorithm>
#include <cmath>

#include "component_fallbacks.h"
#include "meshable_input.h"
#include "meshed_rest.h"
#include "prepare_steps.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/component_meshing.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/hole_filling.h"
#include "tetblend/meshing/seam_welding.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tetgen_mesher.h"
#include "tetblend/pipeline/format_number.h"

namespace tetblend {
namespace {

using prepare_steps::advance;
using prepare_steps::checkExamples;
using prepare_steps::counted;
using prepare_steps::diagnosis;
using prepare_steps::preparedPart;
using prepare_steps::refuseCollapsedRest;
using prepare_steps::refuseInsideOut;
using prepare_steps::refuseSelfIntersecting;
using prepare_steps::roughCount;
using prepare_steps::say;
using prepare_steps::tetrisedModel;
using prepare_steps::threeDigits;
using prepare_steps::warnUnchangedExamples;

// Smallest signed volume ratio (example / rest) over the listed tets.
double worstVolumeRatio(const TetMesh& rest, const CompatibleTetResult& placed) {
  double worst = INFINITY;
  for (std::size_t i = 0; i < placed.invertedTets.size(); ++i) {
    const double restVolume = tetSignedVolume(rest.vertices, rest.tets.row(placed.invertedTets[i]));
    worst = std::min(worst, placed.invertedVolumes[i] / restVolume);
  }
  return worst;
}

// The warning for a rest that intersects itself: what was meshed instead,
// and the tets of the rest that its embedding leaves inverted.
std::string separatedRestWarning(const std::string& restName,
                                 const std::vector<std::string>& exampleNames,
                                 const MeshedRest& meshed, const TetMesh& tets,
                                 const CompatibleTetResult& embedded) {
  const Vertices& v = meshed.surface.vertices;
  const double diagonal = (v.colwise().maxCoeff() - v.colwise().minCoeff()).norm();
  std::string line =
      restName + ": its surface intersects itself at " + std::to_string(meshed.intersectingPairs) +
      " face pair" + (meshed.intersectingPairs > 1 ? "s" : "") + ", first faces " +
      std::to_string(meshed.firstPair.first) + " and " + std::to_string(meshed.firstPair.second);
  if (meshed.meshedOnExample >= 0) {
    line += ", too deeply to separate; the tets were made on the surface of " +
            exampleNames[static_cast<std::size_t>(meshed.meshedOnExample)] +
            " (the example nearest the rest that bounds a solid), and the rest is embedded in "
            "them";
  } else {
    line += "; the tets were made on a copy with " + std::to_string(meshed.movedVertices) +
            " vertices moved apart by at most " + threeDigits(meshed.largestDisplacement) + " (" +
            threeDigits(100.0 * meshed.largestDisplacement / diagonal) +
            " % of the bounding-box diagonal), and the rest is embedded in them";
  }
  if (embedded.invertedTets.empty()) return line + " with no tet inverted";
  return line + "; " + counted(embedded.invertedTets.size(), "tet") +
         " of the rest cannot be embedded (worst volume ratio " +
         threeDigits(worstVolumeRatio(tets, embedded)) + ", first tet " +
         std::to_string(embedded.invertedTets.front()) +
         "): they are left out of the stitch of every blend";
}

// The checks that need no surface: examples given, a valid quality bound.
void checkPrepareArguments(std::size_t exampleCount, const PrepareOptions& options) {
  if (exampleCount == 0) throw InputError("give at least one example surface");
  if (options.radiusEdgeRatio != 0.0 && !(options.radiusEdgeRatio > 1.0)) {
    throw InputError("quality must be 0 or greater than 1, got " +
                     formatNumber(options.radiusEdgeRatio));
  }
}

// Each example on the zipped surface's vertices, or no rows where it does
// not fit the rest (checkExamples names the problem later).
std::vector<Vertices> zippedPositions(const SurfaceMesh& rest, const SeamWelding& welding,
                                      const std::vector<SurfaceMesh>& examples,
                                      const std::vector<std::string>& exampleNames) {
  std::vector<Vertices> positions(examples.size());
  for (std::size_t k = 0; k < examples.size(); ++k) {
    if (examples[k].vertices.rows() != rest.vertices.rows()) continue;
    try {
      positions[k] = weldedPositions(welding, examples[k].vertices, exampleNames[k]);
    } catch (const InputError&) {
    }
  }
  return positions;
}

// The meshed rest of the zipped surface; a refusal's vertex numbers then
// count the zipped surface's vertices, and the message says so.
MeshedRest meshedZippedRest(const SeamWelding& welding, const std::string& restName,
                            const PrepareOptions& options, const std::vector<Vertices>& examples) {
  try {
    return meshedRest(welding.surface, restName, options, examples);
  } catch (const InputError& error) {
    if (welding.mergedVertices == 0) throw;
    throw InputError(std::string(error.what()) + " (vertex numbers count the surface after " +
                     std::to_string(welding.mergedVertices) +
                     " vertices at the position of another were merged: seams zipped, touching "
                     "rims joined)");
  }
}

ModelData preparedAsIs(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                       const std::string& restName, const std::vector<std::string>& exampleNames,
                       const PrepareOptions& options, const PrepareMessages& messages);

// prepareModel of the surfaces with the ends of zero-length edges merged,
// without the faces that repeat a vertex and the vertices no face uses,
// which the model then gets back (meshable_input.h). A refusal's numbers
// count the surface without them, and the message says so.
ModelData withoutUnmeshableParts(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                                 const std::string& restName,
                                 const std::vector<std::string>& exampleNames,
                                 const PrepareOptions& options, const PrepareMessages& messages) {
  const MeshableInput input = meshableInput(rest, examples, exampleNames);
  if (input.droppedFaces.empty() && input.copies.empty() && input.loose.empty()) {
    // Zero-length edges whose ends part in an example: left to the meshing.
    return preparedAsIs(rest, examples, restName, exampleNames, options, messages);
  }
  const auto plural = [](std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::vector<std::string> setAside;
  if (!input.copies.empty()) {
    const std::size_t n = input.copies.size();
    const int first = input.copies.front();
    say(messages.note,
        restName + ": " + plural(n, "vertex is", "vertices are") +
            " at the same position as a neighbour in the rest and every example, joined by an "
            "edge of zero length (first: vertex " +
            std::to_string(first) + " at vertex " +
            std::to_string(input.copyOf[static_cast<std::size_t>(first)]) +
            "): merged for meshing (the blended surfaces keep the input's vertices)");
    setAside.push_back(plural(n, "vertex", "vertices") + " merged along zero-length edges");
  }
  if (!input.droppedFaces.empty()) {
    const std::size_t n = input.droppedFaces.size();
    say(messages.note, restName + ": " + plural(n, "face repeats", "faces repeat") +
                           " a vertex (first: face " + std::to_string(input.droppedFaces.front()) +
                           "), covering nothing: left out of the meshing (the blended surfaces "
                           "keep the input's faces)");
    setAside.push_back(plural(n, "face that repeats", "faces that repeat") + " a vertex");
  }
  if (!input.loose.empty()) {
    const std::size_t n = input.loose.size();
    say(messages.note, restName + ": " + plural(n, "vertex is", "vertices are") +
                           " used by no face (first: vertex " +
                           std::to_string(input.loose.front()) + "): " +
                           (n == 1 ? "it is kept out of the tets and follows"
                                   : "they are kept out of the tets and follow") +
                           " the examples linearly");
    setAside.push_back(plural(n, "vertex", "vertices") + " used by no face");
  }
  ModelData model;
  try {
    model = preparedPart(input.rest, input.examples, restName, exampleNames, options, messages);
  } catch (const InputError& error) {
    std::string without = setAside.front();
    for (std::size_t i = 1; i < setAside.size(); ++i) {
      without += (i + 1 == setAside.size() ? " and its " : ", its ") + setAside[i];
    }
    throw InputError(std::string(error.what()) +
                     " (vertex and face numbers count the surface without its " + without + ")");
  }
  restoreInput(model, rest, examples, input);
  return model;
}

// prepareModel of input without faces that repeat a vertex, zero-length
// edges that can be merged, or vertices no face uses: the per-face
// tetrisation, or TetGen with the seams zipped (the model keeps the input's
// vertices and faces).
ModelData preparedAsIs(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                       const std::string& restName, const std::vector<std::string>& exampleNames,
                       const PrepareOptions& options, const PrepareMessages& messages) {
  if (options.tetrise) {
    return tetrisedModel(rest, examples, restName, exampleNames, options, messages);
  }
  // TetGen meshes the rest with its seams zipped; the model keeps the
  // input's vertices and faces.
  const SeamWelding welding = withTouchingRimsJoined(weldSeams(rest), examples);
  const std::vector<Vertices> candidates = zippedPositions(rest, welding, examples, exampleNames);
  MeshedRest meshed;
  try {
    meshed = meshedZippedRest(welding, restName, options, candidates);
  } catch (const InputError& refusal) {
    try {
      return preparedPartByPart(rest, examples, restName, exampleNames, options, messages, welding,
                                refusal);
    } catch (const InputError&) {
      // Where meshing part by part fails too (a whole part collapsed, where
      // single faces of zero area would get no tet), a frame to use as the
      // rest is the remedy that can work; --strict keeps the first refusal.
      if (!options.strict) refuseCollapsedRest(rest, examples, restName, exampleNames);
      throw;
    }
  }
  if (meshed.reorientedFaces > 0) {
    say(messages.warning, restName + ": " + std::to_string(meshed.reorientedFaces) +
                              " faces point inwards or against their neighbours: they are meshed "
                              "reversed (the blended surfaces keep the input's faces)");
  }
  if (meshed.nestedSolids > 0) {
    const bool one = meshed.nestedSolids == 1;
    say(messages.note, restName + ": " + std::to_string(meshed.nestedSolids) +
                           (one ? " closed component inside another faces"
                                : " closed components inside others face") +
                           " outward, as a solid's surface does (a cavity's faces inward): each "
                           "of its " +
                           std::to_string(meshed.componentCount) +
                           " components is meshed on its own, and their tets may overlap");
  }
  if (meshed.overlappingPairs > 0) {
    say(messages.note, restName + ": its " + std::to_string(meshed.componentCount) +
                           " closed components intersect one another (" +
                           std::to_string(meshed.overlappingPairs) +
                           " face pairs): each is meshed on its own, and their tets may overlap");
  }
  if (meshed.flippedFaces > 0) {
    say(messages.note, restName + ": " + std::to_string(meshed.flippedFaces) +
                           " faces of (almost) zero area are re-split with a neighbour for "
                           "meshing (the blended surfaces keep the input's faces)");
  }
  checkExamples(rest, examples, exampleNames, messages);
  ModelData model;
  model.surfaceTriangles = rest.triangles;
  model.restSource = restName;
  model.exampleSources = exampleNames;
  // The examples on the zipped surface's vertices (weldedPositions again
  // only to name an example that opens a seam).
  std::vector<SurfaceMesh> zipped;
  for (std::size_t k = 0; k < examples.size(); ++k) {
    zipped.push_back({candidates[k].rows() > 0
                          ? candidates[k]
                          : weldedPositions(welding, examples[k].vertices, exampleNames[k]),
                      welding.surface.triangles});
  }
  if (welding.seamEdges > 0) {
    say(messages.note,
        restName + ": " + std::to_string(welding.mergedVertices - welding.rimVertices) +
            " vertices split along texture or normal seams are merged with their " +
            "copies for meshing (" + std::to_string(welding.seamEdges) +
            " seam edges zipped); the blended surfaces keep the input's vertices " + "and faces");
  }
  if (welding.rimVertices > 0) {
    say(messages.note, restName + ": " + std::to_string(welding.rimVertices) +
                           " vertices on the rims of its holes at the same position as another "
                           "(holes that touch there) are merged for meshing, and the holes filled "
                           "around them; the blended surfaces keep the input's vertices and faces");
  }
  refuseInsideOut(meshed.surface, zipped, exampleNames);
  if (options.strict) {
    refuseSelfIntersecting(meshed.surface.triangles, zipped, exampleNames, meshed.faceComponent);
  }
  advance(messages, 1);
  model.surfaceVertexCount = static_cast<int>(welding.surface.vertices.rows());
  if (welding.mergedVertices > 0) model.inputVertexRows = welding.rowOf;
  TetGenOptions tetgen;
  tetgen.maxRadiusEdgeRatio = options.radiusEdgeRatio;
  tetgen.maxTetVolume = options.maxVolume.value_or(0.0);
  tetgen.sourceName = restName;
  tetgen.notice = [&](const std::string& line) { say(messages.warning, line); };
  const TetMesh tets = meshed.faceComponent.empty()
                           ? tetrahedralize(meshed.surface, tetgen)
                           : tetrahedralizeEachComponent(meshed.surface, meshed.faceComponent,
                                                         meshed.componentCount, tetgen);
  advance(messages, 1);
  if (tets.tets.rows() > kLargeMeshWarningTets) {
    say(messages.warning, restName + ": " + roughCount(tets.tets.rows()) +
                              " tets; preparing and each blend need " + "about " +
                              formatNumber(std::round(tets.tets.rows() / 1e5) / 10) +
                              " GB of memory (a coarser mesh: a larger --quality, e.g. 3)");
  }
  // A separated rest is embedded in the tets like a pose, before the examples.
  const std::size_t first = meshed.separated ? 1 : 0;
  std::vector<Vertices> surfaces;
  if (meshed.separated) surfaces.push_back(welding.surface.vertices);
  for (const SurfaceMesh& example : zipped) surfaces.push_back(example.vertices);
  std::size_t placed = 0;
  CompatibleTetMeshes built = buildCompatibleTetMeshes(
      tets, model.surfaceVertexCount, surfaces, ExampleAwareOptions{}, [&](const char* stage) {
        if (std::string(stage) == "place" && placed++ >= first) advance(messages, 1);
      });
  if (meshed.separated) {
    const CompatibleTetResult& embedded = built.examples.front();
    say(messages.warning,
        separatedRestWarning(restName, exampleNames, meshed, built.rest, embedded));
    model.excludedTets = embedded.invertedTets;
  }
  for (std::size_t k = 0; k < examples.size(); ++k) {
    CompatibleTetResult& example = built.examples[k + first];
    if (!example.invertedTets.empty()) {
      const std::string what =
          exampleNames[k] + ": " + counted(example.invertedTets.size(), "tet") +
          " cannot be embedded (worst volume ratio " +
          threeDigits(worstVolumeRatio(built.rest, example)) + ", first tet " +
          std::to_string(example.invertedTets.front()) + "); " +
          diagnosis(built.selfIntersections[k + first], built.collapsedFaces[k + first]);
      if (options.strict) {
        throw InputError(what + ": leave out --strict to exclude those tets from the stitch");
      }
      say(messages.warning, what + ": they are left out of the stitch of every blend");
      model.excludedTets.insert(model.excludedTets.end(), example.invertedTets.begin(),
                                example.invertedTets.end());
    }
    model.examples.push_back(std::move(example.vertices));
  }
  model.rest.tets = std::move(built.rest.tets);
  model.rest.vertices = meshed.separated ? std::move(built.examples.front().vertices)
                                         : std::move(built.rest.vertices);
  std::sort(model.excludedTets.begin(), model.excludedTets.end());
  model.excludedTets.erase(std::unique(model.excludedTets.begin(), model.excludedTets.end()),
                           model.excludedTets.end());
  const HoleFilling& filling = meshed.filling;
  const std::string filled =
      filling.holeCount == 0
          ? ""
          : "; filled " + std::to_string(filling.holeCount) + " hole" +
                (filling.holeCount > 1 ? "s" : "") + " with " +
                std::to_string(filling.triangles.rows()) +
                " triangles, no new vertices (the blended surfaces keep the input's faces)";
  say(messages.note, restName + ": " + roughCount(model.rest.tets.rows()) + " tets, " +
                         std::to_string(model.rest.vertices.rows()) + " vertices (" +
                         counted(static_cast<std::size_t>(built.steinerPoints), "Steiner point") +
                         " added for the examples in " +
                         counted(static_cast<std::size_t>(built.rounds), "round") + "; " +
                         counted(model.excludedTets.size(), "tet") + " excluded)" + filled);
  return model;
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
  ModelData model = preparedPart(rest, examples, restName, exampleNames, options, messages);
  warnUnchangedExamples(rest, examples, restName, exampleNames, messages);
  return model;
}

ModelData prepare_steps::preparedPart(const SurfaceMesh& rest,
                                      const std::vector<SurfaceMesh>& examples,
                                      const std::string& restName,
                                      const std::vector<std::string>& exampleNames,
                                      const PrepareOptions& options,
                                      const PrepareMessages& messages) {
  checkPrepareArguments(examples.size(), options);
  if (exampleNames.size() != examples.size()) {
    throw InputError("prepare: " + std::to_string(exampleNames.size()) + " names given for " +
                     std::to_string(examples.size()) + " examples");
  }
  const bool indicesInRange = rest.triangles.size() > 0 && rest.triangles.minCoeff() >= 0 &&
                              rest.triangles.maxCoeff() < rest.vertices.rows();
  if (indicesInRange && hasUnmeshableParts(rest)) {
    return withoutUnmeshableParts(rest, examples, restName, exampleNames, options, messages);
  }
  return preparedAsIs(rest, examples, restName, exampleNames, options, messages);
}

}  // namespace tetblend
