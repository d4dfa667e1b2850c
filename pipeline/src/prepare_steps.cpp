#include "prepare_steps.h"

#include <cmath>
#include <cstdio>

#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tetrisation.h"
#include "tetblend/pipeline/format_number.h"

namespace tetblend::prepare_steps {

void say(const std::function<void(const std::string&)>& sink, const std::string& line) {
  if (sink) sink(line);
}

void advance(const PrepareMessages& messages, std::size_t steps) {
  if (messages.step) messages.step(steps);
}

std::string roughCount(long long n) {
  if (n >= 1000000) return formatNumber(std::round(n / 1e4) / 100) + " M";
  if (n >= 10000) return formatNumber(std::round(n / 1e3)) + " k";
  return std::to_string(n);
}

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

void refuseSelfIntersecting(const Triangles& triangles, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames,
                            const std::vector<int>& faceComponent) {
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

void checkExamples(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                   const std::vector<std::string>& exampleNames, const PrepareMessages& messages) {
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
  }
}

void warnUnchangedExamples(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                           const std::string& restName,
                           const std::vector<std::string>& exampleNames,
                           const PrepareMessages& messages) {
  for (std::size_t k = 0; k < examples.size() && k < exampleNames.size(); ++k) {
    if (examples[k].vertices.rows() == rest.vertices.rows() &&
        examples[k].vertices == rest.vertices) {
      say(messages.warning, exampleNames[k] + ": every vertex equals the rest's (" + restName +
                                "): blending this example changes nothing");
    }
  }
}

ModelData tetrisedModel(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                        const std::string& restName, const std::vector<std::string>& exampleNames,
                        const PrepareOptions& options, const PrepareMessages& messages) {
  SurfaceValidationOptions validation;
  validation.requireClosed = false;
  validation.requireSolid = false;
  validation.checkSelfIntersections = false;
  requireValidRest(rest, restName, validation);
  checkExamples(rest, examples, exampleNames, messages);
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

}  // namespace tetblend::prepare_steps
