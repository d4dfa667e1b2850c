#pragma once
// Shared helpers of the SE(3), dual-quaternion and baseline-blend tests:
// random rigid motions built with an independent oracle (Eigen's AngleAxis),
// and the rotation angle of a rigid motion.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <random>

#include "core_test_support.h"

namespace tetblend::core_test {

/// [R T; 0 1] with R = AngleAxis(angle, axis).
inline Eigen::Matrix4d rigidFromAngleAxis(double angle, const Eigen::Vector3d& axis,
                                          const Eigen::Vector3d& translation) {
  Eigen::Matrix4d h = Eigen::Matrix4d::Identity();
  h.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  h.topRightCorner<3, 1>() = translation;
  return h;
}

/// Random rigid motion: angle uniform in [0, maxAngle] about a uniform axis,
/// translation uniform in [-maxTranslation, maxTranslation]^3.
inline Eigen::Matrix4d randomRigid(std::mt19937& rng, double maxAngle, double maxTranslation) {
  const Eigen::Vector3d t(uniform(rng, -maxTranslation, maxTranslation),
                          uniform(rng, -maxTranslation, maxTranslation),
                          uniform(rng, -maxTranslation, maxTranslation));
  return rigidFromAngleAxis(uniform(rng, 0.0, maxAngle), randomUnitVector(rng), t);
}

/// Rotation angle in [0, pi] of the rotation block of a rigid motion.
inline double rotationAngle(const Eigen::Matrix4d& h) {
  return Eigen::AngleAxisd(Eigen::Matrix3d(h.topLeftCorner<3, 3>())).angle();
}

}  // namespace tetblend::core_test
