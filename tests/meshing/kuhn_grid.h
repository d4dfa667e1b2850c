#pragma once
// Test support: the unit cube split into cells³ cubes of six tets each
// (Kuhn's split along each cube's diagonal), every tet positively oriented.
// Vertex (i, j, k), each in 0..cells, is row (i (cells+1) + j)(cells+1) + k
// at (i, j, k) / cells.

#include <array>
#include <utility>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {

struct KuhnGrid {
  int cells = 1;

  int side() const { return cells + 1; }
  int index(int i, int j, int k) const { return (i * side() + j) * side() + k; }
  bool onBoundary(int v) const {
    const int i = v / (side() * side()), j = (v / side()) % side(), k = v % side();
    return i == 0 || j == 0 || k == 0 || i == cells || j == cells || k == cells;
  }

  TetMesh mesh() const {
    TetMesh mesh;
    mesh.vertices.resize(side() * side() * side(), 3);
    for (int i = 0; i < side(); ++i) {
      for (int j = 0; j < side(); ++j) {
        for (int k = 0; k < side(); ++k) mesh.vertices.row(index(i, j, k)) << i, j, k;
      }
    }
    mesh.vertices /= cells;
    const std::array<std::array<int, 3>, 6> orders = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<std::array<int, 4>> tets;
    for (int i = 0; i < cells; ++i) {
      for (int j = 0; j < cells; ++j) {
        for (int k = 0; k < cells; ++k) {
          for (const auto& order : orders) {
            std::array<int, 3> corner = {i, j, k};
            std::array<int, 4> tet{};
            tet[0] = index(corner[0], corner[1], corner[2]);
            for (int step = 0; step < 3; ++step) {
              ++corner[static_cast<std::size_t>(order[static_cast<std::size_t>(step)])];
              tet[static_cast<std::size_t>(step) + 1] = index(corner[0], corner[1], corner[2]);
            }
            tets.push_back(tet);
          }
        }
      }
    }
    mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const auto row = static_cast<Eigen::Index>(t);
      for (int a = 0; a < 4; ++a) mesh.tets(row, a) = tets[t][static_cast<std::size_t>(a)];
      if (tetSignedVolume(mesh.vertices, mesh.tets.row(row)) < 0.0) {
        std::swap(mesh.tets(row, 2), mesh.tets(row, 3));
      }
    }
    return mesh;
  }
};

}  // namespace tetblend
