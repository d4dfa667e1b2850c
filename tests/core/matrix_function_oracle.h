#pragma once
// Eigen's MatrixFunctions (Pade approximation with scaling and squaring for
// exp, inverse scaling and squaring for log; sqrt as exp(log(A) / 2)) as the
// independent oracle of the closed forms, compiled once in
// matrix_function_oracle.cpp: its templates made every test file including it
// several times slower to build.

#include <Eigen/Core>

namespace tetblend::core_test {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

Eigen::Matrix3d expmOf(const Eigen::Matrix3d& a);
Eigen::Matrix4d expmOf(const Eigen::Matrix4d& a);
Matrix6d expmOf(const Matrix6d& a);
Eigen::Matrix3d logmOf(const Eigen::Matrix3d& a);
Eigen::Matrix4d logmOf(const Eigen::Matrix4d& a);
Eigen::Matrix3d sqrtmOf(const Eigen::Matrix3d& a);

/// Matrix exponential of any 3x3, 4x4 or 6x6 expression.
template <typename Derived>
auto expm(const Eigen::MatrixBase<Derived>& a) {
  return expmOf(a.eval());
}

/// Principal matrix logarithm of any 3x3 or 4x4 expression.
template <typename Derived>
auto logm(const Eigen::MatrixBase<Derived>& a) {
  return logmOf(a.eval());
}

/// Principal matrix square root of any 3x3 expression whose eigenvalues are
/// off the closed negative real axis.
template <typename Derived>
auto sqrtm(const Eigen::MatrixBase<Derived>& a) {
  return sqrtmOf(a.eval());
}

}  // namespace tetblend::core_test
