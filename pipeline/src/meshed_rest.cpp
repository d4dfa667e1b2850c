#include "meshed_rest.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "tetblend/core/error.h"
#include "tetblend/meshing/component_meshing.h"
#include "tetblend/meshing/degenerate_faces.h"
#include "tetblend/meshing/seam_welding.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_separation.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/pipeline/format_number.h"

namespace tetblend {
namespace {

// Orients `mesh` consistently and outward where it can; a surface that cannot
// be oriented (non-manifold, Möbius-like) is left as it is, for the
// validation to name the problem.
void orientWherePossible(SurfaceMesh& mesh) {
  try {
    orientConsistently(mesh);
  } catch (const InputError&) {
  }
}

// The user's faces, then the triangles that close its holes (none with
// options.fillHoles off), chosen to fold little in `examples` as well.
SurfaceMesh closedSurface(const SurfaceMesh& oriented, const std::string& restName,
                          const PrepareOptions& options, const std::vector<Vertices>& examples,
                          HoleFilling& filling) {
  if (!options.fillHoles) return oriented;
  filling = fillHoles(oriented, restName, examples);
  SurfaceMesh closed{oriented.vertices,
                     Triangles(oriented.triangles.rows() + filling.triangles.rows(), 3)};
  closed.triangles << oriented.triangles, filling.triangles;
  return closed;
}

// Two vertices on the rims of holes at the same position, the smallest such
// pair of indices, or (-1, -1).
std::pair<int, int> coincidentRimVertices(const SurfaceMesh& surface) {
  const std::vector<char> onRim = rimVertices(surface);
  if (std::find(onRim.begin(), onRim.end(), 1) == onRim.end()) return {-1, -1};  // closed
  const std::vector<int> id = positionIds(surface.vertices);
  std::vector<int> firstAt(id.size(), -1);  // per position, its smallest rim vertex
  std::pair<int, int> smallest{-1, -1};
  for (int v = 0; v < static_cast<int>(id.size()); ++v) {
    if (!onRim[static_cast<std::size_t>(v)]) continue;
    int& first = firstAt[static_cast<std::size_t>(id[static_cast<std::size_t>(v)])];
    if (first < 0) {
      first = v;
    } else if (smallest.first < 0 || std::make_pair(first, v) < smallest) {
      smallest = {first, v};
    }
  }
  return smallest;
}

// An open surface with two rim vertices at one position after its seams
// were zipped and its touching rims joined (seam_welding.h): rims that
// touch there but part in an example, or more than two sheets along one
// edge. No fill without new vertices closes them, and merging the two would
// pinch the surface. (A rim that only touches the surface elsewhere is left
// to the self-intersection checks of the closed surface.)
void refuseTouchingRims(const SurfaceMesh& surface, const std::string& restName) {
  const bool indicesInRange = surface.triangles.size() > 0 && surface.triangles.minCoeff() >= 0 &&
                              surface.triangles.maxCoeff() < surface.vertices.rows();
  if (!surface.vertices.allFinite() || !indicesInRange) return;  // validateSurface names them
  const auto [a, b] = coincidentRimVertices(surface);
  if (a < 0) return;
  throw InputError(restName + ": vertices " + std::to_string(a) + " and " + std::to_string(b) +
                   " are at the same position where the rims of its holes touch, and stay apart "
                   "(they part in an example), so no fill without new vertices closes the "
                   "holes: close them yourself (e.g. MeshLab's Close Holes), or use the per-face "
                   "tetrisation (--tetrise)");
}

// A triangle filling a hole that intersects the surface: the fill is fixed by
// the rest for every example, so it cannot be separated away.
void refuseCutFill(const SelfIntersections& found, Eigen::Index userFaceCount,
                   const std::string& restName) {
  for (const auto& [f, g] : found.pairs) {
    if (std::max(f, g) < userFaceCount) continue;
    const long long face = std::min(f, g);
    throw InputError(
        restName + ": " +
        (face < userFaceCount
             ? "a triangle filling one of its holes intersects face " + std::to_string(face)
             : std::string("two triangles filling its holes intersect")) +
        ": the holes cannot be closed without new vertices; close them yourself, "
        "or use the per-face tetrisation");
  }
}

// The face pairs a validation lists as intersecting.
SelfIntersections listedPairs(const SurfaceValidation& checked) {
  SelfIntersections listed;
  for (const SurfaceProblem& problem : checked.problems) {
    if (problem.kind != SurfaceProblemKind::kSelfIntersection) continue;
    listed.pairs.emplace_back(static_cast<int>(problem.element), static_cast<int>(problem.value));
    ++listed.pairCount;
  }
  return listed;
}

int differingRows(const Triangles& a, const Triangles& b) {
  int count = 0;
  for (Eigen::Index f = 0; f < a.rows(); ++f) count += a.row(f) == b.row(f) ? 0 : 1;
  return count;
}

// Marks `meshed` for meshing each component on its own (`faceComponent`
// from surfaceComponents) and reverses the components that face inwards:
// each must bound its own solid.
void meshComponentsApart(MeshedRest& meshed, const std::vector<SurfaceComponent>& components,
                         std::vector<int> faceComponent) {
  Triangles& triangles = meshed.surface.triangles;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const int c = faceComponent[static_cast<std::size_t>(f)];
    if (c >= 0 && components[static_cast<std::size_t>(c)].signedVolume < 0.0) {
      std::swap(triangles(f, 1), triangles(f, 2));
    }
  }
  meshed.faceComponent = std::move(faceComponent);
  meshed.componentCount = static_cast<int>(components.size());
}

// Closed components inside another (odd nesting depth) that the user's
// faces turn outward, as a solid's (an eyeball in a head, teeth in a
// mouth), where orientConsistently made them cavities: when there are such
// and no nested component the user turned inward (a true cavity), every
// component is meshed on its own, each turned outward. Returns how many.
int markNestedSolids(MeshedRest& meshed, const Triangles& userTriangles) {
  std::vector<int> faceComponent;
  const std::vector<SurfaceComponent> components =
      surfaceComponents(meshed.surface, &faceComponent);
  std::vector<int> kept(components.size(), 0), reversed(components.size(), 0);
  for (Eigen::Index f = 0; f < userTriangles.rows(); ++f) {
    const int c = faceComponent[static_cast<std::size_t>(f)];
    if (c < 0) continue;
    const bool same = meshed.surface.triangles.row(f) == userTriangles.row(f);
    ++(same ? kept : reversed)[static_cast<std::size_t>(c)];
  }
  int solids = 0;
  for (std::size_t c = 0; c < components.size(); ++c) {
    if (!components[c].closed || components[c].nestingDepth % 2 == 0) continue;
    if (reversed[c] <= kept[c]) return 0;  // a true cavity: the components stay together
    ++solids;
  }
  if (solids > 0) meshComponentsApart(meshed, components, std::move(faceComponent));
  return solids;
}

// When faces of different closed components intersect (`found` lists every
// intersecting pair), or the components are already meshed apart, counts
// those pairs, marks `meshed` for meshing each component on its own, and
// returns true.
bool meshEachComponent(MeshedRest& meshed, const SelfIntersections& found) {
  const auto countOverlaps = [&](const std::vector<int>& faceComponent) {
    for (const auto& [f, g] : found.pairs) {
      if (faceComponent[static_cast<std::size_t>(f)] != faceComponent[static_cast<std::size_t>(g)])
        ++meshed.overlappingPairs;
    }
  };
  if (!meshed.faceComponent.empty()) {
    countOverlaps(meshed.faceComponent);
    return true;
  }
  std::vector<int> faceComponent;
  const std::vector<SurfaceComponent> components =
      surfaceComponents(meshed.surface, &faceComponent);
  countOverlaps(faceComponent);
  const bool closed = std::all_of(components.begin(), components.end(),
                                  [](const SurfaceComponent& c) { return c.closed; });
  if (meshed.overlappingPairs == 0 || !closed) {
    meshed.overlappingPairs = 0;
    return false;
  }
  meshComponentsApart(meshed, components, std::move(faceComponent));
  return true;
}

// --strict and a rest whose components intersect themselves.
[[noreturn]] void refuseStrictly(const SelfIntersections& found, const std::string& restName) {
  throw InputError(restName + ": faces " + std::to_string(found.pairs.front().first) + " and " +
                   std::to_string(found.pairs.front().second) +
                   " of one closed component "
                   "intersect (" +
                   std::to_string(found.pairCount) +
                   " such pairs in total), and --strict refuses a rest that intersects itself: "
                   "repair the surface (e.g. CGAL's autorefine or MeshLab), or leave out "
                   "--strict to mesh a separated copy");
}

// The separated copy of the meshed surface (surface_separation.h): whole,
// or component by component when they are meshed each on its own.
std::optional<SurfaceSeparation> separatedSurface(const MeshedRest& meshed,
                                                  const SurfaceSeparationOptions& options) {
  if (meshed.faceComponent.empty()) return separateSelfIntersections(meshed.surface, options);
  SurfaceSeparation whole{meshed.surface.vertices, 0, 0.0, 0};
  for (int c = 0; c < meshed.componentCount; ++c) {
    const SurfacePart part = surfacePart(meshed.surface, meshed.faceComponent, c);
    const auto separated = separateSelfIntersections(part.surface, options);
    if (!separated) return std::nullopt;
    if (separated->movedVertices == 0) continue;
    for (std::size_t i = 0; i < part.vertexRows.size(); ++i) {
      whole.vertices.row(part.vertexRows[i]) =
          separated->vertices.row(static_cast<Eigen::Index>(i));
    }
    whole.movedVertices += separated->movedVertices;
    whole.largestDisplacement = std::max(whole.largestDisplacement, separated->largestDisplacement);
    whole.rounds = std::max(whole.rounds, separated->rounds);
  }
  return whole;
}

// Of `examples`, nearest the rest first (sum of squared distances), the
// first whose positions make `meshed`'s surface, oriented outward for them
// (a rest that crosses itself may have turned it inside out), one that
// bounds a solid (validateSurface: closed, outward, no self-intersection);
// `meshed` then holds it. -1 when there is none.
int meshOnCleanExample(SurfaceMesh& meshed, const std::vector<Vertices>& examples,
                       const std::string& restName) {
  std::vector<std::pair<double, int>> byDistance;
  for (std::size_t k = 0; k < examples.size(); ++k) {
    if (examples[k].rows() != meshed.vertices.rows()) continue;
    byDistance.emplace_back((examples[k] - meshed.vertices).squaredNorm(), static_cast<int>(k));
  }
  std::sort(byDistance.begin(), byDistance.end());
  SurfaceValidationOptions validation;
  validation.maxSelfIntersectionPairs = 1;
  for (const auto& [distance, k] : byDistance) {
    SurfaceMesh posed{examples[static_cast<std::size_t>(k)], meshed.triangles};
    orientWherePossible(posed);
    if (!validateSurface(posed, restName, validation).ok()) continue;
    meshed = std::move(posed);
    return k;
  }
  return -1;
}

}  // namespace

MeshedRest meshedRest(const SurfaceMesh& rest, const std::string& restName,
                      const PrepareOptions& options, const std::vector<Vertices>& examples) {
  MeshedRest meshed;
  SurfaceMesh oriented = rest;
  orientWherePossible(oriented);
  if (options.fillHoles) refuseTouchingRims(oriented, restName);
  meshed.surface = closedSurface(oriented, restName, options, examples, meshed.filling);
  orientWherePossible(meshed.surface);
  meshed.nestedSolids = markNestedSolids(meshed, rest.triangles);
  const Eigen::Index userFaces = rest.triangles.rows();
  meshed.reorientedFaces =
      differingRows(meshed.surface.triangles.topRows(userFaces), rest.triangles);
  meshed.flippedFaces = flipDegenerateFaces(meshed.surface, kDefaultZeroAreaRelTol).flipped;

  SurfaceValidationOptions validation;
  validation.componentsAreSolids = !meshed.faceComponent.empty();
  const SurfaceValidation checked = validateSurface(meshed.surface, restName, validation);
  if (checked.ok()) return meshed;
  const bool onlyIntersections = std::all_of(
      checked.problems.begin(), checked.problems.end(),
      [](const SurfaceProblem& p) { return p.kind == SurfaceProblemKind::kSelfIntersection; });
  if (!onlyIntersections) {
    refuseCutFill(listedPairs(checked), userFaces, restName);
    requireValidRest(meshed.surface, restName, validation);
  }

  SelfIntersections found = findSelfIntersections(meshed.surface.vertices, meshed.surface.triangles,
                                                  std::numeric_limits<std::size_t>::max());
  if (meshEachComponent(meshed, found)) {
    meshed.reorientedFaces =
        differingRows(meshed.surface.triangles.topRows(userFaces), rest.triangles);
    found = findSelfIntersections(meshed.surface.vertices, meshed.surface.triangles,
                                  std::numeric_limits<std::size_t>::max(), meshed.faceComponent);
    if (found.pairCount == 0) return meshed;
    if (options.strict) refuseStrictly(found, restName);
  } else if (options.strict) {
    refuseCutFill(found, userFaces, restName);
    requireValidRest(meshed.surface, restName);
  }
  refuseCutFill(found, userFaces, restName);
  meshed.intersectingPairs = found.pairCount;
  meshed.firstPair = found.pairs.front();
  const SurfaceSeparationOptions separation;
  const auto separated = separatedSurface(meshed, separation);
  if (!separated && meshed.faceComponent.empty()) {
    meshed.meshedOnExample = meshOnCleanExample(meshed.surface, examples, restName);
  }
  if (meshed.meshedOnExample >= 0) {
    meshed.separated = true;
    meshed.reorientedFaces =
        differingRows(meshed.surface.triangles.topRows(userFaces), rest.triangles);
    return meshed;
  }
  if (!separated) {
    throw InputError(restName + ": faces " + std::to_string(meshed.firstPair.first) + " and " +
                     std::to_string(meshed.firstPair.second) + " intersect (" +
                     std::to_string(found.pairCount) + " intersecting pairs in total" +
                     (meshed.faceComponent.empty() ? "" : " within its closed components") +
                     "), too deeply to separate by moving each "
                     "vertex by up to " +
                     formatNumber(100.0 * separation.maxDisplacement) +
                     " % of the bounding-box diagonal or its own edge length: repair the "
                     "surface (e.g. CGAL's autorefine or MeshLab) before meshing, or choose "
                     "as the rest a pose whose surface does not intersect itself (examples "
                     "may)");
  }
  meshed.separated = true;
  meshed.movedVertices = separated->movedVertices;
  meshed.largestDisplacement = separated->largestDisplacement;
  meshed.surface.vertices = std::move(separated->vertices);
  return meshed;
}

}  // namespace tetblend
