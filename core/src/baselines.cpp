#include "tetblend/core/baselines.h"

#include <cmath>
#include <complex>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>

#include "tetblend/core/error.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

// Last-row check of the homogeneous inputs (absolute, exact 0 0 0 1 expected).
constexpr double kLastRowTolerance = 1e-12;

void validate(const char* where, const std::vector<double>& weights,
              const std::vector<Eigen::Matrix4d>& maps) {
  if (weights.size() != maps.size() || maps.empty()) {
    std::ostringstream msg;
    msg << where << ": " << maps.size() << " maps and " << weights.size()
        << " weights; give one weight per map, at least one";
    throw InputError(msg.str());
  }
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const Eigen::Matrix4d& a = maps[i];
    std::ostringstream msg;
    if (!a.allFinite() || !std::isfinite(weights[i])) {
      msg << where << ": map " << i << " or its weight has a non-finite entry";
      throw DomainError(msg.str());
    }
    const double rowError = (a.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff();
    if (rowError > kLastRowTolerance) {
      msg << where << ": map " << i << " has last row " << a.row(3)
          << ", not 0 0 0 1; pass affine maps as homogeneous 4x4 matrices";
      throw DomainError(msg.str());
    }
    const double det = a.topLeftCorner<3, 3>().determinant();
    if (!(det > 0.0)) {
      msg << where << ": map " << i << " has det " << det
          << " <= 0 (inverted or flat element); the blend needs orientation-preserving maps";
      throw DomainError(msg.str());
    }
  }
}

Eigen::Matrix4d affine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

// Polar factors of every map, and the linear blends of stretch and translation.
struct PolarParts {
  std::vector<Eigen::Matrix3d> rotations;
  Eigen::Matrix3d stretch = Eigen::Matrix3d::Zero();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

PolarParts polarParts(const std::vector<double>& weights,
                      const std::vector<Eigen::Matrix4d>& maps) {
  PolarParts parts;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const PolarDecomposition pd = polarDecompose(maps[i].topLeftCorner<3, 3>());
    parts.rotations.push_back(pd.rotation);
    parts.stretch += weights[i] * pd.stretch;
    parts.translation += weights[i] * maps[i].topRightCorner<3, 1>();
  }
  return parts;
}

}  // namespace

Eigen::Matrix4d linearMatrixBlend(const std::vector<double>& weights,
                                  const std::vector<Eigen::Matrix4d>& maps) {
  validate("linearMatrixBlend", weights, maps);
  Eigen::Matrix4d sum = Eigen::Matrix4d::Zero();
  for (std::size_t i = 0; i < maps.size(); ++i) sum += weights[i] * maps[i];
  return sum;
}

Eigen::Matrix4d alexaBlend(const std::vector<double>& weights,
                           const std::vector<Eigen::Matrix4d>& maps) {
  validate("alexaBlend", weights, maps);
  Eigen::Matrix4d logSum = Eigen::Matrix4d::Zero();
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const Eigen::Matrix3d linear = maps[i].topLeftCorner<3, 3>();
    const Eigen::EigenSolver<Eigen::Matrix3d> eig(linear, false);
    for (int k = 0; k < 3; ++k) {
      const std::complex<double> lambda = eig.eigenvalues()(k);
      if (lambda.real() < 0.0 &&
          std::abs(lambda.imag()) <= kAlexaRealEigenTolerance * std::abs(lambda)) {
        std::ostringstream msg;
        msg << "alexaBlend: map " << i << " has the negative real eigenvalue " << lambda.real()
            << " (imaginary part " << lambda.imag()
            << "), so it has no real principal matrix logarithm (e.g. a rotation by pi); "
               "log-matrix blending is undefined for it: use another blend method";
        throw DomainError(msg.str());
      }
    }
    logSum += weights[i] * maps[i].log();
  }
  Eigen::Matrix4d result = logSum.exp();
  result.row(3) << 0, 0, 0, 1;  // exact: the log has a zero last row
  return result;
}

Eigen::Quaterniond polarSlerpRotation(const double* weights, const Eigen::Quaterniond* rotations,
                                      std::size_t n) {
  if (n == 2) {
    const double sum = weights[0] + weights[1];
    if (sum == 0.0) {
      throw DomainError("polarSlerpBlend: the two weights sum to 0; no slerp parameter");
    }
    return rotations[0].slerp(weights[1] / sum, rotations[1]);
  }
  std::size_t pivot = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(weights[i]) > std::abs(weights[pivot])) pivot = i;
  }
  const Eigen::Vector4d pivotQ = rotations[pivot].coeffs();
  Eigen::Vector4d q = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector4d qi = rotations[i].coeffs();
    q += (qi.dot(pivotQ) < 0.0 ? -weights[i] : weights[i]) * qi;
  }
  if (!(q.norm() > 0.0)) {
    throw DomainError(
        "polarSlerpBlend: the weighted quaternion sum is zero (cancelling "
        "weights); no rotation to normalise");
  }
  Eigen::Quaterniond rotation;
  rotation.coeffs() = q.normalized();
  return rotation;
}

Eigen::Matrix4d polarSlerpBlend(const std::vector<double>& weights,
                                const std::vector<Eigen::Matrix4d>& maps) {
  validate("polarSlerpBlend", weights, maps);
  const PolarParts parts = polarParts(weights, maps);
  std::vector<Eigen::Quaterniond> rotations;
  for (const Eigen::Matrix3d& r : parts.rotations) rotations.emplace_back(r);
  const Eigen::Quaterniond rotation =
      polarSlerpRotation(weights.data(), rotations.data(), rotations.size());
  return affine(rotation.toRotationMatrix() * parts.stretch, parts.translation);
}

Eigen::Matrix4d logRotationBlend(const std::vector<double>& weights,
                                 const std::vector<Eigen::Matrix4d>& maps) {
  validate("logRotationBlend", weights, maps);
  const PolarParts parts = polarParts(weights, maps);
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < maps.size(); ++i) omega += weights[i] * so3Log(parts.rotations[i]);
  return affine(so3Exp(omega) * parts.stretch, parts.translation);
}

}  // namespace tetblend
