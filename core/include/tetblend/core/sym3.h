#pragma once
// Symmetric 3x3 matrices: the exponential sym(3) -> Sym+(3) and the logarithm
// Sym+(3) -> sym(3) by the closed forms of Kaji–Ochiai §4.1–4.2, eq. (4)–(6)
// (cubic-formula eigenvalues and Cayley–Hamilton reduction to a quadratic in
// the matrix), written in Newton divided-difference form so that coincident
// and near-coincident eigenvalues lose no accuracy.

#include <Eigen/Core>

#include <cmath>

namespace tetblend {

/// Eigenvalues of a symmetric 3x3 matrix Y in descending order, as roots of
/// the normalised characteristic cubic x^3 - 3x - 2r (Kaji–Ochiai §4.1):
/// the largest by Halley steps from a quadratic start, the other two by
/// deflation. Absolute error a few ulps
/// of the spectral radius for well-separated eigenvalues; a (near-)double
/// eigenvalue is split with an error of order sqrt(eps) times the radius (the
/// pair's mean stays accurate). symExp/symLog are insensitive to that split:
/// their interpolation error is second order in it. Y must be symmetric (only its upper triangle
/// and diagonal are read).
Eigen::Vector3d symEigenvalues(const Eigen::Matrix3d& y);

/// Matrix exponential of a symmetric 3x3 Y (dimensionless), Kaji–Ochiai eq.
/// (4), with the series (5) extended to third order when the eigenvalue
/// spread is small. Result is symmetric positive definite up to round-off;
/// error relative to |exp Y|_F is a few ulps times the eigenvalue spread
/// (measured: 1.3 ulps per unit of spread up to 10, 9.5 at 100).
/// Eigenvalues beyond sym3_detail::kExpDirectMaxArg (where e^x would leave
/// the double range) or a spread beyond sym3_detail::kExpDirectMaxSpread
/// take V exp(Lambda) V^T instead, scaled so that no intermediate
/// overflows (error about 6 ulps times |Y|): the result is finite
/// whenever exp(Y) is representable. Throws DomainError naming the largest
/// eigenvalue if exp(Y) overflows double (largest eigenvalue above ~709.8),
/// or if Y is not finite.
Eigen::Matrix3d symExp(const Eigen::Matrix3d& y);

/// Principal logarithm of a symmetric positive definite 3x3 S, Kaji–Ochiai
/// eq. (6) (applied to S itself rather than to A^T A), of any magnitude the
/// double range holds (S is first rescaled by a power of two when its largest
/// diagonal entry leaves [kLogUnscaledMin, kLogUnscaledMax], and k ln 2 added
/// back). For cond(S) above sym3_detail::kLogClosedFormMaxCond the quadratic
/// closed form loses digits, so the logarithm is taken as V log(Lambda) V^T
/// from a QR-iteration eigen-decomposition, redone by Jacobi rotations in long
/// double when cond(S) exceeds 1/kLogLongDoubleMinRatio (so that cond up to
/// ~1e15, where double eigenvalues may even come out negative, keeps the
/// smallest eigenvalue to ~1e-4 relative). Throws DomainError if S is not
/// positive definite or not finite.
Eigen::Matrix3d symLog(const Eigen::Matrix3d& s);

namespace sym3_detail {
/// Condition number above which symLog leaves the closed form (6) for the
/// eigen-decomposition: the Vandermonde reduction amplifies round-off by about
/// cond(S) (the Z^2 term spans cond^2 while the result spans log cond).
constexpr double kLogClosedFormMaxCond = 1e2;
/// Largest |eigenvalue| and eigenvalue spread for symExp's closed form (4):
/// e^lambda2 and expm1 of the spread stay normal (ln DBL_MAX ~ 709.78, and
/// e^-700 ~ 1e-304 is normal). The batched lanes use the same bound
/// (lane_math::kExpMaxArg), so both route the same inputs to the fallback.
constexpr double kExpDirectMaxArg = 700.0;
/// Largest eigenvalue spread for symExp's closed form (4): the quadratic's
/// terms grow like e^spread and cancel, so its error per unit of spread
/// grows with it (measured against a long-double oracle, 2000 random
/// rotations each: 1.3 ulps at spreads up to 10, 9 at 64, 9.5 at 100, 33 at
/// 200, 40 at 700), while V exp(Lambda) V^T stays near 6 ulps per unit of
/// |Y|: past 100 the fallback is the more accurate. The batched lanes route
/// by the same bound.
constexpr double kExpDirectMaxSpread = 100.0;
/// symLog works unscaled while the largest diagonal entry d of S lies in
/// [kLogUnscaledMin, kLogUnscaledMax]: the cubic's p^2 ~ d^2 (and squared
/// relative deviations down to eps^2 d^2) stay normal. Outside, S is scaled
/// by 2^-ilogb(d), exactly.
constexpr double kLogUnscaledMin = 0x1p-256;
constexpr double kLogUnscaledMax = 0x1p+256;
/// Ratio lambda_min / lambda_max below which symLog recomputes the
/// eigen-decomposition in long double: a backward-stable double solver gives
/// lambda_min with relative error ~eps / ratio, 2e-8 at this ratio, and of
/// either sign at ratio ~1e-16. Long double (eps 1.1e-19 on x86-64) gives
/// ~1e-4 at ratio 1e-15.
constexpr double kLogLongDoubleMinRatio = 1e-8;
/// Eigenvalue spread lambda1 - lambda3 below which symExp evaluates the second
/// divided difference of exp (coefficient c of eq. (4)) by its Taylor series
/// through third order. The dropped fourth-order term is <= 5 h^4/720 and
/// multiplies Z(Z - l1 I), of norm <= h^2, so it stays below epsilon for
/// h < (144 eps)^(1/6) ~ 5.6e-3.
inline const double kExpSeriesSpread = std::pow(144.0 * 2.220446049250313e-16, 1.0 / 6.0);
/// Relative eigenvalue spread (mu1 - mu3)/mu2 below which symLog evaluates the
/// second divided difference of log by its Taylor series through third order.
/// The dropped term is <= 5 h^4/6 and multiplies a matrix of norm <= h^2, so
/// it stays below epsilon for h < (1.2 eps)^(1/6) ~ 8.1e-3.
inline const double kLogSeriesSpread = std::pow(1.2 * 2.220446049250313e-16, 1.0 / 6.0);
}  // namespace sym3_detail

}  // namespace tetblend
