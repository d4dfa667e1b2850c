#pragma once
// Distortion and rotation of one tet's deformation gradient F: the figures of
// the "distortion" and "rotation_angle" quality arrays.

#include <Eigen/Core>

namespace tetblend {

/// sigma_max / sigma_min of F (of |F| when det F <= 0; +inf when
/// sigma_min = 0) and the angle (radians, [0, pi]) of F's polar rotation (NaN
/// when det F <= 0).
struct TetDistortion {
  double conditionNumber = 0.0;
  double rotationAngle = 0.0;
};

/// The figures of F (det F given as `det`) by the closed-form SVD of core
/// (polar_detail::svdClosedForm: sigma and the polar rotation U V^T) when
/// det F > 0 lies in the polar range it takes and it accepts F (cond <= 1e3,
/// a-posteriori residual check); tetDistortionReference otherwise. Agrees
/// with the reference to the round-off its residual check bounds (see
/// tests/blending/tet_distortion_test.cpp).
TetDistortion tetDistortion(const Eigen::Matrix3d& f, double det);

/// The reference figures: Eigen's JacobiSVD singular values and polar
/// rotation U V^T (polar_detail::svdRotation), for any F: a method
/// independent of polarDecompose's Newton iteration, which the tests compare
/// it with.
TetDistortion tetDistortionReference(const Eigen::Matrix3d& f, double det);

}  // namespace tetblend
