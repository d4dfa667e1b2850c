#pragma once
// Geometry of single tetrahedra: edge matrices, signed volumes, and the affine
// map between two tetrahedra (the per-element map A_j of the shape blender,
// Kaji–Ochiai §6.2 / Sumner–Popović).

#include <Eigen/Core>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Edge matrix [p1-p0, p2-p0, p3-p0] (3 by 3, edges as columns) of tet `t`.
Eigen::Matrix3d tetEdgeMatrix(const Vertices& vertices, const Eigen::RowVector4i& t);

/// Signed volume det(edge matrix) / 6 of tet `t`; positive when well oriented.
double tetSignedVolume(const Vertices& vertices, const Eigen::RowVector4i& t);

/// The unique affine map (4 by 4 homogeneous) taking the corners of tet `t` in
/// `from` to the same corners in `to`. Requires a non-degenerate `from` tet.
Eigen::Matrix4d tetAffineMap(const Vertices& from, const Vertices& to,
                             const Eigen::RowVector4i& t);

/// Length of the diagonal of the axis-aligned bounding box (0 for no vertex).
double boundingBoxDiagonal(const Vertices& vertices);

} // namespace tetblend
