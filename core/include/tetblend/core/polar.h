#pragma once
// Polar decomposition A = R S of a 3x3 matrix with det A > 0: R in SO(3), S
// symmetric positive definite (the rotation and stretch factors of
// Kaji–Ochiai eq. (3), S = sqrt(A^T A), computed without forming A^T A).

#include <Eigen/Core>

namespace tetblend {

/// The factors of A = rotation * stretch.
struct PolarDecomposition {
  Eigen::Matrix3d rotation;  ///< R in SO(3).
  Eigen::Matrix3d stretch;   ///< S = R^T A, symmetric positive definite.
};

/// The rotation factor and the logarithm of the stretch factor of A.
struct PolarLogDecomposition {
  Eigen::Matrix3d rotation;    ///< R in SO(3).
  Eigen::Matrix3d stretchLog;  ///< log S = V log(Sigma) V^T, symmetric.
};

/// Polar decomposition A = R S (3x3, any units; S has the units of A) by
/// Higham's scaled Newton iteration X <- (g X + X^{-T}/g)/2 with Frobenius
/// scaling g (Higham, Functions of Matrices, §8.6), which works on A itself
/// and so keeps the accuracy of near-singular A (cond(A) up to ~1e12) instead
/// of squaring the condition number through A^T A.
/// Any scale the double range holds: A with det A outside
/// [polar_detail::kUnscaledMinDet, kUnscaledMaxDet] is first scaled by a power
/// of two 2^-k (exactly) to det in [1, 8), and S scaled back by 2^k.
/// Where the iteration meets a non-positive det or does not settle in 30
/// steps (A so near singular that its det is round-off), the factors come
/// from the Jacobi SVD instead (R = U V^T, S = sym(R^T A)).
/// Throws DomainError if det A <= 0 or A is not finite (no reflection is ever
/// returned).
PolarDecomposition polarDecompose(const Eigen::Matrix3d& a);

/// Rotation factor of A and log S = V log(Sigma) V^T (Sigma = singular values
/// of A; Kaji–Ochiai eq. (3), psi_S). Well-conditioned A (cond <=
/// polar_detail::kClosedFormMaxCond) takes the closed form of
/// polar_detail::polarLogClosedForm; otherwise, or if its a-posteriori check
/// fails, polarDecompose followed by symLog. A with det A outside
/// [polar_detail::kUnscaledMinDet, kUnscaledMaxDet] is decomposed as 2^-k A,
/// det in [1, 8), and k ln 2 I added to log S: psi_S(c A) = psi_S(A) + log(c) I
/// holds for every scale the double range holds. Same errors as
/// polarDecompose.
PolarLogDecomposition polarDecomposeLog(const Eigen::Matrix3d& a);

namespace polar_detail {
/// Range of det A that the decompositions take as is. Inside it the closed
/// form's A^T A and its cubic (fourth powers of A, for cond <= 1e3) and the
/// Newton iteration's cofactors and inverse (for cond up to ~1e16) stay far
/// from overflow and underflow; outside it A is rescaled by a power of two.
/// The batched lanes take the same range.
constexpr double kUnscaledMinDet = 0x1p-128;
constexpr double kUnscaledMaxDet = 0x1p+128;
/// Largest cond(A) = sigma_1/sigma_3 for the closed form: it diagonalises
/// A^T A, whose smallest eigenvalue carries an absolute error eps sigma_1^2,
/// i.e. eps cond^2 relative (2e-10 at 1e3). sigma_i = |A v_i| is then only
/// second order in the eigenvector error, and the residual check below
/// decides acceptance; the bound keeps the closed form within the range the
/// tests exercise (accepted and accurate at 0.9e3, declined at 1.1e3).
constexpr double kClosedFormMaxCond = 1e3;
/// A-posteriori acceptance of the closed form: |A - R S|_F <= this * |A|_F
/// with R orthonormal and S SPD by construction. Backward error this small
/// bounds the forward error of R by about this * cond(A) (the polar factor's
/// condition number), so the result is as good as the Newton iteration's.
constexpr double kClosedFormMaxResidual = 32 * 2.220446049250313e-16;

/// The polar rotation U V^T of A from Eigen's Jacobi SVD A = U Sigma V^T,
/// for any A with det A > 0 (not checked here); where rounding gives U V^T
/// det -1 (sigma_min lost in A's round-off), the smallest singular direction
/// is flipped, as det A > 0 asks. polarDecompose's fallback.
Eigen::Matrix3d svdRotation(const Eigen::Matrix3d& a);

/// Closed-form polar decomposition with stretch logarithm for
/// well-conditioned A (3x3, det A > 0 assumed; not checked here): eigenvalues
/// of A^T A by the trigonometric cubic (symEigenvalues, Kaji–Ochiai §4.1), the
/// most isolated eigenvector by cross products of the rows of A^T A - mu I,
/// the other two from the 2x2 problem in its orthogonal complement (Eberly,
/// "A Robust Eigensolver for 3x3 Symmetric Matrices"), V right-handed;
/// sigma_i = |A v_i|, U = A V Sigma^-1 re-orthonormalised (Gram–Schmidt,
/// u3 = u1 x u2), R = U V^T refined by one first-order step that makes
/// R^T A symmetric (the residual bound alone allows 32 eps * cond(A) of error
/// in R; after the step about eps * cond(A)), log S = V log(Sigma) V^T.
/// Returns false (and leaves `out` unspecified) if cond(A) >
/// kClosedFormMaxCond or the residual exceeds kClosedFormMaxResidual.
bool polarLogClosedForm(const Eigen::Matrix3d& a, PolarLogDecomposition& out);

/// The factors of polarLogClosedForm: A = U diag(sigma) V^T with U, V
/// rotations and sigma_i = |A v_i| (in V's column order: descending up to
/// round-off), under the same acceptance (cond(A) <= kClosedFormMaxCond,
/// residual <= kClosedFormMaxResidual |A|_F); false when declined (the
/// outputs are then unspecified). The polar rotation is U V^T.
bool svdClosedForm(const Eigen::Matrix3d& a, Eigen::Matrix3d& u, Eigen::Vector3d& sigma,
                   Eigen::Matrix3d& v);
}  // namespace polar_detail

}  // namespace tetblend
