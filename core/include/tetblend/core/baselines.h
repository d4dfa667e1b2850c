#pragma once
// Baseline blends of affine maps that users compare the project's methods
// against (Kavan et al. §2.2 and §5 survey them; Kaji–Ochiai §2 likewise).
//
// Every function takes n >= 1 weights and n affine maps A_i as 4 by 4
// homogeneous matrices [M_i t_i; 0 0 0 1] with det M_i > 0 (units: those of
// the model; angles in radians), and returns a 4 by 4 affine matrix. Weights
// are meant to sum to 1 (they are used as given: weights summing to s scale
// the linear parts). Input errors: InputError on a size mismatch or no map;
// DomainError naming the map index on a bad last row, a non-finite entry or
// det M_i <= 0.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tetblend {

/// Linear blending of matrices sum w_i A_i (Kavan §5 "Lin", linear blend
/// skinning). Cheapest; bi-invariant (B (sum w_i A_i) C = sum w_i B A_i C).
/// Failure modes: rotations shrink and collapse (the average of +90 and -90
/// degree turns about z is singular: "candy wrapper"), rigid inputs give
/// non-rigid outputs, det can reach 0 or go negative.
Eigen::Matrix4d linearMatrixBlend(const std::vector<double>& weights,
                                  const std::vector<Eigen::Matrix4d>& maps);

/// Alexa's log-matrix blend exp(sum w_i log A_i) (Alexa 2002; Kavan §5
/// "Log"), principal matrix logarithm and exponential from Eigen's
/// MatrixFunctions. Coordinate invariant (log(T A T^-1) = T log(A) T^-1), not
/// bi-invariant, neither constant speed (Kavan App. B) nor shortest path.
/// Failure mode: a map whose linear part has an eigenvalue on the closed
/// negative real axis has no real principal logarithm (a rotation by exactly
/// pi, or a stretch with two negative eigenvalues). Eigenvalues with real
/// part < 0 and |imag| <= kAlexaRealEigenTolerance |lambda| are treated as
/// such (rotations within ~1.5e-8 rad of a half-turn, where the logarithm is
/// ill-conditioned): DomainError naming the map and the eigenvalue, never a
/// silently wrong real part of a complex logarithm.
Eigen::Matrix4d alexaBlend(const std::vector<double>& weights,
                           const std::vector<Eigen::Matrix4d>& maps);

/// Relative tolerance of alexaBlend's negative-real-eigenvalue test:
/// sqrt(epsilon), the accuracy of a computed defective (double) eigenvalue.
constexpr double kAlexaRealEigenTolerance = 1.4901161193847656e-08;

/// Shoemake–Duff polar blend: M_i = R_i S_i (polar decomposition), rotations
/// blended as unit quaternions, stretches and translations linearly:
///   n = 2: R = slerp(q_0, q_1, w_1 / (w_0 + w_1)) (shortest arc);
///   n != 2: R = normalised sum_i w_i q_i, each q_i taken in the hemisphere
///     of the quaternion with the largest |w_i| (quaternion linear blending,
///     within 8.15 degrees of slerp, Kavan §4);
///   S = sum w_i S_i, t = sum w_i t_i; result [R S, t].
/// Rigid inputs give rigid outputs; S stays symmetric positive definite for
/// convex weights. Failure modes: coordinate dependent (translation blended
/// apart from rotation, Kavan §2.2); rotations beyond pi between inputs take
/// the short way (a 4 pi twist collapses, Kaji–Ochiai Fig. 2); DomainError
/// when the weighted quaternion sum vanishes (cancelling weights) or
/// w_0 + w_1 = 0 for n = 2.
Eigen::Matrix4d polarSlerpBlend(const std::vector<double>& weights,
                                const std::vector<Eigen::Matrix4d>& maps);

/// The rotation part of polarSlerpBlend: the n unit quaternions `rotations`
/// (weights[i] for rotations[i], both n long) blended by slerp for n = 2, else
/// by the normalised sum sign-aligned with the quaternion of largest |w_i|
/// (first on ties). DomainError as polarSlerpBlend.
Eigen::Quaterniond polarSlerpRotation(const double* weights, const Eigen::Quaterniond* rotations,
                                      std::size_t n);

/// Log-rotation blend (Grassia 1998 exponential map, as used by Sumner et
/// al. 2005 for deformation features): M_i = R_i S_i (polar decomposition),
/// R = so3Exp(sum w_i so3Log(R_i)) with principal logs (|omega| <= pi),
/// S = sum w_i S_i, t = sum w_i t_i. Rigid inputs give rigid outputs; exact
/// for rotations about one common axis through angles in (-pi, pi).
/// Failure modes: coordinate dependent; not shortest path; discontinuous
/// where an input crosses a half-turn (170 and -170 degrees about one axis
/// blend through 0, the long way); rotation vectors about different axes do
/// not add like rotations.
Eigen::Matrix4d logRotationBlend(const std::vector<double>& weights,
                                 const std::vector<Eigen::Matrix4d>& maps);

}  // namespace tetblend
