#pragma once
// Blending of rigid motions with dual quaternions (Kavan et al., "Dual
// Quaternions for Rigid Transformation Blending", §4) and the dual-quaternion
// form of the SE(3) geodesic (Eberly, "Interpolation of Rigid Motions in 3D",
// §4.2 eq. 33).
//
// All inputs are unit dual quaternions; antipodes q and -q are accepted
// anywhere (they encode the same motion) and handled as documented per
// function. Weights need not be convex unless stated; for convex weights DLB
// and DIB are bi-invariant (Kavan §4, Table 1).

#include <vector>

#include <Eigen/Core>

#include "tetblend/core/dual_quaternion.h"

namespace tetblend {

/// Screw linear interpolation ScLERP(t; p, q) = p (p^* q)^t (Kavan §4), with
/// p^* q replaced by its antipode when its real scalar part is negative, so
/// the path is the shortest one (rotation angle of p^{-1} q in [0, pi]).
/// Constant speed, shortest path, bi-invariant (Kavan Lemma 2). Any real t.
DualQuaternion scLerp(double t, const DualQuaternion& p, const DualQuaternion& q);

/// Dual quaternion linear blending DLB(w; q_1..q_n) = sum w_i q_i / |sum w_i q_i|
/// (Kavan §4). Antipodes: the input with the largest |weight| is the pivot and
/// every q_i whose real part has a negative 4D dot product with the pivot's
/// is used as -q_i, so each input enters through its representative nearest
/// the pivot. Shortest path, bi-invariant, within 8.15 degrees of ScLERP for
/// n = 2 (Kavan §4). `dqs` and `weights` hold `count` >= 1 entries. Throws
/// DomainError when the blended real part is zero (weights that cancel; not
/// possible for non-negative weights with a positive one).
DualQuaternion dlb(const DualQuaternion* dqs, const double* weights, int count);

/// DLB over vectors of equal size (>= 1); throws InputError on a size mismatch.
DualQuaternion dlb(const std::vector<DualQuaternion>& dqs, const std::vector<double>& weights);

/// Options of dib().
struct DibOptions {
  /// Stop when the Euclidean norm of the 6 coefficients of the update
  /// x = sum w_i log(b^* q_i) (half-angles in radians and half-translations in
  /// model units, Kavan §4 "until |x| < p") falls below this. Absolute.
  double precision = 1e-13;
  /// Cap on the number of updates b <- b exp(x). Kavan reports 1 to 4 steps
  /// at graphics precision; at the default precision 4 inputs spread over
  /// 1.5 rad take up to ~13 (linear convergence).
  int maxIterations = 50;
};

/// Result of dib().
struct DibResult {
  DualQuaternion blend;    ///< Unit dual quaternion, canonical sign (w >= 0).
  int iterations = 0;      ///< Updates b <- b exp(x) applied.
  double residual = 0;     ///< Norm of the last update x evaluated (see DibOptions).
  bool converged = false;  ///< residual < precision was reached.
};

/// Dual quaternion iterative blending (Kavan §4, DIB): starts from DLB and
/// iterates b <- b exp(sum w_i log(b^* q_i)) until the update is below
/// options.precision or options.maxIterations updates were applied (then
/// converged = false; the last estimate is still returned). Each b^* q_i is
/// taken with non-negative real scalar part (the logarithm of the motion), so
/// antipodal inputs are handled. Requires sum w_i = 1 (within 1e-9, else
/// InputError): the fixed point is the weighted Lie-group mean. For two
/// inputs the first update lands on ScLERP (Kavan Lemma 3): iterations = 1.
DibResult dib(const std::vector<DualQuaternion>& dqs, const std::vector<double>& weights,
              const DibOptions& options = {});

/// Eberly's dual-quaternion form of the SE(3) geodesic between the rigid
/// motions H0 and H1 (4 by 4), eq. 33: d(t) = q(t) + eps (q(t) a + b(t) q(t))/2
/// with q(t) the slerp of the rotations (shortest way), a = R0^T T0 and
/// b(t) = t V(t) U from (S, U) = log(H1 H0^{-1}) (eq. 22-25). Equals ScLERP of
/// the dual quaternions of H0, H1 and the matrix geodesic se3Geodesic.
DualQuaternion eberlyGeodesic(double t, const Eigen::Matrix4d& H0, const Eigen::Matrix4d& H1);

}  // namespace tetblend
