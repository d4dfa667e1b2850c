#include "tetblend/core/tet_geometry.h"

#include <Eigen/LU>

namespace tetblend {

Eigen::Matrix3d tetEdgeMatrix(const Vertices& vertices, const Eigen::RowVector4i& t) {
  Eigen::Matrix3d edges;
  for (int k = 0; k < 3; ++k) {
    edges.col(k) = (vertices.row(t(k + 1)) - vertices.row(t(0))).transpose();
  }
  return edges;
}

double tetSignedVolume(const Vertices& vertices, const Eigen::RowVector4i& t) {
  return tetEdgeMatrix(vertices, t).determinant() / 6.0;
}

Eigen::Matrix4d tetAffineMap(const Vertices& from, const Vertices& to,
                             const Eigen::RowVector4i& t) {
  const Eigen::Matrix3d linear =
      tetEdgeMatrix(to, t) * tetEdgeMatrix(from, t).inverse();
  Eigen::Matrix4d map = Eigen::Matrix4d::Identity();
  map.topLeftCorner<3, 3>() = linear;
  map.topRightCorner<3, 1>() =
      to.row(t(0)).transpose() - linear * from.row(t(0)).transpose();
  return map;
}

double boundingBoxDiagonal(const Vertices& vertices) {
  if (vertices.rows() == 0) return 0.0;
  return (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

} // namespace tetblend
