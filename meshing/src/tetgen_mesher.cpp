#include "tetblend/meshing/tetgen_mesher.h"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "half_edge_table.h"
#include "spatial_order.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetgen_child_process.h"

namespace tetblend {
namespace {

// The automatic time limit of the quality refinement (qualityTimeLimit):
// kQualityTimeFloorSeconds plus kQualityTimeSlack times TetGen's usual time
// for the tets expected, at kTetGenSecondsPerTet (bench_meshing: 1 M tets in
// 4.5-6.6 s on the 2-core machine). The tets expected are the larger of
// kExpectedTetsPerFace per input face (2-3 measured for CGAL's scans with
// the default quality bound and no volume bound: armadillo 2.6, bunny 2.2)
// and the solid's volume over the volume bound.
constexpr double kQualityTimeFloorSeconds = 30.0;
constexpr double kQualityTimeSlack = 20.0;
constexpr double kTetGenSecondsPerTet = 6.6e-6;
constexpr double kExpectedTetsPerFace = 4.0;
// A region of tets counts as inside the solid when the winding number of one
// of its tets' centroids exceeds this (exactly 1 inside, 0 outside).
constexpr double kInsideWinding = 0.5;
// Outward faces of a positively oriented tet, as corner positions.
constexpr std::array<std::array<int, 3>, 4> kTetFaces{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

std::string formatFixed(double x) {
  // TetGen's -q parser reads digits and '.' only: no exponent, no sign.
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", x);
  return buffer;
}

std::string formatSeconds(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3g", seconds);
  return buffer;
}

std::string formatGeneral(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// The volume bound of `options` in file units cubed; 0 = none.
double volumeBound(const TetGenOptions& options, double diagonal) {
  double maxVolume = options.maxTetVolume;
  if (options.maxTetVolumeRelative > 0.0) {
    const double relative = options.maxTetVolumeRelative * diagonal * diagonal * diagonal;
    maxVolume = maxVolume > 0.0 ? std::min(maxVolume, relative) : relative;
  }
  return maxVolume;
}

// TetGen's output switches: Q (silent) or V (verbose) by options.verbosity.
std::string reportSwitches(const TetGenOptions& options) {
  if (options.verbosity <= 0) return "Q";
  return options.verbosity >= 2 ? "V" : "";
}

// p: the input is a piecewise linear complex; z: zero-based indices;
// Y: keep the boundary (no Steiner point on it, input vertices first).
constexpr const char* kPlainSwitches = "pzY";

std::string buildSwitches(const TetGenOptions& options, double diagonal) {
  if (options.maxRadiusEdgeRatio != 0.0 && !(options.maxRadiusEdgeRatio > 1.0)) {
    throw InputError(
        "TetGenOptions::maxRadiusEdgeRatio = " + formatGeneral(options.maxRadiusEdgeRatio) +
        ": use 0 (no quality refinement) or a bound above 1 (TetGen's default 2)");
  }
  if (!(options.minDihedralAngleDeg >= 0.0 && options.minDihedralAngleDeg < 60.0) ||
      !(options.maxTetVolume >= 0.0) || !(options.maxTetVolumeRelative >= 0.0)) {
    throw InputError(
        "TetGenOptions: minDihedralAngleDeg must lie in [0, 60) degrees and the "
        "volume bounds must be >= 0 (0 = no bound)");
  }
  if (std::isnan(options.qualityTimeLimitSeconds)) {
    throw InputError(
        "TetGenOptions::qualityTimeLimitSeconds is NaN: use seconds > 0, 0 (automatic) or a "
        "negative value (no limit)");
  }
  std::string s = kPlainSwitches;
  if (options.maxRadiusEdgeRatio > 0.0) {
    s += "q" + formatFixed(options.maxRadiusEdgeRatio);
    if (options.minDihedralAngleDeg > 0.0) s += "/" + formatFixed(options.minDihedralAngleDeg);
  }
  const double maxVolume = volumeBound(options, diagonal);
  if (maxVolume > 0.0) s += "a" + formatGeneral(maxVolume);
  return s + reportSwitches(options);
}

// Seconds TetGen may take with `options` (kQualityTimeFloorSeconds above);
// 0 = no limit (no quality refinement, or a negative limit asked for).
double qualityTimeLimit(const SurfaceMesh& surface, const TetGenOptions& options, double diagonal) {
  if (options.maxRadiusEdgeRatio <= 0.0 || options.qualityTimeLimitSeconds < 0.0) return 0.0;
  if (options.qualityTimeLimitSeconds > 0.0) return options.qualityTimeLimitSeconds;
  double expectedTets = kExpectedTetsPerFace * static_cast<double>(surface.triangles.rows());
  const double maxVolume = volumeBound(options, diagonal);
  if (maxVolume > 0.0) {
    expectedTets = std::max(expectedTets, std::abs(enclosedVolume(surface)) / maxVolume);
  }
  return kQualityTimeFloorSeconds + kQualityTimeSlack * kTetGenSecondsPerTet * expectedTets;
}

// TetGen 1.5 terminatetetgen() codes (tetgen.h), as typed errors naming the
// surface.
[[noreturn]] void throwTetGenError(int code, const std::string& source) {
  const std::string prefix = source + ": TetGen failed (code " + std::to_string(code) + "): ";
  switch (code) {
    case 1:
      throw Error(prefix +
                  "out of memory; reduce the refinement (larger maxTetVolume, "
                  "maxRadiusEdgeRatio) or free memory");
    case 2:
      throw NumericalError(prefix +
                           "internal error; try other quality options, or "
                           "remesh the surface more evenly");
    case 3:
      throw InputError(prefix +
                       "the surface intersects itself; repair it (run "
                       "validateSurface to name the faces)");
    case 4:
      throw InputError(prefix +
                       "a very small input feature (nearly coincident vertices or "
                       "edges relative to the bounding box); merge or remesh them");
    case 5:
      throw InputError(prefix +
                       "two input facets are very close to each other; move them "
                       "apart or remesh that region");
    case 10:
      throw InputError(prefix +
                       "invalid input (e.g. all vertices nearly identical, or a "
                       "face that cannot be recovered); check the surface");
    default:
      throw Error(prefix + "unknown TetGen error code");
  }
}

// TetGen's mesh of `surface` with `switches`, or nothing when it had not
// finished after `timeLimitSeconds` (0: no limit).
std::optional<TetMesh> runTetGen(const SurfaceMesh& surface, const std::string& switches,
                                 const TetGenOptions& options, double timeLimitSeconds) {
  tetgenio in;
  const int nv = static_cast<int>(surface.vertices.rows());
  const int nf = static_cast<int>(surface.triangles.rows());
  in.firstnumber = 0;
  in.numberofpoints = nv;
  in.pointlist = new REAL[3 * static_cast<std::size_t>(nv)];
  std::copy(surface.vertices.data(), surface.vertices.data() + 3 * nv, in.pointlist);
  in.numberoffacets = nf;
  in.facetlist = new tetgenio::facet[static_cast<std::size_t>(nf)];
  for (int f = 0; f < nf; ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = surface.triangles(f, k);
  }
  detail::TetGenChildResult run =
      detail::runTetGenInChild(switches, in, /*silence=*/options.verbosity <= 0, timeLimitSeconds);
  switch (run.status) {
    case detail::TetGenChildStatus::kOk:
      break;
    case detail::TetGenChildStatus::kTimedOut:
      return std::nullopt;
    case detail::TetGenChildStatus::kTetGenError:
      throwTetGenError(run.code, options.sourceName);
    case detail::TetGenChildStatus::kSignal:
      throw InputError(options.sourceName + ": TetGen crashed (signal " + std::to_string(run.code) +
                       ", " + run.detail +
                       ") on this surface; check it for nearly touching facets or tiny "
                       "features (validateSurface), or remesh it");
    case detail::TetGenChildStatus::kBrokenChild:
      throw Error(options.sourceName + ": could not run TetGen in a child process: " + run.detail);
  }
  if (run.corners != 4 || run.points.rows() < nv) {
    throw NumericalError("TetGen returned " + std::to_string(run.points.rows()) +
                         " points (input " + std::to_string(nv) + ") and " +
                         std::to_string(run.corners) + "-corner elements: unusable");
  }
  TetMesh mesh;
  mesh.vertices = std::move(run.points);
  mesh.tets = std::move(run.tets);
  if (std::memcmp(mesh.vertices.data(), surface.vertices.data(),
                  sizeof(double) * 3 * static_cast<std::size_t>(nv)) != 0) {
    throw NumericalError("TetGen moved or reordered the surface vertices despite switch Y");
  }
  if (mesh.tets.size() > 0 &&
      (mesh.tets.minCoeff() < 0 || mesh.tets.maxCoeff() >= mesh.vertices.rows())) {
    throw NumericalError("TetGen returned a tet index out of range");
  }
  return mesh;
}

// Swaps corners 1 and 2 of negatively oriented tets (TetGen's convention is
// the mirror of ours); a flat tet is an error.
void orientPositively(TetMesh& mesh) {
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const double volume = tetSignedVolume(mesh.vertices, mesh.tets.row(t));
    if (volume < 0.0) std::swap(mesh.tets(t, 1), mesh.tets(t, 2));
    if (volume == 0.0) {
      throw NumericalError("TetGen produced a flat tet " + std::to_string(t) +
                           ": remesh the surface more evenly or relax the quality options");
    }
  }
}

using FaceKey = std::array<int, 3>;

FaceKey sortedKey(int a, int b, int c) {
  FaceKey key{a, b, c};
  std::sort(key.begin(), key.end());
  return key;
}

// Rotates a face so its smallest index comes first (orientation kept).
FaceKey rotatedKey(int a, int b, int c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

// Keeps the tets of regions (connected without crossing an input triangle)
// that lie inside the solid, then drops Steiner points no tet uses.
TetMesh keepInside(const TetMesh& mesh, const SurfaceMesh& surface) {
  std::vector<FaceKey> inputFaces;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    inputFaces.push_back(
        sortedKey(surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2)));
  }
  std::sort(inputFaces.begin(), inputFaces.end());
  std::vector<std::pair<FaceKey, int>> faces;
  for (int t = 0; t < static_cast<int>(mesh.tets.rows()); ++t) {
    for (const auto& c : kTetFaces) {
      faces.push_back({sortedKey(mesh.tets(t, c[0]), mesh.tets(t, c[1]), mesh.tets(t, c[2])), t});
    }
  }
  std::sort(faces.begin(), faces.end());
  detail::UnionFind regions(static_cast<std::size_t>(mesh.tets.rows()));
  for (std::size_t i = 1; i < faces.size(); ++i) {
    if (faces[i].first != faces[i - 1].first) continue;
    if (std::binary_search(inputFaces.begin(), inputFaces.end(), faces[i].first)) continue;
    regions.unite(static_cast<std::size_t>(faces[i].second),
                  static_cast<std::size_t>(faces[i - 1].second));
  }
  std::vector<int> inside(static_cast<std::size_t>(mesh.tets.rows()), -1);  // per region root
  std::vector<int> kept;
  for (std::size_t t = 0; t < inside.size(); ++t) {
    int& decision = inside[regions.find(t)];
    if (decision < 0) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k) centroid += mesh.vertices.row(mesh.tets(t, k)).transpose() / 4;
      decision = windingNumber(surface, centroid) > kInsideWinding ? 1 : 0;
    }
    if (decision == 1) kept.push_back(static_cast<int>(t));
  }
  const Eigen::Index nv = surface.vertices.rows();
  std::vector<int> newIndex(static_cast<std::size_t>(mesh.vertices.rows()), -1);
  for (int t : kept) {
    for (int k = 0; k < 4; ++k) newIndex[static_cast<std::size_t>(mesh.tets(t, k))] = 0;
  }
  int next = 0;
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (static_cast<Eigen::Index>(v) < nv && newIndex[v] < 0) {
      throw NumericalError("surface vertex " + std::to_string(v) +
                           " belongs to no tet inside the solid after TetGen");
    }
    if (newIndex[v] == 0) newIndex[v] = next++;
  }
  TetMesh result;
  result.vertices.resize(next, 3);
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (newIndex[v] >= 0) result.vertices.row(newIndex[v]) = mesh.vertices.row(v);
  }
  result.tets.resize(static_cast<Eigen::Index>(kept.size()), 4);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      result.tets(i, k) = newIndex[static_cast<std::size_t>(mesh.tets(kept[i], k))];
    }
  }
  return result;
}

// Postcondition: the boundary faces of the tets are the input triangles.
void checkBoundary(const TetMesh& mesh, const SurfaceMesh& surface) {
  std::vector<std::pair<FaceKey, FaceKey>> faces;  // (sorted, rotated)
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (const auto& c : kTetFaces) {
      const int a = mesh.tets(t, c[0]), b = mesh.tets(t, c[1]), d = mesh.tets(t, c[2]);
      faces.push_back({sortedKey(a, b, d), rotatedKey(a, b, d)});
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<FaceKey> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    if (j - i == 1) boundary.push_back(faces[i].second);
    if (j - i > 2) throw NumericalError("TetGen output has a face shared by more than two tets");
    i = j;
  }
  std::vector<FaceKey> input;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    input.push_back(
        rotatedKey(surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2)));
  }
  std::sort(boundary.begin(), boundary.end());
  std::sort(input.begin(), input.end());
  if (boundary != input) {
    throw NumericalError("the boundary of TetGen's mesh (" + std::to_string(boundary.size()) +
                         " faces) differs from the input surface (" + std::to_string(input.size()) +
                         " faces) despite switch Y: remesh the surface more evenly");
  }
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& closedSurface, const TetGenOptions& options) {
  requireValidRest(closedSurface, options.sourceName);
  const double diagonal = boundingBoxDiagonal(closedSurface.vertices);
  const std::string switches = buildSwitches(options, diagonal);
  const double timeLimit = qualityTimeLimit(closedSurface, options, diagonal);
  std::optional<TetMesh> refined = runTetGen(closedSurface, switches, options, timeLimit);
  if (!refined) {
    refined = runTetGen(closedSurface, kPlainSwitches + reportSwitches(options), options, 0.0);
    if (options.notice) {
      options.notice(options.sourceName + ": TetGen's quality refinement had not finished after " +
                     formatSeconds(timeLimit) +
                     " s (very small angles or nearly touching faces in the surface?); "
                     "meshed without it, the examples refine the interior where they need");
    }
  }
  TetMesh mesh = std::move(*refined);
  orientPositively(mesh);
  mesh = keepInside(mesh, closedSurface);
  checkBoundary(mesh, closedSurface);
  return inSpatialOrder(mesh, static_cast<int>(closedSurface.vertices.rows()));
}

}  // namespace tetblend
