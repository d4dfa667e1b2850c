#include "tetblend/core/se3.h"

#include <cmath>
#include <sstream>

#include <Eigen/LU>

#include "tetblend/core/error.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

// Coefficients of S and S^2 in V (Eberly eq. 20), series below the threshold.
struct VCoefficients {
  double a;  // (1 - cos theta) / theta^2
  double b;  // (theta - sin theta) / theta^3
};

VCoefficients vCoefficients(double theta) {
  const double t2 = theta * theta;
  if (theta < kSe3SeriesThreshold) {
    return {0.5 - t2 / 24.0 + t2 * t2 / 720.0, 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0};
  }
  const double half = std::sin(0.5 * theta);
  return {2.0 * half * half / t2, (theta - std::sin(theta)) / (t2 * theta)};
}

// (1 - theta sin theta / (2 (1 - cos theta))) / theta^2 = (1 - (theta/2) cot(theta/2)) / theta^2.
double vInverseCoefficient(double theta) {
  const double t2 = theta * theta;
  if (theta < kSe3SeriesThreshold) return 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  const double half = 0.5 * theta;
  return (1.0 - half * std::cos(half) / std::sin(half)) / t2;
}

constexpr double kTwoPi = 6.283185307179586476925;
// V is singular at theta = 2 pi; refuse angles this close to it (radians).
constexpr double kSingularGuard = 1e-6;
// Rigidity check of se3Log (absolute, unit-scale entries).
constexpr double kRigidTolerance = 1e-9;

}  // namespace

Eigen::Matrix4d se3Hat(const Vector6d& xi) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m.topLeftCorner<3, 3>() = hat(xi.head<3>());
  m.topRightCorner<3, 1>() = xi.tail<3>();
  return m;
}

Vector6d se3Vee(const Eigen::Matrix4d& xiHat) {
  Vector6d xi;
  xi << vee(xiHat.topLeftCorner<3, 3>()), xiHat.topRightCorner<3, 1>();
  return xi;
}

Eigen::Matrix3d se3LeftJacobian(const Eigen::Vector3d& omega) {
  const VCoefficients c = vCoefficients(omega.norm());
  const Eigen::Matrix3d s = hat(omega);
  return Eigen::Matrix3d::Identity() + c.a * s + c.b * (s * s);
}

Eigen::Matrix3d se3LeftJacobianInverse(const Eigen::Vector3d& omega) {
  const double theta = omega.norm();
  if (theta >= kTwoPi - kSingularGuard) {
    std::ostringstream msg;
    msg << "se3LeftJacobianInverse: rotation angle " << theta
        << " rad is at or beyond 2 pi, where V is singular; wrap the angle into [0, pi] (se3Log "
           "does)";
    throw DomainError(msg.str());
  }
  const Eigen::Matrix3d s = hat(omega);
  return Eigen::Matrix3d::Identity() - 0.5 * s + vInverseCoefficient(theta) * (s * s);
}

Eigen::Matrix4d se3Exp(const Vector6d& xi) {
  Eigen::Matrix4d h = Eigen::Matrix4d::Identity();
  h.topLeftCorner<3, 3>() = so3Exp(xi.head<3>());
  h.topRightCorner<3, 1>() = se3LeftJacobian(xi.head<3>()) * xi.tail<3>();
  return h;
}

Vector6d se3Log(const Eigen::Matrix4d& rigid) {
  const Eigen::Matrix3d r = rigid.topLeftCorner<3, 3>();
  const double rowError = (rigid.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff();
  const double orthoError = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double det = r.determinant();
  if (!(rowError <= kRigidTolerance && orthoError <= kRigidTolerance &&
        std::abs(det - 1.0) <= kRigidTolerance)) {
    std::ostringstream msg;
    msg << "se3Log: the 4x4 matrix is not a rigid motion (last-row error " << rowError
        << ", |R^T R - I| = " << orthoError << ", det R = " << det << ", tolerance "
        << kRigidTolerance << "); use a rigid matrix [R T; 0 1] with R a rotation";
    throw DomainError(msg.str());
  }
  Vector6d xi;
  xi.head<3>() = so3Log(r);
  xi.tail<3>() = se3LeftJacobianInverse(xi.head<3>()) * rigid.topRightCorner<3, 1>();
  return xi;
}

Eigen::Matrix4d rigidInverse(const Eigen::Matrix4d& rigid) {
  Eigen::Matrix4d inv = Eigen::Matrix4d::Identity();
  const Eigen::Matrix3d rt = rigid.topLeftCorner<3, 3>().transpose();
  inv.topLeftCorner<3, 3>() = rt;
  inv.topRightCorner<3, 1>() = -rt * rigid.topRightCorner<3, 1>();
  return inv;
}

Eigen::Matrix4d se3Geodesic(double t, const Eigen::Matrix4d& H0, const Eigen::Matrix4d& H1) {
  return H0 * se3Exp(t * se3Log(rigidInverse(H0) * H1));
}

}  // namespace tetblend
