#include "tet_elements.h"

#include <string>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {

std::vector<TetElement> buildTetElements(const TetMesh& mesh) {
  const Eigen::Index vertexCount = mesh.vertices.rows();
  std::vector<TetElement> elements(static_cast<size_t>(mesh.tets.rows()));
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::RowVector4i tet = mesh.tets.row(t);
    if (tet.minCoeff() < 0 || tet.maxCoeff() >= vertexCount) {
      throw InputError("tet " + std::to_string(t) + " has a vertex index outside [0, " +
                       std::to_string(vertexCount) + ")");
    }
    const Eigen::Matrix3d edges = tetEdgeMatrix(mesh.vertices, tet);
    const double volume = edges.determinant() / 6.0;
    if (!(volume > 0.0)) {
      throw InputError("rest tet " + std::to_string(t) + " has signed volume " +
                       std::to_string(volume) +
                       "; the rest mesh must be positively oriented and non-degenerate");
    }
    const Eigen::Matrix3d inverse = edges.inverse();  // rows: gradients of λ1..λ3
    TetElement& element = elements[static_cast<size_t>(t)];
    element.volume = volume;
    element.gradients.rightCols<3>() = inverse.transpose();
    element.gradients.col(0) = -inverse.transpose().rowwise().sum();
  }
  return elements;
}

Eigen::Matrix3d closestRotation(const Eigen::Matrix3d& f) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  return u * v.transpose();
}

}  // namespace tetblend
