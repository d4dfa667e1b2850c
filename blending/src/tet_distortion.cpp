#include "tetblend/blending/tet_distortion.h"

#include <Eigen/SVD>
#include <limits>

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
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(f).singularValues();
  return {conditionNumber(sigma(0), sigma(2)), det > 0.0
                                                   ? so3Log(polar_detail::svdRotation(f)).norm()
                                                   : std::numeric_limits<double>::quiet_NaN()};
}

}  // namespace tetblend
