#include "half_edge_table.h"

#include <algorithm>
#include <tuple>

namespace tetblend {
namespace detail {

HalfEdgeTable buildHalfEdgeTable(const Triangles& triangles, const std::vector<char>& skipFace) {
  HalfEdgeTable table;
  table.halfEdges.reserve(3 * static_cast<std::size_t>(triangles.rows()));
  for (int f = 0; f < static_cast<int>(triangles.rows()); ++f) {
    if (skipFace[static_cast<std::size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(f, k);
      const int b = triangles(f, (k + 1) % 3);
      table.halfEdges.push_back({std::min(a, b), std::max(a, b), f, a < b});
    }
  }
  std::sort(table.halfEdges.begin(), table.halfEdges.end(),
            [](const HalfEdge& x, const HalfEdge& y) {
              return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
            });
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= table.halfEdges.size(); ++i) {
    const bool same = i < table.halfEdges.size() &&
                      table.halfEdges[i].lo == table.halfEdges[begin].lo &&
                      table.halfEdges[i].hi == table.halfEdges[begin].hi;
    if (!same) {
      table.edges.emplace_back(begin, i);
      begin = i;
    }
  }
  return table;
}

std::vector<char> repeatedIndexFaces(const Triangles& triangles) {
  std::vector<char> skip(static_cast<std::size_t>(triangles.rows()), 0);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    skip[static_cast<std::size_t>(f)] = repeatsAVertex(triangles, f) ? 1 : 0;
  }
  return skip;
}

std::vector<char> rimVertices(const Triangles& triangles, Eigen::Index vertexCount) {
  const HalfEdgeTable table = buildHalfEdgeTable(triangles, repeatedIndexFaces(triangles));
  std::vector<char> onRim(static_cast<std::size_t>(vertexCount), 0);
  for (const auto& [begin, end] : table.edges) {
    if (end - begin != 1) continue;
    onRim[static_cast<std::size_t>(table.halfEdges[begin].lo)] = 1;
    onRim[static_cast<std::size_t>(table.halfEdges[begin].hi)] = 1;
  }
  return onRim;
}

}  // namespace detail
}  // namespace tetblend
