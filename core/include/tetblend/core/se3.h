#pragma once
// The rigid motions SE(3) as 4 by 4 homogeneous matrices [R T; 0 1]: the
// exponential and logarithm of Eberly, "Interpolation of Rigid Motions in 3D"
// (eq. 19-20), and the geodesic between two rigid motions (eq. 21, 27).
//
// Twists are 6-vectors xi = (omega, v): omega (first three) is the rotation
// vector (axis times angle, radians), v (last three) the translational part in
// model units. The matching Lie-algebra matrix is
//   se3Hat(xi) = [hat(omega) v; 0 0],   se3Exp(xi) = exp(se3Hat(xi)).
// Note that v is NOT the translation of se3Exp(xi): the translation is V v,
// with V = se3LeftJacobian(omega) (Eberly eq. 19-20).

#include <Eigen/Core>

namespace tetblend {

/// Twist (omega, v): rotation vector first, translational part last.
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// Below this rotation angle (radians) the coefficients of V and V^{-1} use
/// their Taylor series through theta^4. The first dropped term is at most
/// theta^6/20160 relative (for (1 - cos)/theta^2), below double epsilon for
/// theta < (20160 eps)^(1/6) = 0.0128; rounded down. Above it the closed forms
/// lose about eps/theta^2 relative in the S^2 coefficients, which multiply
/// |S^2| = theta^2, so the absolute error of V stays at round-off level.
constexpr double kSe3SeriesThreshold = 1e-2;

/// Lie-algebra matrix [hat(omega) v; 0 0] (4 by 4) of twist xi = (omega, v).
Eigen::Matrix4d se3Hat(const Vector6d& xi);

/// Inverse of se3Hat: reads omega from the skew block and v from the last
/// column of a 4 by 4 se(3) matrix (the skew part is not checked).
Vector6d se3Vee(const Eigen::Matrix4d& xiHat);

/// Eberly's V (eq. 20) for rotation vector omega, theta = |omega|:
///   V = I + (1 - cos theta)/theta^2 S + (theta - sin theta)/theta^3 S^2,
/// S = hat(omega); equal to the integral of exp(s S) over s in [0, 1]. Uses a
/// Taylor series (through theta^4) below kSe3SeriesThreshold.
Eigen::Matrix3d se3LeftJacobian(const Eigen::Vector3d& omega);

/// Eberly's V^{-1} (eq. 20):
///   V^{-1} = I - S/2 + (1 - theta sin theta / (2 (1 - cos theta)))/theta^2 S^2.
/// Finite for theta < 2 pi; series (through theta^4) below kSe3SeriesThreshold.
/// Throws DomainError for theta >= 2 pi - 1e-6 where V is (nearly) singular.
Eigen::Matrix3d se3LeftJacobianInverse(const Eigen::Vector3d& omega);

/// exp(se3Hat(xi)) = [so3Exp(omega) V v; 0 1] (Eberly eq. 19). Any angle,
/// including |omega| > 2 pi.
Eigen::Matrix4d se3Exp(const Vector6d& xi);

/// Principal logarithm of a rigid motion H = [R T; 0 1] (4 by 4): the twist
/// (omega, v) with |omega| in [0, pi], omega = so3Log(R) (Eberly eq. 11 and
/// the theta = pi branch of §4.3), v = V^{-1} T (eq. 20). At exactly theta = pi
/// the sign of omega is not unique; one of the two is returned. Throws
/// DomainError if the last row is not (0 0 0 1) or R is not a rotation
/// (|R^T R - I| or |det R - 1| above 1e-9).
Vector6d se3Log(const Eigen::Matrix4d& rigid);

/// Inverse [R^T -R^T T; 0 1] of a rigid motion (Eberly eq. 18). No check.
Eigen::Matrix4d rigidInverse(const Eigen::Matrix4d& rigid);

/// The geodesic between rigid motions H0 and H1 (4 by 4), matrix form:
///   F(t) = H0 exp(t log(H0^{-1} H1)),
/// which equals Eberly's exp(t log(H1 H0^{-1})) H0 (eq. 21, 27) because
/// log(H0^{-1} H H0) = H0^{-1} log(H) H0. F(0) = H0, F(1) = H1, constant
/// speed (eq. 30), rotation angle of H0^{-1} H1 taken in [0, pi]. Any real t
/// (t outside [0, 1] extrapolates). When H0^{-1} H1 rotates by exactly pi the
/// geodesic is not unique and one of the two is returned.
Eigen::Matrix4d se3Geodesic(double t, const Eigen::Matrix4d& H0, const Eigen::Matrix4d& H1);

}  // namespace tetblend
