#pragma once
// The cofactor matrix of a 3 by 3 matrix, shared by the polar decomposition
// (its Newton iteration) and the untangler (∂ det F / ∂F).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tetblend {

/// Cofactor matrix of x, det(x) x^{-T}: its columns c_i satisfy
/// c_i · x_j = det(x) δ_ij, i.e. cᵀ x = det(x) I; it is also ∂ det(x) / ∂x.
inline Eigen::Matrix3d cofactor(const Eigen::Matrix3d& x) {
  Eigen::Matrix3d c;
  c.col(0) = x.col(1).cross(x.col(2));
  c.col(1) = x.col(2).cross(x.col(0));
  c.col(2) = x.col(0).cross(x.col(1));
  return c;
}

}  // namespace tetblend
