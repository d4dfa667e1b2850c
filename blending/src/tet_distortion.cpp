#include "tetblend/blending/tet_distortion.h"

#include <Eigen/SVD>
#include <limits>

#include <Eigen/LU>

#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"

namespace tetblend {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double conditionNumber(double sigmaMax, double sigmaMin) {
  return sigmaMin > 0.0 ? sigmaMax / sigmaMin : kInfinity;
}

}  // namespace

TetDistortion tetDistortion(const Eigen::Matrix3d& f, double det) {
  Eigen::Matrix3d u, v;
  Eigen::Vector3d sigma;
  if (det >= polar_detail::kUnscaledMinDet && det <= polar_detail::kUnscaledMaxDet &&
      polar_detail::svdClosedForm(f, u, sigma, v)) {
    return {conditionNumber(sigma.maxCoeff(), sigma.minCoeff()), so3Log(u * v.transpose()).norm()};
  }
  return tetDistortionReference(f, det);
}

TetDistortion tetDistortionReference(const Eigen::Matrix3d& f, double det) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d& sigma = svd.singularValues();
  const double condition = conditionNumber(sigma(0), sigma(2));
  if (!(det > 0.0)) return {condition, std::numeric_limits<double>::quiet_NaN()};
  // The polar rotation U V^T; when rounding gives it det -1 (sigma_min lost
  // in F's round-off), the smallest singular direction is flipped, as the
  // sign of det F asks.
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0) u.col(2) = -u.col(2);
  return {condition, so3Log(u * svd.matrixV().transpose()).norm()};
}

}  // namespace tetblend
