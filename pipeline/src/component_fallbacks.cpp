#include "component_fallbacks.h"

#include <algorithm>
#include <utility>

#include "meshable_input.h"
#include "meshed_rest.h"
#include "model_join.h"
#include "prepare_steps.h"
#include "tetblend/meshing/component_meshing.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

using prepare_steps::advance;
using prepare_steps::preparedPart;
using prepare_steps::roughCount;
using prepare_steps::say;
using prepare_steps::tetrisedModel;

// "components", or "parts (its components, split at K edges ...)" when
// edges of more than two faces split them (manifoldRegions); `more` goes
// inside the parentheses.
std::string partsNoun(int splitEdges, const std::string& more = "") {
  if (splitEdges == 0) return "components" + (more.empty() ? "" : " (" + more + ")");
  return "parts (its components, split at " + std::to_string(splitEdges) +
         (splitEdges == 1 ? " edge" : " edges") + " of more than two faces" +
         (more.empty() ? "" : "; " + more) + ")";
}

// Per face of the input, 1 where its component (of the zipped surface)
// cannot be meshed with an interior on its own (meshedRest refuses it: an
// open sheet no fill closes, faces that cross too deeply, ...), else 0.
// `splitEdges` receives manifoldRegions' count of edges that split parts.
std::vector<int> componentsWithoutInterior(const SeamWelding& welding, const std::string& restName,
                                           const PrepareOptions& options, int& count,
                                           int& splitEdges) {
  std::vector<int> faceComponent;
  const auto components = static_cast<std::size_t>(
      manifoldRegions(welding.surface.triangles, faceComponent, &splitEdges));
  std::vector<int> refused(components, 0);
  count = 0;
  for (std::size_t c = 0; c < components; ++c) {
    if (components == 1) {  // the surface itself, which meshing refused
      refused[c] = 1;
      ++count;
      break;
    }
    const SurfacePart part = surfacePart(welding.surface, faceComponent, static_cast<int>(c));
    try {
      meshedRest(part.surface, restName, options);
    } catch (const InputError&) {
      refused[c] = 1;
      ++count;
    }
  }
  std::vector<int> label(faceComponent.size());
  for (std::size_t f = 0; f < label.size(); ++f) {
    label[f] = faceComponent[f] < 0 ? 0 : refused[static_cast<std::size_t>(faceComponent[f])];
  }
  return label;
}

// The part of the input (rest and examples) whose faces `label` marks
// `which`, as a surface of its own.
struct InputPart {
  SurfaceMesh rest;
  std::vector<SurfaceMesh> examples;
  std::vector<int> inputVertices;
};

InputPart inputPart(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                    const std::vector<int>& label, int which) {
  SurfacePart part = surfacePart(rest, label, which);
  InputPart result{std::move(part.surface), {}, std::move(part.vertexRows)};
  for (const SurfaceMesh& example : examples) {
    Vertices positions(static_cast<Eigen::Index>(result.inputVertices.size()), 3);
    for (std::size_t i = 0; i < result.inputVertices.size(); ++i) {
      positions.row(static_cast<Eigen::Index>(i)) = example.vertices.row(result.inputVertices[i]);
    }
    result.examples.push_back({std::move(positions), result.rest.triangles});
  }
  return result;
}

// Faces of `surface` the tetrisation can give no tet: zero area (no normal)
// or the same three vertices as an earlier face; ascending.
std::vector<int> facesWithoutATet(const SurfaceMesh& surface) {
  SurfaceValidationOptions faces;
  faces.requireClosed = false;
  faces.requireSolid = false;
  faces.checkSelfIntersections = false;
  std::vector<int> result;
  for (const SurfaceProblem& problem : validateSurface(surface, "", faces).problems) {
    if (problem.kind == SurfaceProblemKind::kZeroAreaFace ||
        problem.kind == SurfaceProblemKind::kDuplicateFace) {
      result.push_back(static_cast<int>(problem.element));
    }
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

// When meshing refused the rest (`refusal`) although each of its components
// meshes on its own (components touching at a vertex, where their holes
// meet): each component is prepared on its own (notes silenced, warnings
// kept) and the models are joined. Rethrows `refusal` for one component.
ModelData eachComponentOnItsOwn(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                                const std::string& restName,
                                const std::vector<std::string>& exampleNames,
                                const PrepareOptions& options, const PrepareMessages& messages,
                                const SeamWelding& welding, const InputError& refusal) {
  std::vector<int> faceComponent;
  int splitEdges = 0;
  const int count = manifoldRegions(welding.surface.triangles, faceComponent, &splitEdges);
  if (count < 2) throw refusal;
  std::vector<ModelPart> parts;
  Eigen::Index tets = 0;
  for (int c = 0; c < count; ++c) {
    const auto firstFace =
        std::find(faceComponent.begin(), faceComponent.end(), c) - faceComponent.begin();
    const std::string where = " (in its component of face " + std::to_string(firstFace) +
                              ", prepared on its own: the numbers count that component's own "
                              "faces, vertices and tets)";
    PrepareMessages warningsOnly;
    if (messages.warning) {
      warningsOnly.warning = [&](const std::string& line) { messages.warning(line + where); };
    }
    InputPart part = inputPart(rest, examples, faceComponent, c);
    ModelPart prepared{{}, std::move(part.inputVertices)};
    try {
      prepared.model =
          preparedPart(part.rest, part.examples, restName, exampleNames, options, warningsOnly);
    } catch (const InputError& error) {
      throw InputError(std::string(error.what()) + where);
    }
    tets += prepared.model.rest.tets.rows();
    parts.push_back(std::move(prepared));
  }
  say(messages.note, std::string(refusal.what()) + "; instead, each of its " +
                         std::to_string(count) + " " + partsNoun(splitEdges) +
                         " is prepared on its own (" + roughCount(tets) + " tets in all)");
  advance(messages, prepareStepCount(examples.size()));
  return joinedModel(parts, rest.triangles, static_cast<int>(rest.vertices.rows()));
}

}  // namespace

ModelData preparedPartByPart(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                             const std::string& restName,
                             const std::vector<std::string>& exampleNames,
                             const PrepareOptions& options, const PrepareMessages& messages,
                             const SeamWelding& welding, const InputError& refusal) {
  if (!options.fillHoles || options.strict) throw refusal;
  int count = 0, splitEdges = 0;
  const std::vector<int> label =
      componentsWithoutInterior(welding, restName, options, count, splitEdges);
  if (count == 0) {
    return eachComponentOnItsOwn(rest, examples, restName, exampleNames, options, messages, welding,
                                 refusal);
  }
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
  }
  InputPart sheets = inputPart(rest, examples, label, 1);
  try {
    orientConsistently(sheets.rest);  // the tets only: the model keeps the input's faces
  } catch (const InputError&) {
  }
  const std::vector<int> flat = facesWithoutATet(sheets.rest);
  sheets.rest = withoutFaces(sheets.rest, flat);
  for (SurfaceMesh& example : sheets.examples) example.triangles = sheets.rest.triangles;
  ModelPart tetrised{{}, sheets.inputVertices};
  try {
    // A vertex only the flat faces used follows the examples linearly
    // (meshable_input.h), as in any model of the tetrisation.
    PrepareOptions perFace = options;
    perFace.tetrise = true;
    tetrised.model = preparedPart(sheets.rest, sheets.examples, restName, exampleNames, perFace,
                                  PrepareMessages{});
  } catch (const InputError& error) {
    throw InputError(
        std::string(refusal.what()) + "; meshing " +
        (count == 1 ? std::string("the component") : std::to_string(count) + " components") +
        " that cannot be filled with tets face by face fails too: " + error.what());
  }
  const std::string flatFaces =
      flat.empty()       ? ""
      : flat.size() == 1 ? std::string(" (1 face of zero area or repeating another gets none)")
                         : " (" + std::to_string(flat.size()) +
                               " faces of zero area or repeating another get none)";
  if (label.end() == std::find(label.begin(), label.end(), 0)) {
    const std::string reason = refusal.what();
    const Eigen::Index faces = rest.triangles.rows();
    say(messages.note, reason + "; instead, " +
                           (faces == 1 ? std::string("its face gets")
                                       : "each of its " + std::to_string(faces) + " faces gets") +
                           " a tet of its own, as with --tetrise" + flatFaces +
                           ", and blends without an interior");
  } else {
    const auto firstFace = std::find(label.begin(), label.end(), 1) - label.begin();
    say(messages.note,
        restName + ": " + std::to_string(count) + " of its " +
            partsNoun(splitEdges, "first: the one of face " + std::to_string(firstFace)) +
            " cannot be filled with tets on their own (open sheets that no fill "
            "without new vertices closes, or faces that cross): each of their " +
            std::to_string(sheets.rest.triangles.rows() + static_cast<Eigen::Index>(flat.size())) +
            " faces gets a tet of its own, as with --tetrise" + flatFaces +
            ", and blends without an interior");
  }
  const InputPart solids = inputPart(rest, examples, label, 0);
  ModelPart meshedPart{{}, solids.inputVertices};
  if (solids.rest.triangles.rows() == 0) {
    meshedPart.model.examples.assign(examples.size(), Vertices(0, 3));
    advance(messages, prepareStepCount(examples.size()));
  } else {
    try {
      meshedPart.model =
          preparedPart(solids.rest, solids.examples, restName, exampleNames, options, messages);
    } catch (const InputError& error) {
      throw InputError(std::string(error.what()) +
                       " (vertex and face numbers count the surface without the components "
                       "tetrised face by face)");
    }
  }
  meshedPart.model.restSource = restName;
  meshedPart.model.exampleSources = exampleNames;
  return joinedModel({meshedPart, tetrised}, rest.triangles,
                     static_cast<int>(rest.vertices.rows()));
}

}  // namespace tetblend
