#include "tetblend/meshing/seam_welding.h"

#include <algorithm>
#include <array>
#include <tuple>

#include "half_edge_table.h"
#include "surface_messages.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// A boundary edge between the vertices `low` and `high`, keyed by their
// positions (lowPosition < highPosition).
struct BoundaryEdge {
  int lowPosition;
  int highPosition;
  int low;
  int high;
};

bool byPositions(const BoundaryEdge& a, const BoundaryEdge& b) {
  return std::tie(a.lowPosition, a.highPosition) < std::tie(b.lowPosition, b.highPosition);
}

// The boundary edges of `triangles` but those between two vertices at one
// position, sorted by their positions.
std::vector<BoundaryEdge> boundaryEdges(const Triangles& triangles, const std::vector<int>& id) {
  const detail::HalfEdgeTable table =
      detail::buildHalfEdgeTable(triangles, std::vector<char>(triangles.rows(), 0));
  std::vector<BoundaryEdge> result;
  for (const auto& [begin, end] : table.edges) {
    if (end - begin != 1) continue;
    int a = table.halfEdges[begin].lo, b = table.halfEdges[begin].hi;
    if (id[static_cast<std::size_t>(a)] == id[static_cast<std::size_t>(b)]) continue;
    if (id[static_cast<std::size_t>(a)] > id[static_cast<std::size_t>(b)]) std::swap(a, b);
    result.push_back({id[static_cast<std::size_t>(a)], id[static_cast<std::size_t>(b)], a, b});
  }
  std::sort(result.begin(), result.end(), byPositions);
  return result;
}

SeamWelding unchanged(const SurfaceMesh& surface) {
  SeamWelding welding;
  welding.surface = surface;
  welding.rowOf.resize(static_cast<std::size_t>(surface.vertices.rows()));
  for (std::size_t v = 0; v < welding.rowOf.size(); ++v) welding.rowOf[v] = static_cast<int>(v);
  return welding;
}

bool indicesInRange(const SurfaceMesh& surface) {
  return surface.triangles.size() == 0 || (surface.triangles.minCoeff() >= 0 &&
                                           surface.triangles.maxCoeff() < surface.vertices.rows());
}

// `surface` with each group of `groups` merged into its smallest vertex, or
// as it is (nothing merged) when a face would collapse.
SeamWelding merged(const SurfaceMesh& surface, detail::UnionFind& groups) {
  SeamWelding welding;
  welding.rowOf.resize(static_cast<std::size_t>(surface.vertices.rows()));
  std::vector<int> kept;
  for (std::size_t v = 0; v < welding.rowOf.size(); ++v) {
    const std::size_t root = groups.find(v);
    if (root == v) {
      welding.rowOf[v] = static_cast<int>(kept.size());
      kept.push_back(static_cast<int>(v));
    } else {
      welding.rowOf[v] = welding.rowOf[root];  // root < v: already numbered
    }
  }
  welding.mergedVertices = static_cast<int>(welding.rowOf.size() - kept.size());
  if (welding.mergedVertices == 0) return unchanged(surface);
  welding.surface.vertices.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t r = 0; r < kept.size(); ++r) {
    welding.surface.vertices.row(static_cast<Eigen::Index>(r)) = surface.vertices.row(kept[r]);
  }
  welding.surface.triangles.resize(surface.triangles.rows(), 3);
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      welding.surface.triangles(f, c) =
          welding.rowOf[static_cast<std::size_t>(surface.triangles(f, c))];
    }
    const auto t = welding.surface.triangles.row(f);
    if (t(0) == t(1) || t(1) == t(2) || t(0) == t(2)) return unchanged(surface);
  }
  return welding;
}

}  // namespace

std::vector<char> rimVertices(const SurfaceMesh& surface) {
  return detail::rimVertices(surface.triangles, surface.vertices.rows());
}

std::vector<int> positionIds(const Vertices& vertices) {
  std::vector<int> order(static_cast<std::size_t>(vertices.rows()));
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto position = [&](int v) {
    return std::array<double, 3>{vertices(v, 0), vertices(v, 1), vertices(v, 2)};
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return position(a) < position(b); });
  std::vector<int> id(order.size());
  int next = -1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || position(order[i]) != position(order[i - 1])) ++next;
    id[static_cast<std::size_t>(order[i])] = next;
  }
  return id;
}

SeamWelding weldSeams(const SurfaceMesh& surface) {
  if (!surface.vertices.allFinite() || !indicesInRange(surface)) return unchanged(surface);
  const std::vector<int> id = positionIds(surface.vertices);
  const std::vector<BoundaryEdge> edges = boundaryEdges(surface.triangles, id);
  detail::UnionFind groups(static_cast<std::size_t>(surface.vertices.rows()));
  int seamEdges = 0;
  // Exactly two boundary edges between the same two positions are the two
  // sides of a seam, whichever way their faces run them (orientation is
  // made consistent later); one, or three and more, are not.
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t end = i + 1;
    while (end < edges.size() && !byPositions(edges[i], edges[end])) ++end;
    if (end - i == 2) {
      groups.unite(static_cast<std::size_t>(edges[i].low),
                   static_cast<std::size_t>(edges[i + 1].low));
      groups.unite(static_cast<std::size_t>(edges[i].high),
                   static_cast<std::size_t>(edges[i + 1].high));
      ++seamEdges;
    }
    i = end;
  }
  if (seamEdges == 0) return unchanged(surface);

  SeamWelding welding = merged(surface, groups);
  if (welding.mergedVertices > 0) welding.seamEdges = seamEdges;
  return welding;
}

SeamWelding withTouchingRimsJoined(SeamWelding welding, const std::vector<SurfaceMesh>& examples) {
  const SurfaceMesh& surface = welding.surface;
  if (!indicesInRange(surface) || !surface.vertices.allFinite()) return welding;
  const std::vector<char> onRim = rimVertices(surface);
  if (std::find(onRim.begin(), onRim.end(), 1) == onRim.end()) return welding;  // closed
  // An input vertex of each row, to read the examples' positions there.
  std::vector<int> inputOf(onRim.size(), -1);
  for (std::size_t v = welding.rowOf.size(); v-- > 0;) {
    inputOf[static_cast<std::size_t>(welding.rowOf[v])] = static_cast<int>(v);
  }
  const auto together = [&](int a, int b) {
    return std::all_of(examples.begin(), examples.end(), [&](const SurfaceMesh& example) {
      const Vertices& at = example.vertices;
      return at.rows() != static_cast<Eigen::Index>(welding.rowOf.size()) ||
             at.row(inputOf[static_cast<std::size_t>(a)]) ==
                 at.row(inputOf[static_cast<std::size_t>(b)]);
    });
  };
  const std::vector<int> id = positionIds(surface.vertices);
  std::vector<int> firstAt(onRim.size(), -1);  // per position, its first rim vertex
  detail::UnionFind groups(onRim.size());
  for (std::size_t v = 0; v < onRim.size(); ++v) {
    if (!onRim[v]) continue;
    int& first = firstAt[static_cast<std::size_t>(id[v])];
    if (first < 0) {
      first = static_cast<int>(v);
    } else if (together(first, static_cast<int>(v))) {
      groups.unite(static_cast<std::size_t>(first), v);
    }
  }
  const SeamWelding rims = merged(surface, groups);
  if (rims.mergedVertices == 0) return welding;
  for (int& row : welding.rowOf) row = rims.rowOf[static_cast<std::size_t>(row)];
  welding.surface = rims.surface;
  welding.mergedVertices += rims.mergedVertices;
  welding.rimVertices = rims.mergedVertices;
  return welding;
}

Vertices weldedPositions(const SeamWelding& welding, const Vertices& positions,
                         const std::string& sourceName) {
  if (positions.rows() != static_cast<Eigen::Index>(welding.rowOf.size())) {
    throw InputError(sourceName + ": " + std::to_string(positions.rows()) +
                     " vertices, the rest has " + std::to_string(welding.rowOf.size()));
  }
  Vertices result(welding.surface.vertices.rows(), 3);
  std::vector<int> first(static_cast<std::size_t>(result.rows()), -1);
  for (std::size_t v = 0; v < welding.rowOf.size(); ++v) {
    const int row = welding.rowOf[v];
    const auto at = positions.row(static_cast<Eigen::Index>(v));
    int& firstOfRow = first[static_cast<std::size_t>(row)];
    if (firstOfRow < 0) {
      firstOfRow = static_cast<int>(v);
      result.row(row) = at;
    } else if (at != result.row(row)) {
      throw InputError(sourceName + ": vertices " + std::to_string(firstOfRow) + " and " +
                       std::to_string(v) +
                       " lie on one seam of the rest (same position there) but differ here "
                       "by " +
                       detail::numberText((at - result.row(row)).norm()) +
                       ": a seam must stay closed in every example; export the examples "
                       "from the same mesh as the rest, or merge the seam vertices in all of "
                       "them alike");
    }
  }
  return result;
}

}  // namespace tetblend
