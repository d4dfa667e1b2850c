#pragma once
// The shear group G_A of Bansal & Tatu, "Affine Interpolation in a Lie Group
// Framework" (2019), §3 step (3) and App. A.1.1:
//
//   G_A = { [[1, a1, a3], [0, a2, a4], [0, 0, a5]] : a2, a5 > 0 },
//   g_A = { [[0, b1, b3], [0, b2, b4], [0, 0, b5]] }        (its Lie algebra),
//
// with closed-form exp and log (App. A.2.3, A.2.4). The paper lists five cases
// for each map: b2 = 0 != b5, b5 = 0 != b2, b2 = b5 = 0, b2 = b5 != 0, and the
// general case (for the log: a2 = 1, a5 = 1, both, a2 = a5, general). They are
// exactly the coincidence patterns of the eigenvalues {0, b2, b5}, and every
// one of the ten formulas is the same expression written with divided
// differences of exp (Opitz' formula for triangular matrices):
//
//   exp(X)_12 = b1 f[0, b2],   exp(X)_23 = b4 f[b2, b5],
//   exp(X)_13 = b3 f[0, b5] + b1 b4 f[0, b2, b5],
//   f[x, y] = (e^x - e^y)/(x - y),  f[x, y, z] = (f[x, y] - f[y, z])/(x - z),
//
// each divided difference taking its confluent limit when nodes coincide
// (f[x, x] = e^x, f[x, x, x] = e^x / 2). Evaluating f robustly makes the
// transitions between the paper's cases continuous to round-off:
//  - f[x, y] = e^min(x,y) expm1(h)/h, h = |x - y|: expm1 has no cancellation,
//    so the only special point is h == 0 exactly (cases 1, 2, 4 and their
//    neighbourhoods need no threshold);
//  - f[x, y, z] uses the difference quotient of the two outer nodes when their
//    spread is at least kShearSeriesSpread, and a Taylor series (complete
//    homogeneous symmetric polynomials of the centred nodes, degrees 0..10)
//    below it (the neighbourhood of case 3, b2 = b5 = 0).
// The log inverts the three relations above; all divided differences of exp
// are positive, so the log exists and is unique on all of G_A (the principal
// matrix logarithm: the eigenvalues 1, a2, a5 are positive).

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace tetblend {

/// Spread (max - min) of the three nodes of f[x, y, z] below which the series
/// is used. eps^(1/16) ~ 0.105. Series through degree 10 in the centred nodes
/// d_i (|d_i| <= 2/3 spread): the first dropped term is at most
/// C(13, 2) (2/3 * 0.105)^11 / 13! ~ 3e-20 relative to f ~ e^mean / 2, far
/// below eps. Above it, the difference quotient (f[b,c] - f[a,b]) / (c - a)
/// amplifies the round-off of its numerator by at most ~2 e^spread / spread
/// ~ 21 (4 bits) at the switch and less beyond.
inline const double kShearSeriesSpread =
    std::pow(std::numeric_limits<double>::epsilon(), 1.0 / 16.0);

/// First divided difference of exp, f[x, y] = (e^x - e^y)/(x - y), with
/// f[x, x] = e^x. Unitless; positive.
double expDividedDifference(double x, double y);

/// Second divided difference of exp, f[x, y, z] (symmetric in its nodes), with
/// the confluent limits (f[x, x, y] = d/dx f[x, y], f[x, x, x] = e^x / 2).
/// Series below kShearSeriesSpread (see above). Positive.
double expDividedDifference(double x, double y, double z);

/// Exponential of X in g_A (3 by 3; only the five entries X(0,1), X(0,2),
/// X(1,1), X(1,2), X(2,2) are read, the others are taken as 0). Returns the
/// element of G_A (Bansal & Tatu App. A.2.3, all five cases, continuous).
Eigen::Matrix3d shearExp(const Eigen::Matrix3d& x);

/// Logarithm of A in G_A (3 by 3; reads A(0,1), A(0,2), A(1,1), A(1,2),
/// A(2,2), the others are taken as the identity's). Returns the element of g_A
/// (first column and lower triangle zero) with shearExp(log A) = A (Bansal &
/// Tatu App. A.2.4, all five cases, continuous). Throws DomainError unless
/// A(1,1) > 0 and A(2,2) > 0 and all five entries are finite.
Eigen::Matrix3d shearLog(const Eigen::Matrix3d& a);

/// Inverse of A in G_A (3 by 3 upper triangular with A(0,0) = 1), closed form
/// of the triangular inverse; stays in G_A. No check.
Eigen::Matrix3d shearInverse(const Eigen::Matrix3d& a);

}  // namespace tetblend
