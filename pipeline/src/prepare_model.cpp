#include "tetblend/pipeline/prepare_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "meshable_input.h"
#include "meshed_rest.h"
#include "model_join.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/component_meshing.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/hole_filling.h"
#include "tetblend/meshing/seam_welding.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_orientation.h"
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
  return line + "; " + std::to_string(embedded.invertedTets.size()) +
         " tets of the rest cannot be embedded (worst volume ratio " +
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

// --strict fails fast: an example whose surface intersects itself is refused
// before any meshing, since some of its tets can never be embedded. With
// `faceComponent` (components meshed each on its own), only faces of one
// component count.
void refuseSelfIntersecting(const Triangles& triangles, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames,
                            const std::vector<int>& faceComponent = {}) {
  for (std::size_t k = 0; k < examples.size(); ++k) {
    const SelfIntersections found =
        faceComponent.empty()
            ? findSelfIntersections(examples[k].vertices, triangles, 1)
            : findSelfIntersections(examples[k].vertices, triangles, 1, faceComponent);
    if (found.pairCount > 0) {
      throw InputError(exampleNames[k] + ": " + diagnosis(found) +
                       ", so some tets cannot be embedded: repair the pose, or leave out --strict "
                       "to exclude those tets from the stitch");
    }
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
                     " copies of seam vertices were merged)");
  }
}

// Refuses an example that is not the rest's surface; warns about one whose
// quads are split the other way, and about one equal to the rest.
void checkExamples(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                   const std::string& restName, const std::vector<std::string>& exampleNames,
                   const PrepareMessages& messages) {
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
    const int flips = examples[k].triangles == rest.triangles
                          ? 0
                          : flippedQuadDiagonals(rest.triangles, examples[k].triangles);
    if (flips > 0) {
      say(messages.warning, exampleNames[k] + ": " + std::to_string(flips) +
                                " quads are split along the other diagonal than in the rest (an "
                                "exporter that triangulates each frame by its shape): the rest's "
                                "triangles are used for every example");
    }
    if (examples[k].vertices == rest.vertices) {
      say(messages.warning, exampleNames[k] + ": every vertex equals the rest's (" + restName +
                                "): blending this example changes nothing");
    }
  }
}

// The model of the per-face tetrisation: the user's surface as it is (open
// or not, seams and all, crossing itself, pinched or oriented any way: each
// face's tet is its own), no interior.
ModelData tetrisedModel(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                        const std::string& restName, const std::vector<std::string>& exampleNames,
                        const PrepareOptions& options, const PrepareMessages& messages) {
  SurfaceValidationOptions validation;
  validation.requireClosed = false;
  validation.requireSolid = false;
  validation.checkSelfIntersections = false;
  requireValidRest(rest, restName, validation);
  checkExamples(rest, examples, restName, exampleNames, messages);
  if (options.strict) refuseSelfIntersecting(rest.triangles, examples, exampleNames);
  advance(messages, 1);
  ModelData model;
  model.surfaceTriangles = rest.triangles;
  model.surfaceVertexCount = static_cast<int>(rest.vertices.rows());
  model.restSource = restName;
  model.exampleSources = exampleNames;
  std::vector<TetMesh> meshes = tetriseCompatible(rest, examples, exampleNames);
  model.rest = std::move(meshes.front());
  for (std::size_t k = 1; k < meshes.size(); ++k) model.examples.push_back(meshes[k].vertices);
  advance(messages, exampleNames.size() + 1);
  return model;
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
    model = prepareModel(input.rest, input.examples, restName, exampleNames, options, messages);
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

// Per face of the input, 1 where its component (of the zipped surface)
// cannot be meshed with an interior on its own (meshedRest refuses it: an
// open sheet no fill closes, faces that cross too deeply, ...), else 0.
std::vector<int> componentsWithoutInterior(const SeamWelding& welding, const std::string& restName,
                                           const PrepareOptions& options, int& count) {
  std::vector<int> faceComponent;
  const std::vector<SurfaceComponent> components =
      surfaceComponents(welding.surface, &faceComponent);
  std::vector<int> refused(components.size(), 0);
  count = 0;
  for (std::size_t c = 0; c < components.size(); ++c) {
    if (components.size() == 1) {  // the surface itself, which meshing refused
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
  const auto count = static_cast<int>(surfaceComponents(welding.surface, &faceComponent).size());
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
          prepareModel(part.rest, part.examples, restName, exampleNames, options, warningsOnly);
    } catch (const InputError& error) {
      throw InputError(std::string(error.what()) + where);
    }
    tets += prepared.model.rest.tets.rows();
    parts.push_back(std::move(prepared));
  }
  say(messages.note, std::string(refusal.what()) + "; instead, each of its " +
                         std::to_string(count) + " components is prepared on its own (" +
                         roughCount(tets) + " tets in all)");
  advance(messages, prepareStepCount(examples.size()));
  return joinedModel(parts, rest.triangles, static_cast<int>(rest.vertices.rows()));
}

// When meshing refused the rest (`refusal`): the components that cannot be
// meshed with an interior on their own get one tet per face (the
// tetrisation), the others are prepared as usual, and the two models are
// joined; when every component meshes on its own, eachComponentOnItsOwn.
// Rethrows `refusal` with --no-fill-holes or --strict, or when the
// tetrisation refuses the components that do not mesh.
ModelData withComponentsTetrised(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                                 const std::string& restName,
                                 const std::vector<std::string>& exampleNames,
                                 const PrepareOptions& options, const PrepareMessages& messages,
                                 const SeamWelding& welding, const InputError& refusal) {
  if (!options.fillHoles || options.strict) throw refusal;
  int count = 0;
  const std::vector<int> label = componentsWithoutInterior(welding, restName, options, count);
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
  for (SurfaceMesh& example : sheets.examples) example.triangles = sheets.rest.triangles;
  ModelPart tetrised{{}, sheets.inputVertices};
  try {
    tetrised.model = tetrisedModel(sheets.rest, sheets.examples, restName, exampleNames, options,
                                   PrepareMessages{});
  } catch (const InputError& error) {
    throw InputError(
        std::string(refusal.what()) + "; meshing " +
        (count == 1 ? std::string("the component") : std::to_string(count) + " components") +
        " that cannot be filled with tets face by face fails too: " + error.what());
  }
  if (sheets.rest.triangles.rows() == rest.triangles.rows()) {
    const std::string reason = refusal.what();
    say(messages.note,
        reason + "; instead, each of its " + std::to_string(rest.triangles.rows()) +
            " faces gets a tet of its own, as with --tetrise, and blends without an interior");
  } else {
    const auto firstFace = std::find(label.begin(), label.end(), 1) - label.begin();
    say(messages.note, restName + ": " + std::to_string(count) +
                           " of its components (first: the one of face " +
                           std::to_string(firstFace) +
                           ") cannot be filled with tets on their own (open sheets that no fill "
                           "without new vertices closes, or faces that cross): each of their " +
                           std::to_string(sheets.rest.triangles.rows()) +
                           " faces gets a tet of its own, as with --tetrise, and blends without "
                           "an interior");
  }
  const InputPart solids = inputPart(rest, examples, label, 0);
  ModelPart meshedPart{{}, solids.inputVertices};
  if (solids.rest.triangles.rows() == 0) {
    meshedPart.model.examples.assign(examples.size(), Vertices(0, 3));
    advance(messages, prepareStepCount(examples.size()));
  } else {
    try {
      meshedPart.model =
          prepareModel(solids.rest, solids.examples, restName, exampleNames, options, messages);
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
  const SeamWelding welding = weldSeams(rest);
  const std::vector<Vertices> candidates = zippedPositions(rest, welding, examples, exampleNames);
  MeshedRest meshed;
  try {
    meshed = meshedZippedRest(welding, restName, options, candidates);
  } catch (const InputError& refusal) {
    return withComponentsTetrised(rest, examples, restName, exampleNames, options, messages,
                                  welding, refusal);
  }
  if (meshed.reorientedFaces > 0) {
    say(messages.warning, restName + ": " + std::to_string(meshed.reorientedFaces) +
                              " faces point inwards or against their neighbours: they are meshed "
                              "reversed (the blended surfaces keep the input's faces)");
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
  checkExamples(rest, examples, restName, exampleNames, messages);
  ModelData model;
  model.surfaceTriangles = rest.triangles;
  model.restSource = restName;
  model.exampleSources = exampleNames;
  // The examples on the zipped surface's vertices.
  std::vector<SurfaceMesh> zipped;
  for (std::size_t k = 0; k < examples.size(); ++k) {
    zipped.push_back({weldedPositions(welding, examples[k].vertices, exampleNames[k]),
                      welding.surface.triangles});
  }
  if (welding.mergedVertices > 0) {
    say(messages.note, restName + ": " + std::to_string(welding.mergedVertices) +
                           " vertices split along texture or normal seams are merged with their " +
                           "copies for meshing (" + std::to_string(welding.seamEdges) +
                           " seam edges zipped); the blended surfaces keep the input's vertices " +
                           "and faces");
  }
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
      const std::string what = exampleNames[k] + ": " +
                               std::to_string(example.invertedTets.size()) +
                               " tets cannot be embedded (worst volume ratio " +
                               threeDigits(worstVolumeRatio(built.rest, example)) + ", first tet " +
                               std::to_string(example.invertedTets.front()) + "); " +
                               diagnosis(built.selfIntersections[k + first]);
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
                         std::to_string(built.steinerPoints) +
                         " Steiner points added for the examples in " +
                         std::to_string(built.rounds) + " rounds; " +
                         std::to_string(model.excludedTets.size()) + " tets excluded)" + filled);
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
