#include "matrix_function_oracle.h"

#include <unsupported/Eigen/MatrixFunctions>

namespace tetblend::core_test {

Eigen::Matrix3d expmOf(const Eigen::Matrix3d& a) { return a.exp(); }
Eigen::Matrix4d expmOf(const Eigen::Matrix4d& a) { return a.exp(); }
Matrix6d expmOf(const Matrix6d& a) { return a.exp(); }
Eigen::Matrix3d logmOf(const Eigen::Matrix3d& a) { return a.log(); }
Eigen::Matrix4d logmOf(const Eigen::Matrix4d& a) { return a.log(); }
Eigen::Matrix3d sqrtmOf(const Eigen::Matrix3d& a) { return a.sqrt(); }

}  // namespace tetblend::core_test
