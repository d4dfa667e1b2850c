#include "tetblend/meshing/surface_separation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_orientation.h"

namespace tetblend {
namespace {

// Fraction of the way to the one-ring mean that a moved vertex goes per round
// (the classic umbrella step; 1 would collapse a vertex onto its ring).
constexpr double kSmoothingStep = 0.5;
// Inward push of an intersecting face's vertex in its first round, and the
// factor by which it grows each round, in units of the vertex's mean edge
// length: slight contacts part after a round or two, deeper ones after about
// six (0.05 · 1.5^6 ≈ 0.6 edge lengths), and the displacement bound stops
// the rest.
constexpr double kFirstPush = 0.05;
constexpr double kPushGrowth = 1.5;
// No push exceeds this many edge lengths in one round: larger steps fold the
// faces around the vertex.
constexpr double kLargestPush = 0.5;
// The winding number is probed this many edge lengths behind a vertex: well
// inside the overlap of parts that touch, and short of the far side of any
// part thicker than a tenth of an edge.
constexpr double kProbeDepth = 0.1;
// Winding numbers are integers off the surface; halfway marks say "covered
// twice" and "not covered".
constexpr double kDoubleCover = 1.5;
constexpr double kNoCover = 0.5;

// The vertices sharing an edge with each vertex, as compressed rows.
struct VertexRings {
  std::vector<int> start;  // #V + 1
  std::vector<int> neighbours;
};

VertexRings vertexRings(const Triangles& triangles, int vertexCount) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<std::size_t>(triangles.rows()) * 6);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      edges.emplace_back(a, b);
      edges.emplace_back(b, a);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  VertexRings rings;
  rings.start.assign(static_cast<std::size_t>(vertexCount) + 1, 0);
  for (const auto& e : edges) ++rings.start[static_cast<std::size_t>(e.first) + 1];
  for (int v = 0; v < vertexCount; ++v) rings.start[v + 1] += rings.start[v];
  rings.neighbours.reserve(edges.size());
  for (const auto& e : edges) rings.neighbours.push_back(e.second);
  return rings;
}

// Mean length of the edges at each vertex (0 for a vertex on no edge).
std::vector<double> meanEdgeLengths(const Vertices& vertices, const VertexRings& rings) {
  std::vector<double> h(static_cast<std::size_t>(vertices.rows()), 0.0);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const int begin = rings.start[v], end = rings.start[v + 1];
    for (int i = begin; i < end; ++i) {
      h[v] += (vertices.row(rings.neighbours[i]) - vertices.row(v)).norm();
    }
    if (end > begin) h[v] /= end - begin;
  }
  return h;
}

// Area-weighted outward vertex normals, unit length (zero where the faces
// around a vertex cancel).
Vertices vertexNormals(const Vertices& vertices, const Triangles& triangles) {
  Vertices normals = Vertices::Zero(vertices.rows(), 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Eigen::Vector3d a = vertices.row(triangles(f, 0));
    const Eigen::Vector3d b = vertices.row(triangles(f, 1));
    const Eigen::Vector3d c = vertices.row(triangles(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) normals.row(triangles(f, k)) += n;
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0.0) normals.row(v) /= length;
  }
  return normals;
}

}  // namespace

std::optional<SurfaceSeparation> separateSelfIntersections(
    const SurfaceMesh& surface, const SurfaceSeparationOptions& options) {
  const int vertexCount = static_cast<int>(surface.vertices.rows());
  const VertexRings rings = vertexRings(surface.triangles, vertexCount);
  const std::vector<double> edgeLength = meanEdgeLengths(surface.vertices, rings);
  const double diagonal =
      (surface.vertices.colwise().maxCoeff() - surface.vertices.colwise().minCoeff()).norm();
  const double globalBound = options.maxDisplacement * diagonal;

  Vertices current = surface.vertices;
  std::vector<int> pushes(static_cast<std::size_t>(vertexCount), 0);  // rounds each was pushed
  for (int round = 0;; ++round) {
    const SelfIntersections found = findSelfIntersections(
        current, surface.triangles, std::numeric_limits<std::size_t>::max());
    if (found.pairCount == 0) {
      SurfaceSeparation result;
      result.rounds = round;
      for (Eigen::Index v = 0; v < current.rows(); ++v) {
        if (current.row(v) == surface.vertices.row(v)) continue;
        ++result.movedVertices;
        result.largestDisplacement = std::max(
            result.largestDisplacement, (current.row(v) - surface.vertices.row(v)).norm());
      }
      result.vertices = std::move(current);
      return result;
    }
    if (round == options.maxRounds) return std::nullopt;

    // The intersecting faces' vertices and their one-ring are smoothed; the
    // intersecting faces' vertices are pushed too where the solid just
    // behind them is covered twice (two parts overlap: the vertex retreats
    // inwards) or not at all (the two sides of a thin part crossed: it moves
    // outwards), as the winding number there says.
    std::vector<char> onPair(static_cast<std::size_t>(vertexCount), 0);
    for (const auto& pair : found.pairs) {
      for (int face : {pair.first, pair.second}) {
        for (int k = 0; k < 3; ++k) onPair[surface.triangles(face, k)] = 1;
      }
    }
    std::vector<char> smoothed = onPair;
    for (int v = 0; v < vertexCount; ++v) {
      if (!onPair[v]) continue;
      for (int i = rings.start[v]; i < rings.start[v + 1]; ++i) smoothed[rings.neighbours[i]] = 1;
    }
    const SurfaceMesh posed{current, surface.triangles};
    const Vertices normals = vertexNormals(current, surface.triangles);
    Vertices next = current;
    for (int v = 0; v < vertexCount; ++v) {
      if (!smoothed[v]) continue;
      const int begin = rings.start[v], end = rings.start[v + 1];
      if (end == begin) continue;
      Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
      for (int i = begin; i < end; ++i) mean += current.row(rings.neighbours[i]);
      mean /= end - begin;
      next.row(v) += kSmoothingStep * (mean - current.row(v));
      if (onPair[v]) {
        const Eigen::Vector3d behind =
            (current.row(v) - kProbeDepth * edgeLength[v] * normals.row(v)).transpose();
        const double cover = windingNumber(posed, behind);
        const double side = cover > kDoubleCover ? -1.0 : cover < kNoCover ? 1.0 : 0.0;
        if (side != 0.0) {
          const double step = std::min(kFirstPush * std::pow(kPushGrowth, pushes[v]), kLargestPush);
          next.row(v) += side * step * edgeLength[v] * normals.row(v);
          ++pushes[v];
        }
      }
      const double bound = std::max(globalBound, options.maxEdgeLengths * edgeLength[v]);
      if ((next.row(v) - surface.vertices.row(v)).norm() > bound) return std::nullopt;
    }
    current = std::move(next);
  }
}

}  // namespace tetblend
