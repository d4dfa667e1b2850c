#pragma once
// Plain mesh containers shared by every library (libigl style: rows are
// elements). Vertex order is part of the contract everywhere: users map
// results back by index.

#include <Eigen/Core>

namespace tetblend {

/// #V by 3 vertex positions, one row per vertex.
using Vertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices of triangles, counter-clockwise seen from outside.
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #T by 4 vertex indices of tetrahedra, positively oriented: with corners
/// p0..p3, det[p1-p0, p2-p0, p3-p0] > 0.
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// A closed or open triangle surface.
struct SurfaceMesh {
  Vertices vertices;
  Triangles triangles;
};

/// A tetrahedral mesh. When it was made from a surface, the surface's vertices
/// come first and in the surface's order.
struct TetMesh {
  Vertices vertices;
  Tets tets;
};

} // namespace tetblend
