#include "tet_stellar_split.h"

#include <algorithm>
#include <string>

#include "tetblend/core/error.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// The six edges and four faces of a tet as local corners.
constexpr std::array<std::array<int, 2>, 6> kTetEdges = {
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
constexpr std::array<std::array<int, 3>, 4> kTetFaces = {
    {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};

bool contains(const std::vector<Simplex>& sorted, const Simplex& simplex) {
  return std::binary_search(sorted.begin(), sorted.end(), simplex);
}

std::string simplexText(const Simplex& simplex) {
  std::string text = "(";
  for (int i = 0; i < simplex.count; ++i) {
    text += (i > 0 ? ", " : "") + std::to_string(simplex.vertices[static_cast<size_t>(i)]);
  }
  return text + ")";
}

}  // namespace

Simplex makeSimplex(std::initializer_list<int> vertices) {
  Simplex simplex;
  for (int v : vertices) {
    // Insertion into the ascending prefix (at most 3 entries).
    int i = simplex.count++;
    for (; i > 0 && simplex.vertices[static_cast<size_t>(i - 1)] > v; --i) {
      simplex.vertices[static_cast<size_t>(i)] = simplex.vertices[static_cast<size_t>(i - 1)];
    }
    simplex.vertices[static_cast<size_t>(i)] = v;
  }
  return simplex;
}

bool Simplex::operator<(const Simplex& other) const {
  return count != other.count ? count < other.count : vertices < other.vertices;
}

bool Simplex::operator==(const Simplex& other) const {
  return count == other.count && vertices == other.vertices;
}

BoundarySimplices boundarySimplices(const Triangles& triangles) {
  BoundarySimplices boundary;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const int a = triangles(f, 0), b = triangles(f, 1), c = triangles(f, 2);
    boundary.faces.push_back(makeSimplex({a, b, c}));
    boundary.edges.push_back(makeSimplex({a, b}));
    boundary.edges.push_back(makeSimplex({b, c}));
    boundary.edges.push_back(makeSimplex({c, a}));
  }
  for (std::vector<Simplex>* list : {&boundary.edges, &boundary.faces}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  return boundary;
}

std::vector<Simplex> simplicesToSplit(const TetMesh& mesh, int tet, int surfaceCount,
                                      const BoundarySimplices& boundary) {
  const Eigen::RowVector4i corners = mesh.tets.row(tet);
  std::vector<Simplex> rigid;
  Simplex longest;
  double longestLength = -1.0;
  for (const auto& local : kTetEdges) {
    const Simplex edge = makeSimplex({corners(local[0]), corners(local[1])});
    if (contains(boundary.edges, edge)) continue;
    if (edge.vertices[1] < surfaceCount) rigid.push_back(edge);
    const double length =
        (mesh.vertices.row(edge.vertices[0]) - mesh.vertices.row(edge.vertices[1])).norm();
    if (length > longestLength) {
      longestLength = length;
      longest = edge;
    }
  }
  for (const auto& local : kTetFaces) {
    const Simplex face = makeSimplex({corners(local[0]), corners(local[1]), corners(local[2])});
    if (contains(boundary.faces, face)) continue;
    const int a = face.vertices[0], b = face.vertices[1], c = face.vertices[2];
    if (contains(boundary.edges, makeSimplex({a, b})) &&
        contains(boundary.edges, makeSimplex({b, c})) &&
        contains(boundary.edges, makeSimplex({a, c}))) {
      rigid.push_back(face);
    }
  }
  if (!rigid.empty()) return rigid;
  if (longest.count == 0) return {};
  return {longest};
}

std::vector<Simplex> rigidSimplices(const TetMesh& mesh, int surfaceCount,
                                    const BoundarySimplices& boundary) {
  std::vector<Simplex> rigid;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::RowVector4i corners = mesh.tets.row(t);
    // A rigid simplex has two corners on the surface at least; most tets of
    // a fine mesh have fewer (bench_meshing's 1 M row: 163 -> 33 ms).
    if ((corners.array() < surfaceCount).count() < 2) continue;
    for (const auto& local : kTetEdges) {
      const Simplex edge = makeSimplex({corners(local[0]), corners(local[1])});
      if (edge.vertices[1] < surfaceCount && !contains(boundary.edges, edge)) rigid.push_back(edge);
    }
    for (const auto& local : kTetFaces) {
      const Simplex face = makeSimplex({corners(local[0]), corners(local[1]), corners(local[2])});
      if (face.vertices[2] < surfaceCount && !contains(boundary.faces, face)) rigid.push_back(face);
    }
  }
  std::sort(rigid.begin(), rigid.end());
  rigid.erase(std::unique(rigid.begin(), rigid.end()), rigid.end());
  return rigid;
}

TetMesh splitSimplices(const TetMesh& mesh, const std::vector<Simplex>& simplices) {
  const Eigen::Index oldVertices = mesh.vertices.rows();
  // Stars are kept only for the simplices' vertices, the only ones read
  // (building every vertex's took most of a split of bench_meshing's 1 M-tet
  // bar; with the filter of rigidSimplices its stage 1 took 158 ms instead of
  // 403 ms, scratch timers).
  std::vector<char> tracked(static_cast<size_t>(oldVertices) + simplices.size(), 0);
  for (const Simplex& simplex : simplices) {
    for (int i = 0; i < simplex.count; ++i) {
      const int v = simplex.vertices[static_cast<size_t>(i)];
      if (v >= 0 && v < oldVertices) tracked[static_cast<size_t>(v)] = 1;
    }
  }
  std::vector<std::vector<int>> stars(tracked.size());
  std::vector<Eigen::RowVector4i> tets(static_cast<size_t>(mesh.tets.rows()));
  for (size_t t = 0; t < tets.size(); ++t) {
    tets[t] = mesh.tets.row(static_cast<Eigen::Index>(t));
    for (int c = 0; c < 4; ++c) {
      const auto v = static_cast<size_t>(tets[t](c));
      if (tracked[v]) stars[v].push_back(static_cast<int>(t));
    }
  }
  std::vector<Eigen::RowVector3d> positions;
  for (const Simplex& simplex : simplices) {
    const int first = simplex.vertices[0];
    if (simplex.count < 2 || first < 0 ||
        simplex.vertices[static_cast<size_t>(simplex.count - 1)] >= oldVertices) {
      throw InputError("splitSimplices: " + simplexText(simplex) +
                       " is not an edge or face of the mesh");
    }
    std::vector<int> around;  // tets holding every vertex of the simplex
    for (int t : stars[static_cast<size_t>(first)]) {
      bool all = true;
      for (int i = 1; i < simplex.count; ++i) {
        all = all &&
              (tets[static_cast<size_t>(t)].array() == simplex.vertices[static_cast<size_t>(i)])
                  .any();
      }
      if (all) around.push_back(t);
    }
    if (around.empty()) {
      throw InputError("splitSimplices: " + simplexText(simplex) +
                       " is not an edge or face of the mesh");
    }
    const int p = static_cast<int>(oldVertices + static_cast<Eigen::Index>(positions.size()));
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int i = 0; i < simplex.count; ++i)
      centroid += mesh.vertices.row(simplex.vertices[static_cast<size_t>(i)]);
    positions.push_back(centroid / simplex.count);
    for (int t : around) {
      const Eigen::RowVector4i parent = tets[static_cast<size_t>(t)];
      for (int i = 0; i < simplex.count; ++i) {
        const int s = simplex.vertices[static_cast<size_t>(i)];
        Eigen::RowVector4i child = parent;
        for (int c = 0; c < 4; ++c) {
          if (child(c) == s) child(c) = p;
        }
        int index = t;
        if (i == 0) {
          tets[static_cast<size_t>(t)] = child;
        } else {
          index = static_cast<int>(tets.size());
          tets.push_back(child);
        }
        for (int c = 0; c < 4; ++c) {
          const auto v = static_cast<size_t>(child(c));
          if (tracked[v] && index != t) stars[v].push_back(index);  // p is not tracked
        }
        // The parent's vertex s left this child: drop the child from s's star.
        if (index == t) {
          std::vector<int>& star = stars[static_cast<size_t>(s)];
          star.erase(std::remove(star.begin(), star.end(), t), star.end());
        }
      }
    }
  }
  TetMesh result;
  result.vertices.resize(oldVertices + static_cast<Eigen::Index>(positions.size()), 3);
  result.vertices.topRows(oldVertices) = mesh.vertices;
  for (size_t i = 0; i < positions.size(); ++i) {
    result.vertices.row(oldVertices + static_cast<Eigen::Index>(i)) = positions[i];
  }
  result.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t) result.tets.row(static_cast<Eigen::Index>(t)) = tets[t];
  return result;
}

}  // namespace tetblend
