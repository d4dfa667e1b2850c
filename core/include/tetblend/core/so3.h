#pragma once
// The rotation group SO(3) and its Lie algebra so(3): hat/vee, the exponential
// (Rodrigues), the principal logarithm (exact through theta = pi) and the
// logarithm closest to a reference (Kaji–Ochiai Alg. 1, rotations beyond 2 pi).
//
// Convention: hat(w) * v = w x v, i.e. hat(w) = [[0,-w3,w2],[w3,0,-w1],[-w2,w1,0]].
// Angles are in radians. The kernels are inline: they sit in per-tet loops.

#include <Eigen/Core>

#include <cmath>

#include "tetblend/core/constants.h"

namespace tetblend {

namespace so3_detail {

/// Below this angle (radians) the so(3) exponential and logarithm use Taylor
/// series truncated after the theta^2 term. The dropped term is O(theta^4)
/// relative (coefficients 1/120 and 7/360), so it stays below epsilon for
/// theta < eps^(1/4) ~ 1.2e-4. Above it the closed forms are accurate.
inline const double kSmallAngle = std::sqrt(std::sqrt(2.220446049250313e-16));

/// Cosine below which the logarithm takes the rotation axis from the symmetric
/// part (R + R^T)/2 = cos(theta) I + (1 - cos(theta)) a a^T (Eberly eq. (11) and
/// its special case at theta = pi) instead of the skew part sin(theta) [a]x,
/// whose direction loses accuracy as sin(theta) -> 0. For cos(theta) < 0 the
/// symmetric form has 1 - cos(theta) > 1, so it is accurate to a few ulps.
constexpr double kAxisFromSymmetricCos = 0.0;

/// Largest |omega|^2 for Rodrigues' formula in terms of omega itself: b x y
/// with b = (1 - cos t)/t^2 stays normal and t^2 finite below 2^1000 (t <
/// 2^500 ~ 3e150); above it (including t^2 = inf) so3Exp works on the unit
/// axis instead. A comparison, so the common path pays one branch.
constexpr double kMaxSquaredAngle = 0x1p+1000;

/// Default tolerance of so3LogChecked: |R^T R - I| (largest entry) and
/// |det R - 1|. Rotations written to text with 7 significant digits (single
/// precision, most mesh and animation formats) are orthonormal to ~1e-7.
constexpr double kRotationTolerance = 1e-6;

}  // namespace so3_detail

/// hat: R^3 -> so(3), the 3x3 skew-symmetric matrix with hat(w) v = w x v.
inline Eigen::Matrix3d hat(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

/// vee: so(3) -> R^3, inverse of hat. For a matrix that is not exactly
/// skew-symmetric it returns vee of its skew part (M - M^T)/2.
inline Eigen::Vector3d vee(const Eigen::Matrix3d& m) {
  return 0.5 * Eigen::Vector3d(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

namespace so3_detail {

/// I + a [v]x + b [v]x^2, written out: Rodrigues' formula with its two
/// coefficients given (Kaji–Ochiai §4.1).
inline Eigen::Matrix3d rodrigues(const Eigen::Vector3d& v, double a, double b) {
  const double x = v.x(), y = v.y(), z = v.z();
  const double bxy = b * x * y, bxz = b * x * z, byz = b * y * z;
  Eigen::Matrix3d r;
  r << 1.0 - b * (y * y + z * z), bxy - a * z, bxz + a * y,  //
      bxy + a * z, 1.0 - b * (x * x + z * z), byz - a * x,   //
      bxz - a * y, byz + a * x, 1.0 - b * (x * x + y * y);
  return r;
}

/// Rodrigues' formula on a unit axis u: I + sin(t) [u]x + (1 - cos t) [u]x^2,
/// with sin t = 2 s c and 1 - cos t = 2 s^2 (s, c the sine and cosine of t/2).
inline Eigen::Matrix3d rodriguesOnAxis(const Eigen::Vector3d& u, double s, double c) {
  return rodrigues(u, 2.0 * s * c, 2.0 * s * s);
}

/// so3Exp for |omega|^2 > kMaxSquaredAngle: the axis is taken from omega /
/// max|omega_i| (norm in [1, sqrt 3], no overflow) and the half angle is
/// formed without |omega| itself, which may exceed the double range. The rotation
/// depends on t only modulo 2 pi; std::sin/std::cos reduce t/2 exactly (the
/// C library's Payne–Hanek reduction), so the result is the rotation of the
/// given double omega, not of a rounded angle.
inline Eigen::Matrix3d so3ExpHugeAngle(const Eigen::Vector3d& omega) {
  const double m = omega.cwiseAbs().maxCoeff();
  const Eigen::Vector3d scaled = omega / m;
  const double n = scaled.norm();  // in [1, sqrt 3]
  const double half = (0.5 * m) * n;
  return rodriguesOnAxis(scaled / n, std::sin(half), std::cos(half));
}

}  // namespace so3_detail

/// Rotation matrix exp(hat(omega)) by Rodrigues' formula (Kaji–Ochiai §4.1):
/// exp(X) = I + sin(t)/t X + (1 - cos(t))/t^2 X^2, t = |omega| (radians).
/// (1 - cos t) is evaluated as 2 sin^2(t/2) to avoid cancellation; below
/// so3_detail::kSmallAngle both coefficients use their Taylor series. Any
/// finite omega is valid, including |omega| > 2 pi and |omega|^2 beyond the
/// double range (so3_detail::so3ExpHugeAngle).
inline Eigen::Matrix3d so3Exp(const Eigen::Vector3d& omega) {
  const double theta2 = omega.squaredNorm();
  if (theta2 > so3_detail::kMaxSquaredAngle) return so3_detail::so3ExpHugeAngle(omega);
  double a;  // sin(t)/t
  double b;  // (1 - cos t)/t^2
  if (theta2 < so3_detail::kSmallAngle * so3_detail::kSmallAngle) {
    a = 1.0 - theta2 / 6.0;
    b = 0.5 - theta2 / 24.0;
  } else {
    const double theta = std::sqrt(theta2);
    const double s = std::sin(0.5 * theta);
    const double c = std::cos(0.5 * theta);
    a = 2.0 * s * c / theta;
    b = 2.0 * s * s / theta2;
  }
  return so3_detail::rodrigues(omega, a, b);
}

/// Principal logarithm of a rotation matrix R (3x3, orthonormal, det +1) as a
/// rotation vector omega with |omega| = theta in [0, pi] (Kaji–Ochiai eq. (7),
/// Eberly eq. (11)). theta = atan2(|vee(R - R^T)|/2, (tr R - 1)/2), accurate
/// everywhere (acos alone loses half the digits near 0 and pi). For theta >
/// pi/2 the axis comes from the symmetric part, which makes the result exact at
/// theta = pi (Eberly's special case; the sign is then that of the largest
/// axis component's row, either is a valid logarithm). If R is only nearly
/// orthonormal, the result is the log of a nearby rotation. Precondition (not
/// checked, this sits in per-tet loops): R is a rotation; for any other matrix
/// the result is meaningless (so3Log(0) = (pi, 0, 0)). Matrices from users go
/// through so3LogChecked.
inline Eigen::Vector3d so3Log(const Eigen::Matrix3d& r) {
  const Eigen::Vector3d v = vee(r);  // sin(theta) * axis
  const double c = 0.5 * (r.trace() - 1.0);
  const double s = v.norm();
  const double theta = std::atan2(s, c);
  if (c >= so3_detail::kAxisFromSymmetricCos) {
    // theta / sin(theta) = 1 + theta^2/6 + O(theta^4).
    const double f = theta < so3_detail::kSmallAngle ? 1.0 + theta * theta / 6.0 : theta / s;
    return f * v;
  }
  // (R + R^T)/2 - c I = (1 - c) a a^T; take its best-conditioned column k
  // (largest diagonal entry), built without forming the whole matrix.
  const int k = r(0, 0) >= r(1, 1) ? (r(0, 0) >= r(2, 2) ? 0 : 2) : (r(1, 1) >= r(2, 2) ? 1 : 2);
  Eigen::Vector3d axis(0.5 * (r(0, k) + r(k, 0)), 0.5 * (r(1, k) + r(k, 1)),
                       0.5 * (r(2, k) + r(k, 2)));
  axis(k) = r(k, k) - c;
  axis /= axis.norm();
  if (axis.dot(v) < 0.0) axis = -axis;
  return theta * axis;
}

/// so3Log after checking that R (3x3) is a rotation: finite, largest entry of
/// |R^T R - I| and |det R - 1| at most `tolerance` (absolute, both
/// dimensionless). Throws DomainError naming the defect otherwise. For
/// rotations that come from outside the library (files, user code).
Eigen::Vector3d so3LogChecked(const Eigen::Matrix3d& r,
                              double tolerance = so3_detail::kRotationTolerance);

/// Logarithm of R closest (Euclidean norm in R^3) to `reference` among all
/// logarithms of R, (theta + 2 pi k) * axis for integer k (Kaji–Ochiai §4.3,
/// Alg. 1). This represents rotations by more than 2 pi when the reference
/// comes from a neighbouring element or the previous frame. For R = I exactly
/// the logarithms are the spheres |omega| = 2 pi k and the closest point on the
/// nearest sphere along `reference` is returned.
inline Eigen::Vector3d so3LogClosest(const Eigen::Matrix3d& r, const Eigen::Vector3d& reference) {
  constexpr double kTwoPi = 2.0 * kPi;
  const Eigen::Vector3d principal = so3Log(r);
  const double theta = principal.norm();
  if (theta == 0.0) {
    const double refNorm = reference.norm();
    if (refNorm == 0.0) return principal;
    return (kTwoPi * std::round(refNorm / kTwoPi) / refNorm) * reference;
  }
  const Eigen::Vector3d axis = principal / theta;
  // |reference - (theta + 2 pi k) axis|^2 is minimal for the k nearest to
  // (reference . axis - theta) / (2 pi).
  const double k = std::round((reference.dot(axis) - theta) / kTwoPi);
  return (theta + kTwoPi * k) * axis;
}

}  // namespace tetblend
