#include "prepare_steps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "tetblend/core/error.h"
#include "tetblend/meshing/collapsed_faces.h"
#include "tetblend/meshing/surface_orientation.h"
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

std::string counted(std::size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string threeDigits(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

std::string diagnosis(const SelfIntersections& found, std::size_t collapsedFaces) {
  if (found.pairCount == 0 && collapsedFaces > 0) {
    return "its surface collapses " + std::to_string(collapsedFaces) + " face" +
           (collapsedFaces > 1 ? "s" : "") +
           " to (almost) zero area (a part scaled to a point?), so the tets on them cannot have "
           "a volume";
  }
  if (found.pairCount == 0) {
    return "its surface does not intersect itself, but the interior could not be placed "
           "without inverting them (a finer rest mesh, --max-volume, may help)";
  }
  return "its surface intersects itself at " + std::to_string(found.pairCount) + " face pair" +
         (found.pairCount > 1 ? "s" : "") + ", first faces " +
         std::to_string(found.pairs.front().first) + " and " +
         std::to_string(found.pairs.front().second);
}

void refuseCollapsedRest(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                         const std::string& restName,
                         const std::vector<std::string>& exampleNames) {
  for (std::size_t k = 0; k < examples.size(); ++k) {
    if (examples[k].vertices.rows() != rest.vertices.rows()) continue;  // refused elsewhere
    const std::vector<int> faces =
        collapsedFaces(examples[k].vertices, rest.vertices, rest.triangles);
    if (faces.empty()) continue;
    const std::size_t n = faces.size();
    throw InputError(
        restName + ": " + std::to_string(n) + (n == 1 ? " face has" : " faces have") +
        " (almost) zero area in the rest but not in " + exampleNames[k] + " (first: face " +
        std::to_string(faces.front()) + "; a part scaled to a point?), so no tet can fill " +
        (n == 1 ? "it" : "them") +
        ": prepare with a frame where the part has its size as the rest, e.g. " + exampleNames[k]);
  }
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

namespace {

// Per component of `faceComponent` (count components), the volume enclosed
// by its faces (Σ det[p0 − c, p1 − c, p2 − c] / 6, c the mean vertex, which
// keeps the terms small for data far from the origin).
std::vector<double> componentVolumes(const Vertices& vertices, const Triangles& triangles,
                                     const std::vector<int>& faceComponent, std::size_t count) {
  const Eigen::RowVector3d centre = vertices.colwise().mean();
  std::vector<double> volumes(count, 0.0);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const int c = faceComponent[static_cast<std::size_t>(f)];
    if (c < 0) continue;
    Eigen::Matrix3d p;
    for (int k = 0; k < 3; ++k) p.row(k) = vertices.row(triangles(f, k)) - centre;
    volumes[static_cast<std::size_t>(c)] += p.determinant() / 6.0;
  }
  return volumes;
}

// How many face pairs of component `c` of `faceComponent` intersect in
// `positions`.
std::size_t pairsWithin(const Vertices& positions, const Triangles& triangles,
                        const std::vector<int>& faceComponent, int c) {
  const SelfIntersections found = findSelfIntersections(
      positions, triangles, std::numeric_limits<std::size_t>::max(), faceComponent);
  return static_cast<std::size_t>(
      std::count_if(found.pairs.begin(), found.pairs.end(), [&](const std::pair<int, int>& pair) {
        return faceComponent[static_cast<std::size_t>(pair.first)] == c;
      }));
}

}  // namespace

void refuseInsideOut(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                     const std::vector<std::string>& exampleNames) {
  std::vector<int> faceComponent;
  const std::vector<SurfaceComponent> components = surfaceComponents(rest, &faceComponent);
  const std::vector<double> restVolumes =
      componentVolumes(rest.vertices, rest.triangles, faceComponent, components.size());
  for (std::size_t k = 0; k < examples.size(); ++k) {
    const std::vector<double> volumes =
        componentVolumes(examples[k].vertices, rest.triangles, faceComponent, components.size());
    for (std::size_t c = 0; c < components.size(); ++c) {
      if (!components[c].closed || !components[c].consistent ||
          !(volumes[c] * restVolumes[c] < 0.0)) {
        continue;
      }
      const int part = static_cast<int>(c);
      if (pairsWithin(examples[k].vertices, rest.triangles, faceComponent, part) >
          pairsWithin(rest.vertices, rest.triangles, faceComponent, part)) {
        continue;  // pushed through itself rather than mirrored
      }
      const std::string where = components.size() == 1
                                    ? "its surface"
                                    : "the closed part of its surface with face " +
                                          std::to_string(components[c].firstFace);
      throw InputError(
          exampleNames[k] + ": " + where + " encloses a volume of " + threeDigits(volumes[c]) +
          " where the rest's encloses " + threeDigits(restVolumes[c]) +
          " and intersects itself no more than there: the example is mirrored (turned inside "
          "out), so no tet there can be embedded; export it without a negative "
          "scale, or mirror it back");
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
