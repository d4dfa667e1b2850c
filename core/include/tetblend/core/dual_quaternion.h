#pragma once
// Dual quaternions q = q0 + eps q_eps (eps^2 = 0) representing rigid motions,
// after Kavan, Collins, O'Sullivan, Zara, "Dual Quaternions for Rigid
// Transformation Blending" (§3). A unit dual quaternion (|q0| = 1,
// <q0, q_eps> = 0) encodes the rigid motion x -> R x + T with q0 the unit
// quaternion of R and q_eps = (T/2) q0 (Kavan eq. 1); q and -q encode the same
// motion (antipodal property, Kavan §3).
//
// Blending (ScLERP, DLB, DIB) lives in dual_quaternion_blend.h.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tetblend {

/// Dual number a0 + eps a_eps (Kavan §3).
struct DualNumber {
  double real = 0.0;
  double dual = 0.0;
};

/// Below this half-angle phi (radians) of the real quaternion, exp and log use
/// Taylor series through phi^4 for phi / sin(phi), sin(phi) / phi and
/// (cos(phi) - sin(phi)/phi) / phi^2. The first dropped term is at most
/// 31 phi^6 / 15120 relative (for phi / sin(phi)), below double epsilon for
/// phi < (eps * 15120 / 31)^(1/6) = 0.0069; rounded down. Above it the closed
/// forms lose about eps/phi^2 relative in the last coefficient, which
/// multiplies <a, b> a of size phi^2 |b|: absolute error stays at round-off.
constexpr double kDualQuaternionSeriesThreshold = 5e-3;

/// A dual quaternion real + eps dual, both parts Eigen quaternions (w, x, y, z).
class DualQuaternion {
 public:
  /// The identity motion 1 + eps 0.
  DualQuaternion() : real_(1.0, 0.0, 0.0, 0.0), dual_(0.0, 0.0, 0.0, 0.0) {}
  DualQuaternion(const Eigen::Quaterniond& real, const Eigen::Quaterniond& dual)
      : real_(real), dual_(dual) {}

  static DualQuaternion Identity() { return DualQuaternion(); }

  /// Unit dual quaternion of the rigid motion [R T; 0 1] (4 by 4), Kavan eq. 1:
  /// q0 = quaternion(R), q_eps = (T/2) q0, with q0.w() >= 0. Throws DomainError
  /// when the last row is not (0 0 0 1) or R is not a rotation (|R^T R - I| or
  /// |det R - 1| above kRigidTolerance).
  static DualQuaternion fromRigid(const Eigen::Matrix4d& rigid);

  /// Same as fromRigid from a rotation and a translation, without checks.
  static DualQuaternion fromRotationTranslation(const Eigen::Quaterniond& rotation,
                                                const Eigen::Vector3d& translation);

  /// The pure dual quaternion (0, a) + eps (0, b) from two 3-vectors.
  static DualQuaternion pure(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

  /// Tolerance (absolute, unit-scale entries) of fromRigid's rigidity check.
  static constexpr double kRigidTolerance = 1e-9;

  const Eigen::Quaterniond& real() const { return real_; }
  const Eigen::Quaterniond& dual() const { return dual_; }

  /// The 4 by 4 rigid matrix [R T; 0 1] with R from real() and translation
  /// T = 2 q_eps q0^* (Kavan §3). Assumes a unit dual quaternion.
  Eigen::Matrix4d toMatrix() const;
  /// Translation T = 2 q_eps q0^* of a unit dual quaternion.
  Eigen::Vector3d translation() const;

  /// Dual-quaternion product (composition of motions: (p q) x = p (q x)).
  DualQuaternion operator*(const DualQuaternion& other) const;
  DualQuaternion operator*(double s) const;
  DualQuaternion operator+(const DualQuaternion& other) const;
  DualQuaternion operator-() const;

  /// Quaternion conjugate q0^* + eps q_eps^*: the inverse of a unit dual
  /// quaternion (Kavan §3).
  DualQuaternion conjugate() const;
  /// Dual-number conjugate q0 - eps q_eps (Kavan §3).
  DualQuaternion dualConjugate() const;

  /// Dual-number norm sqrt(q^* q) = |q0| + eps <q0, q_eps>/|q0| (Kavan §3).
  /// Requires q0 != 0 (returns dual = 0 when q0 = 0).
  DualNumber norm() const;
  /// q / |q| (dual-number division, Kavan §3): a unit dual quaternion. Throws
  /// DomainError when |q0| = 0 (no inverse of a purely dual number).
  DualQuaternion normalized() const;
  /// |q0| = 1 and <q0, q_eps> = 0 within tol (absolute).
  bool isUnit(double tol = 1e-12) const;

  /// Euclidean distance of the 8 coefficients, up to sign (antipodes equal).
  /// Useful to compare motions: small iff the motions are close.
  double distanceUpToSign(const DualQuaternion& other) const;

  /// The same motion with q0.w() >= 0 (the antipode if q0.w() < 0).
  DualQuaternion canonicalSign() const;

  /// exp of a pure dual quaternion x = (0, a) + eps (0, b) (scalar parts are
  /// ignored), Kavan §3 "Euler's identity": a unit dual quaternion. With
  /// phi = |a|: real = (cos phi, sinc(phi) a), dual = (-sinc(phi) <a,b>,
  /// sinc(phi) b + (cos phi - sinc phi)/phi^2 <a,b> a) (dual-number extension
  /// of the quaternion exp). exp(x) is the rigid motion se3Exp(2 a, 2 b).
  static DualQuaternion exp(const DualQuaternion& x);

  /// Principal logarithm of a unit dual quaternion: the pure dual quaternion
  /// x = s theta/2 (Kavan §3) with half-angle |x.real| in [0, pi]; equals half
  /// the twist se3Log of the motion when q0.w() >= 0. Throws DomainError when
  /// q0 is within 1e-12 of -1 (half-angle pi: no logarithm unless q_eps is 0;
  /// take canonicalSign() first for the logarithm of the motion).
  DualQuaternion log() const;

  /// q^t = exp(t log q) (Kavan §3), principal branch as in log().
  DualQuaternion power(double t) const;

  /// R x + T for a unit dual quaternion (Kavan §3, q v q-bar).
  Eigen::Vector3d transformPoint(const Eigen::Vector3d& x) const;

 private:
  Eigen::Quaterniond real_;
  Eigen::Quaterniond dual_;
};

}  // namespace tetblend
