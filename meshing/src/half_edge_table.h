#pragma once
// Private helper of the surface checks: the half-edges of a triangle soup
// grouped by undirected edge, and a small union-find.

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {
namespace detail {

/// Half-edge from corner k to corner k+1 of `face`, stored with lo < hi.
struct HalfEdge {
  int lo;
  int hi;
  int face;
  bool forward;  ///< true when the face runs lo -> hi
};

/// Half-edges sorted by (lo, hi, face) and split into groups of equal edges.
/// Faces with `skipFace[f] != 0` contribute nothing.
struct HalfEdgeTable {
  std::vector<HalfEdge> halfEdges;
  /// [begin, end) ranges into halfEdges, one per undirected edge.
  std::vector<std::pair<std::size_t, std::size_t>> edges;
};

HalfEdgeTable buildHalfEdgeTable(const Triangles& triangles, const std::vector<char>& skipFace);

/// Whether face f repeats a vertex (a, a, b): it covers nothing.
inline bool repeatsAVertex(const Triangles& t, Eigen::Index f) {
  return t(f, 0) == t(f, 1) || t(f, 1) == t(f, 2) || t(f, 0) == t(f, 2);
}

/// Per face, 1 where it repeats a vertex: the faces the checks skip.
std::vector<char> repeatedIndexFaces(const Triangles& triangles);

/// Per vertex (of `vertexCount`), 1 where it lies on a boundary edge (an
/// edge of exactly one face), faces that repeat a vertex skipped.
std::vector<char> rimVertices(const Triangles& triangles, Eigen::Index vertexCount);

/// Union-find with path halving.
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace detail
}  // namespace tetblend
