#pragma once
// The Lie-Bodies representation of an oriented tetrahedron (Bansal & Tatu,
// "Affine Interpolation in a Lie Group Framework", 2019, §3-4, App. A.1):
// a tet with corners (u0, u1, u2, u3) is the triple p = (E, A, s) in
// M = SE(3) x G_A x R+ such that T = A S E (eq. 1, all 4 by 4 homogeneous)
// maps it onto the canonical tet Delta = ((0,0,0), (1,0,0), (1,1,0), (0,0,1)):
//  - E = [R d; 0 1] puts u0 at the origin, u1 on the +x axis and u2 in the
//    xy-plane with y > 0 (then u3 has z > 0: positive orientation);
//  - S = diag(s, s, s, 1), s = 1/|u1 - u0|;
//  - A in G_A (shear_group.h) maps the scaled u2, u3 to (1,1,0), (0,0,1)
//    (App. A.1.2, eq. 8-9).
// M is a direct product: product, inverse, exp and log act per component (§3.3).
// Interpolation is the per-component geodesic p exp(t log(p^-1 q)) (eq. 4),
// extrapolation the same for t outside [0, 1]; the shape blender's blend is
// p0 exp(sum_k w_k log(p0^-1 p_k)). Corner matrices are 3 by 4, corner i in
// column i, in any length unit; positively oriented means
// det[u1 - u0, u2 - u0, u3 - u0] > 0 (as in mesh_types.h).

#include <Eigen/Core>

#include <vector>

#include "tetblend/core/se3.h"

namespace tetblend {

/// Corners of one tetrahedron, 3 by 4: corner i in column i.
using TetCorners = Eigen::Matrix<double, 3, 4>;

/// An element (E, A, s) of M = SE(3) x G_A x R+ (Bansal & Tatu §3.1, eq. 1).
struct LieBody {
  Eigen::Matrix4d rigid;  ///< E = [R d; 0 1] in SE(3).
  Eigen::Matrix3d shear;  ///< A in G_A (upper triangular, A(0,0) = 1).
  double scale;           ///< s > 0 (1 / length unit).

  /// (I, I, 1): the representation of the canonical tet itself.
  static LieBody Identity();
};

/// An element of the Lie algebra m = se(3) x g_A x R (§3.3).
struct LieBodyTangent {
  Vector6d rigid;         ///< Twist (omega, v) of se(3), se3.h convention.
  Eigen::Matrix3d shear;  ///< Element of g_A (first column, lower part 0).
  double scale;           ///< log s.

  static LieBodyTangent Zero();
};

LieBodyTangent operator+(const LieBodyTangent& a, const LieBodyTangent& b);
LieBodyTangent operator-(const LieBodyTangent& a, const LieBodyTangent& b);
LieBodyTangent operator*(double w, const LieBodyTangent& x);

/// Corners of the canonical tetrahedron (0,0,0), (1,0,0), (1,1,0), (0,0,1).
TetCorners canonicalTetCorners();

/// The unique (E, A, s) with A S E mapping `corners` onto the canonical tet
/// (Theorem 1(3), App. A.1.2). E comes from a Householder QR of the edge
/// matrix (orthonormal to round-off even for slivers). Throws DomainError
/// naming the volume if the tet is not finite, not positively oriented or
/// degenerate (an edge-matrix diagonal of the QR is 0).
LieBody lieBodyFromCorners(const TetCorners& corners);

/// Corners (A S E)^-1 Delta of the tet that `body` represents (inverse of
/// lieBodyFromCorners). Corner 0 is -R^T d; the others add lieBodyEdges.
TetCorners lieBodyCorners(const LieBody& body);

/// Edge matrix [u1-u0, u2-u0, u3-u0] (3 by 3, edges as columns) of the tet of
/// `body`: R^T s^-1 A^-1 [e1, e1+e2, e3]. Independent of the translation d, so
/// it keeps full relative accuracy when the tet is far from the origin.
Eigen::Matrix3d lieBodyEdges(const LieBody& body);

/// The homogeneous map T = A S E (4 by 4, eq. 1) of `body`: it maps the tet of
/// `body` onto the canonical tet.
Eigen::Matrix4d lieBodyAffine(const LieBody& body);

/// Decomposition T = A S E of an orientation-preserving affine map T (4 by 4
/// homogeneous, det of the linear part > 0): the representation of the tet
/// T^-1 Delta (Theorem 1, §3.4). lieBodyAffine(lieBodyFromAffine(T)) = T.
/// Throws DomainError if T is not affine (last row) or not orientation
/// preserving.
LieBody lieBodyFromAffine(const Eigen::Matrix4d& map);

/// Representation of `corners` against another canonical tet `canonical`
/// (§5.1, eq. 7): (E_p, A_c^-1 A_p, s_p / s_c) where (E_p, A_p, s_p) and
/// (E_c, A_c, s_c) are the standard representations of the two tets; the
/// affine map E_c^-1 A S E_p of the result maps `corners` onto `canonical`.
LieBody lieBodyFromCorners(const TetCorners& corners, const TetCorners& canonical);

/// Inverse of the two-argument lieBodyFromCorners: corners of the tet that
/// `body` represents against `canonical` (eq. 7, 12).
TetCorners lieBodyCorners(const LieBody& body, const TetCorners& canonical);

/// Group product (E1 E2, A1 A2, s1 s2) (§3.3).
LieBody lieBodyCompose(const LieBody& a, const LieBody& b);

/// Group inverse (E^-1, A^-1, 1/s).
LieBody lieBodyInverse(const LieBody& p);

/// Per-component exponential (App. A.2.1, A.2.3, A.2.5); any rotation angle.
LieBody lieBodyExp(const LieBodyTangent& x);

/// Per-component principal logarithm (App. A.2.2, A.2.4, A.2.5): rotation
/// angle in [0, pi]. Throws DomainError if a component is outside its group.
LieBodyTangent lieBodyLog(const LieBody& p);

/// Logarithm whose rotation vector is the one closest to `rotationReference`
/// (radians) among all logarithms of R (so3LogClosest, Kaji–Ochiai Alg. 1),
/// so rotations beyond pi and 2 pi are represented; v = V(omega)^-1 T
/// (Eberly eq. 20; V from se3.h). Where V(omega) is singular to within
/// kScrewSingularValueFloor (|omega| within ~1e-8 |omega| of a non-zero
/// multiple of 2 pi) no screw with that rotation vector moves across its axis:
/// v keeps only the axial part of T, so lieBodyExp reproduces the rotation,
/// shear, scale and the axial translation exactly and misses the translation
/// across the axis (the shape blender, which uses only edges, is unaffected).
/// Throws DomainError if a component is outside its group.
LieBodyTangent lieBodyLog(const LieBody& p, const Eigen::Vector3d& rotationReference);

/// Smallest singular value 2 |sin(theta/2)| / theta of V(omega) that the
/// reference log inverts: above it |v| <= 1e8 |T|.
constexpr double kScrewSingularValueFloor = 1e-8;

/// Geodesic interpolation p exp(t log(p^-1 q)) per component (eq. 4); any real
/// t (t outside [0, 1] extrapolates, §6.2). Principal logarithms.
LieBody lieBodyInterpolate(const LieBody& p, const LieBody& q, double t);

/// Corners of the tet interpolated between tets `p` and `q` at t (eq. 4).
TetCorners lieBodyInterpolateCorners(const TetCorners& p, const TetCorners& q, double t);

/// The world-frame rotation W = R_k^T R_0 of `example` relative to `rest`:
/// the rotation factor of the example's deformation gradient
/// F = W (R_0^T U R_0), U upper triangular. Rotation vectors of W made
/// consistent over the mesh (rotation_consistency.h) are the references of
/// lieBodyRelativeLog. The rotation part of log(p0^-1 p_k) is -log W.
Eigen::Matrix3d lieBodyWorldRotation(const LieBody& rest, const LieBody& example);

/// Tangent log(p0^-1 p_k) of `example` relative to `rest` (principal logs).
LieBodyTangent lieBodyRelativeLog(const LieBody& rest, const LieBody& example);

/// Tangent log(p0^-1 p_k) whose rotation part is -omega, omega the logarithm
/// of W = lieBodyWorldRotation(rest, example) closest to
/// `worldRotationReference` (a consistent rotation vector of W, radians).
/// Same behaviour near multiples of 2 pi as the reference lieBodyLog.
LieBodyTangent lieBodyRelativeLog(const LieBody& rest, const LieBody& example,
                                  const Eigen::Vector3d& worldRotationReference);

/// Blend p0 exp(sum_k w_k X_k) per component, X_k = lieBodyRelativeLog(p0,
/// p_k) (computed once per example and tet). weights.size() must equal
/// relativeLogs.size() (else InputError). Weights 0 give p0, the k-th unit
/// vector gives p_k; weights need not sum to 1 (extrapolation).
LieBody lieBodyBlend(const LieBody& rest, const std::vector<LieBodyTangent>& relativeLogs,
                     const Eigen::VectorXd& weights);

/// Corners of lieBodyBlend(rest, relativeLogs, weights): the blended tet, from
/// which the blender forms the deformation gradient D_blend D_rest^-1.
TetCorners lieBodyBlendCorners(const LieBody& rest, const std::vector<LieBodyTangent>& relativeLogs,
                               const Eigen::VectorXd& weights);

}  // namespace tetblend
