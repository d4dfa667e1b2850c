#include "matrix_function_oracle.h"

#include <unsupported/Eigen/MatrixFunctions>

namespace tetblend::core_test {
namespace {

// One dynamic-size instantiation per function serves every fixed size: the
// fixed-size instantiations took 198 s to build at -O3 (this file with them
// all, one core), these take 40 s.
Eigen::MatrixXd dynamicExpm(const Eigen::MatrixXd& a) { return a.exp(); }
Eigen::MatrixXd dynamicLogm(const Eigen::MatrixXd& a) { return a.log(); }

}  // namespace

Eigen::Matrix3d expmOf(const Eigen::Matrix3d& a) { return dynamicExpm(a); }
Eigen::Matrix4d expmOf(const Eigen::Matrix4d& a) { return dynamicExpm(a); }
Matrix6d expmOf(const Matrix6d& a) { return dynamicExpm(a); }
Eigen::Matrix3d logmOf(const Eigen::Matrix3d& a) { return dynamicLogm(a); }
Eigen::Matrix4d logmOf(const Eigen::Matrix4d& a) { return dynamicLogm(a); }
// The principal square root is exp(log(A) / 2) wherever the principal log
// exists (no eigenvalue on the closed negative real axis); Eigen's Schur-based
// sqrt alone added 65 s to this file's build.
Eigen::Matrix3d sqrtmOf(const Eigen::Matrix3d& a) { return dynamicExpm(0.5 * dynamicLogm(a)); }

}  // namespace tetblend::core_test
