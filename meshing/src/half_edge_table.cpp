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

}  // namespace detail
}  // namespace tetblend
