#include "tetblend/core/dual_quaternion.h"

#include <cmath>
#include <sstream>

#include <Eigen/LU>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

Eigen::Quaterniond fromCoeffs(const Eigen::Vector4d& c) {
  Eigen::Quaterniond q;
  q.coeffs() = c;
  return q;
}

// Coefficients of the quaternion exp/log at half-angle phi (see
// kDualQuaternionSeriesThreshold for the series orders).
double sinc(double phi) {
  if (phi < kDualQuaternionSeriesThreshold) {
    const double p2 = phi * phi;
    return 1.0 - p2 / 6.0 + p2 * p2 / 120.0;
  }
  return std::sin(phi) / phi;
}

// phi / sin(phi), given sinPhi = |vec(q0)| itself rather than sin(atan2(..)):
// near phi = pi, sin(phi) of the rounded phi is off by ~1e-16 absolute, which
// is a large relative error when sin(phi) is tiny.
double phiOverSin(double phi, double sinPhi) {
  if (phi < kDualQuaternionSeriesThreshold) {
    const double p2 = phi * phi;
    return 1.0 + p2 / 6.0 + 7.0 * p2 * p2 / 360.0;
  }
  return phi / sinPhi;
}

// (cos(phi) - sin(phi)/phi) / phi^2 = d(sinc)/dphi / phi.
double sincDerivativeOverPhi(double phi) {
  if (phi < kDualQuaternionSeriesThreshold) {
    const double p2 = phi * phi;
    return -1.0 / 3.0 + p2 / 30.0 - p2 * p2 / 840.0;
  }
  return (std::cos(phi) - std::sin(phi) / phi) / (phi * phi);
}

}  // namespace

DualQuaternion DualQuaternion::fromRigid(const Eigen::Matrix4d& rigid) {
  const Eigen::Matrix3d r = rigid.topLeftCorner<3, 3>();
  const double rowError = (rigid.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff();
  const double orthoError = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double detError = std::abs(r.determinant() - 1.0);
  if (!(rowError <= kRigidTolerance && orthoError <= kRigidTolerance &&
        detError <= kRigidTolerance)) {
    std::ostringstream msg;
    msg << "DualQuaternion::fromRigid: the 4x4 matrix is not a rigid motion (last-row error "
        << rowError << ", |R^T R - I| = " << orthoError << ", |det R - 1| = " << detError
        << ", tolerance " << kRigidTolerance
        << "); orthonormalise R (e.g. polar decomposition) first";
    throw DomainError(msg.str());
  }
  return fromRotationTranslation(Eigen::Quaterniond(r), rigid.topRightCorner<3, 1>());
}

DualQuaternion DualQuaternion::fromRotationTranslation(const Eigen::Quaterniond& rotation,
                                                       const Eigen::Vector3d& translation) {
  Eigen::Quaterniond q0 = rotation.normalized();
  if (q0.w() < 0.0) q0.coeffs() = -q0.coeffs();
  const Eigen::Quaterniond t(0.0, 0.5 * translation.x(), 0.5 * translation.y(),
                             0.5 * translation.z());
  return DualQuaternion(q0, t * q0);
}

DualQuaternion DualQuaternion::pure(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return DualQuaternion(Eigen::Quaterniond(0.0, a.x(), a.y(), a.z()),
                        Eigen::Quaterniond(0.0, b.x(), b.y(), b.z()));
}

Eigen::Vector3d DualQuaternion::translation() const {
  return 2.0 * (dual_ * real_.conjugate()).vec();
}

Eigen::Matrix4d DualQuaternion::toMatrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = real_.toRotationMatrix();
  m.topRightCorner<3, 1>() = translation();
  return m;
}

DualQuaternion DualQuaternion::operator*(const DualQuaternion& other) const {
  const Eigen::Quaterniond a = real_ * other.dual_;
  const Eigen::Quaterniond b = dual_ * other.real_;
  return DualQuaternion(real_ * other.real_, fromCoeffs(a.coeffs() + b.coeffs()));
}

DualQuaternion DualQuaternion::operator*(double s) const {
  return DualQuaternion(fromCoeffs(s * real_.coeffs()), fromCoeffs(s * dual_.coeffs()));
}

DualQuaternion DualQuaternion::operator+(const DualQuaternion& other) const {
  return DualQuaternion(fromCoeffs(real_.coeffs() + other.real_.coeffs()),
                        fromCoeffs(dual_.coeffs() + other.dual_.coeffs()));
}

DualQuaternion DualQuaternion::operator-() const { return *this * -1.0; }

DualQuaternion DualQuaternion::conjugate() const {
  return DualQuaternion(real_.conjugate(), dual_.conjugate());
}

DualQuaternion DualQuaternion::dualConjugate() const {
  return DualQuaternion(real_, fromCoeffs(-dual_.coeffs()));
}

DualNumber DualQuaternion::norm() const {
  const double r = real_.norm();
  return {r, r > 0.0 ? real_.coeffs().dot(dual_.coeffs()) / r : 0.0};
}

DualQuaternion DualQuaternion::normalized() const {
  const double r2 = real_.squaredNorm();
  if (!(r2 > 0.0)) {
    throw DomainError(
        "DualQuaternion::normalized: the real part is zero (a purely dual number has no "
        "inverse); a blend whose weights cancel cannot be normalised");
  }
  const double inv = 1.0 / std::sqrt(r2);
  const double d = real_.coeffs().dot(dual_.coeffs()) / r2;
  return DualQuaternion(fromCoeffs(inv * real_.coeffs()),
                        fromCoeffs(inv * (dual_.coeffs() - d * real_.coeffs())));
}

bool DualQuaternion::isUnit(double tol) const {
  return std::abs(real_.norm() - 1.0) <= tol && std::abs(real_.coeffs().dot(dual_.coeffs())) <= tol;
}

double DualQuaternion::distanceUpToSign(const DualQuaternion& other) const {
  Eigen::Matrix<double, 8, 1> a, b;
  a << real_.coeffs(), dual_.coeffs();
  b << other.real_.coeffs(), other.dual_.coeffs();
  return std::min((a - b).norm(), (a + b).norm());
}

DualQuaternion DualQuaternion::canonicalSign() const { return real_.w() < 0.0 ? -*this : *this; }

DualQuaternion DualQuaternion::exp(const DualQuaternion& x) {
  const Eigen::Vector3d a = x.real_.vec();
  const Eigen::Vector3d b = x.dual_.vec();
  const double phi = a.norm();
  const double s = sinc(phi);
  const double k = sincDerivativeOverPhi(phi);
  const double ab = a.dot(b);
  const Eigen::Vector3d realVec = s * a;
  const Eigen::Vector3d dualVec = s * b + (k * ab) * a;
  return DualQuaternion(Eigen::Quaterniond(std::cos(phi), realVec.x(), realVec.y(), realVec.z()),
                        Eigen::Quaterniond(-s * ab, dualVec.x(), dualVec.y(), dualVec.z()));
}

DualQuaternion DualQuaternion::log() const {
  const Eigen::Vector3d v0 = real_.vec();
  const double s = v0.norm();
  if (real_.w() < 0.0 && s < 1e-12) {
    throw DomainError(
        "DualQuaternion::log: the real part is -1 (half-angle pi): the logarithm is not unique "
        "or does not exist; use canonicalSign() to take the logarithm of the motion");
  }
  const double phi = std::atan2(s, real_.w());
  const double c = phiOverSin(phi, s);
  const double k = sincDerivativeOverPhi(phi);
  const Eigen::Vector3d a = c * v0;
  // Invert exp's dual part: w_eps = -sinc <a,b>, v_eps = sinc b + k <a,b> a.
  const double ab = -c * dual_.w();
  const Eigen::Vector3d b = c * (dual_.vec() - (k * ab) * a);
  return pure(a, b);
}

DualQuaternion DualQuaternion::power(double t) const {
  const DualQuaternion x = log();
  return exp(x * t);
}

Eigen::Vector3d DualQuaternion::transformPoint(const Eigen::Vector3d& x) const {
  return real_ * x + translation();
}

}  // namespace tetblend
