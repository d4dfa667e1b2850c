#include "tetblend/core/sym3.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "power_of_two.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

/// Z^2 for symmetric Z, evaluated so the result is exactly symmetric.
Eigen::Matrix3d symSquare(const Eigen::Matrix3d& z) {
  Eigen::Matrix3d r;
  r(0, 0) = z(0, 0) * z(0, 0) + z(0, 1) * z(0, 1) + z(0, 2) * z(0, 2);
  r(1, 1) = z(0, 1) * z(0, 1) + z(1, 1) * z(1, 1) + z(1, 2) * z(1, 2);
  r(2, 2) = z(0, 2) * z(0, 2) + z(1, 2) * z(1, 2) + z(2, 2) * z(2, 2);
  r(0, 1) = r(1, 0) = z(0, 0) * z(0, 1) + z(0, 1) * z(1, 1) + z(0, 2) * z(1, 2);
  r(0, 2) = r(2, 0) = z(0, 0) * z(0, 2) + z(0, 1) * z(1, 2) + z(0, 2) * z(2, 2);
  r(1, 2) = r(2, 1) = z(0, 1) * z(0, 2) + z(1, 1) * z(1, 2) + z(1, 2) * z(2, 2);
  return r;
}

/// First divided difference of exp at (0, x): expm1(x)/x, accurate for all x.
double expDivided(double x) { return x == 0.0 ? 1.0 : std::expm1(x) / x; }

/// First divided difference of log at (1, 1 + x): log1p(x)/x.
double logDivided(double x) { return x == 0.0 ? 1.0 : std::log1p(x) / x; }

/// The symmetric matrix whose upper triangle and diagonal are those of y.
Eigen::Matrix3d fromUpper(const Eigen::Matrix3d& y) {
  Eigen::Matrix3d m = y;
  m(1, 0) = y(0, 1);
  m(2, 0) = y(0, 2);
  m(2, 1) = y(1, 2);
  return m;
}

/// symExp outside the closed form's range: V exp(Lambda - lambda_max) V^T,
/// multiplied by e^(lambda_max / 2) twice so that neither factor overflows
/// while the product is representable.
Eigen::Matrix3d symExpByEigenDecomposition(const Eigen::Matrix3d& y) {
  if (!y.allFinite()) throw DomainError("symExp: matrix has a non-finite entry");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(fromUpper(y));
  const Eigen::Vector3d mu = es.eigenvalues();  // ascending
  const double top = mu(2);
  // The largest diagonal entry of exp(Y) is at least e^top / 3.
  const double kOverflowArg = std::log(std::numeric_limits<double>::max()) + std::log(3.0);
  if (es.info() != Eigen::Success || !(top <= kOverflowArg)) {
    std::ostringstream msg;
    msg << "symExp: largest eigenvalue " << top
        << " of the symmetric matrix; its exponential overflows double (the largest"
           " representable is e^709.78)";
    throw DomainError(msg.str());
  }
  const Eigen::Matrix3d& v = es.eigenvectors();
  const Eigen::Vector3d e = (mu.array() - top).exp().matrix();
  const double half = std::exp(0.5 * top);
  const Eigen::Matrix3d unit = v * e.asDiagonal() * v.transpose();  // exp(Y - top I)
  const Eigen::Matrix3d r = ((0.5 * (unit + unit.transpose())) * half) * half;
  if (!r.allFinite()) {
    std::ostringstream msg;
    msg << "symExp: largest eigenvalue " << top
        << " of the symmetric matrix; an entry of its exponential overflows double";
    throw DomainError(msg.str());
  }
  return r;
}

[[noreturn]] void throwNotPositiveDefinite(double smallest) {
  std::ostringstream msg;
  msg << "symLog: matrix is not symmetric positive definite (smallest eigenvalue " << smallest
      << "); the logarithm of a stretch needs S > 0";
  throw DomainError(msg.str());
}

using Matrix3ld = Eigen::Matrix<long double, 3, 3>;

/// Sweeps of cyclic Jacobi: convergence is quadratic once the off-diagonal
/// is below the eigenvalue gaps; a 3x3 matrix needs 4 to 6.
constexpr int kJacobiMaxSweeps = 12;

/// V log(Lambda) V^T in long double by cyclic Jacobi rotations (Golub & Van
/// Loan, Alg. 8.5.3), with the relative stopping test |a_pq| <= eps
/// sqrt(a_pp a_qq) of Demmel and Veselic, which keeps small eigenvalues of a
/// positive definite matrix to relative accuracy.
Eigen::Matrix3d symLogByLongDoubleJacobi(const Eigen::Matrix3d& s) {
  using std::abs;
  using std::sqrt;
  const long double eps = std::numeric_limits<long double>::epsilon();
  Matrix3ld a = fromUpper(s).cast<long double>();
  Matrix3ld v = Matrix3ld::Identity();
  for (int sweep = 0; sweep < kJacobiMaxSweeps; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        const long double apq = a(p, q);
        if (!(abs(apq) > eps * sqrt(abs(a(p, p) * a(q, q))))) continue;
        rotated = true;
        const long double tau = (a(q, q) - a(p, p)) / (2 * apq);
        const long double t = (tau >= 0 ? 1 : -1) / (abs(tau) + sqrt(1 + tau * tau));
        const long double c = 1 / sqrt(1 + t * t), sn = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- A J
          const long double akp = a(k, p), akq = a(k, q);
          a(k, p) = c * akp - sn * akq;
          a(k, q) = sn * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // A <- J^T A
          const long double apk = a(p, k), aqk = a(q, k);
          a(p, k) = c * apk - sn * aqk;
          a(q, k) = sn * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // V <- V J
          const long double vkp = v(k, p), vkq = v(k, q);
          v(k, p) = c * vkp - sn * vkq;
          v(k, q) = sn * vkp + c * vkq;
        }
      }
    }
    if (!rotated) break;
  }
  const Eigen::Matrix<long double, 3, 1> mu = a.diagonal();
  if (!(mu.minCoeff() > 0)) throwNotPositiveDefinite(static_cast<double>(mu.minCoeff()));
  const Matrix3ld r = v * mu.array().log().matrix().asDiagonal() * v.transpose();
  return (0.5L * (r + r.transpose())).cast<double>();
}

Eigen::Matrix3d symLogByEigenDecomposition(const Eigen::Matrix3d& s) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(s);
  const Eigen::Vector3d mu = es.eigenvalues();  // ascending
  if (es.info() == Eigen::Success && !(mu(0) >= sym3_detail::kLogLongDoubleMinRatio * mu(2))) {
    return symLogByLongDoubleJacobi(s);
  }
  if (es.info() != Eigen::Success || !(mu(0) > 0.0)) throwNotPositiveDefinite(mu.minCoeff());
  const Eigen::Matrix3d& v = es.eigenvectors();
  const Eigen::Matrix3d r = v * mu.array().log().matrix().asDiagonal() * v.transpose();
  return 0.5 * (r + r.transpose());
}

/// symLog of S whose largest diagonal entry d is outside the unscaled range:
/// log(S) = log(2^-k S) + k ln 2 I with k = ilogb(d), exact scaling.
Eigen::Matrix3d symLogRescaled(const Eigen::Matrix3d& s, double d) {
  if (!(d > 0.0)) throwNotPositiveDefinite(d);  // some diagonal entry of S > 0 is <= 0
  const int k = std::ilogb(d);
  Eigen::Matrix3d r = symLog(core_detail::timesPowerOfTwo(s, -k));
  r.diagonal().array() += k * core_detail::kLn2;
  return r;
}

}  // namespace

Eigen::Vector3d symEigenvalues(const Eigen::Matrix3d& y) {
  const double q = y.trace() / 3.0;
  const double b00 = y(0, 0) - q, b11 = y(1, 1) - q, b22 = y(2, 2) - q;
  const double b01 = y(0, 1), b02 = y(0, 2), b12 = y(1, 2);
  const double p2 =
      (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (b01 * b01 + b02 * b02 + b12 * b12)) / 6.0;
  if (p2 == 0.0) return Eigen::Vector3d::Constant(q);
  const double p = std::sqrt(p2);
  const double ip = 1.0 / p;
  const double c00 = b00 * ip, c11 = b11 * ip, c22 = b22 * ip;
  const double c01 = b01 * ip, c02 = b02 * ip, c12 = b12 * ip;
  const double det =
      c00 * (c11 * c22 - c12 * c12) - c01 * (c01 * c22 - c12 * c02) + c02 * (c01 * c12 - c11 * c02);
  const double r = std::clamp(0.5 * det, -1.0, 1.0);
  // The eigenvalues of C are the roots of x^3 - 3x - 2r, i.e. 2 cos(acos(r)/3
  // + 2 pi k/3) (§4.1). Rather than acos and sin/cos, solve for the root that
  // stays simple on this half of r: x in [sqrt 3, 2], the largest root at |r|
  // (the largest root for r >= 0, minus the smallest for r < 0), by Halley's
  // method from a quadratic fit (error < 1.1e-3; f' >= 6 on the interval, so
  // the cubic convergence takes two steps to round-off: 1e-3 -> 6e-10 -> 1e-27).
  // Deflation leaves x'^2 + x x' + x^2 - 3 for the pair
  // x' = (-x +- d)/2, d = sqrt(3 (2 - x)(2 + x)) (signs mirrored for r < 0).
  const double a = std::abs(r);
  // Fit: the quadratic through (0, sqrt 3), (1/2, 2 cos(pi/9)), (1, 2).
  double x = 1.7320508075688774 + a * (0.3213885435806343 - 0.053439351149511705 * a);
  for (int it = 0; it < 2; ++it) {
    const double f = x * (x * x - 3.0) - 2.0 * a;
    const double df = 3.0 * (x * x - 1.0);
    x -= 2.0 * f * df / (2.0 * df * df - 6.0 * x * f);
  }
  const double d = std::sqrt(3.0 * std::max(0.0, (2.0 - x) * (2.0 + x)));
  const double top = r >= 0.0 ? x : 0.5 * (x + d);
  const double bottom = r >= 0.0 ? -0.5 * (x + d) : -x;
  const double l1 = q + p * top;
  const double l3 = q + p * bottom;
  return Eigen::Vector3d(l1, 3.0 * q - l1 - l3, l3);
}

Eigen::Matrix3d symExp(const Eigen::Matrix3d& y) {
  const Eigen::Vector3d lambda = symEigenvalues(y);
  const double l1 = lambda(0) - lambda(1);  // >= 0
  const double l3 = lambda(2) - lambda(1);  // <= 0
  const double h = l1 - l3;
  // Negated so that NaN (entries beyond ~1e154 overflow the cubic) also leaves.
  if (!(std::max(std::abs(lambda(0)), std::abs(lambda(2))) <= sym3_detail::kExpDirectMaxArg &&
        h <= sym3_detail::kExpDirectMaxSpread)) {
    return symExpByEigenDecomposition(y);
  }
  // Newton form of the interpolating quadratic at the nodes (0, l1, l3) of
  // exp(x + lambda2): exp(Y) = e^lambda2 (I + b Z + c Z^2), Z = Y - lambda2 I,
  // with c = exp[0, l1, l3] and b = exp[0, l1] - l1 c (eq. (4)).
  const double e1 = expDivided(l1);
  double c;
  if (h < sym3_detail::kExpSeriesSpread) {
    // exp[0, l1, l3] = sum_k h_k(l1, l3) / (k + 2)!, h_k complete homogeneous;
    // series through k = 3 (eq. (5) plus one order).
    c = 0.5 + (l1 + l3) / 6.0 + (l1 * l1 + l1 * l3 + l3 * l3) / 24.0 +
        (l1 + l3) * (l1 * l1 + l3 * l3) / 120.0;
  } else {
    c = (e1 - expDivided(l3)) / h;
  }
  const double b = e1 - l1 * c;
  Eigen::Matrix3d z = y;
  z.diagonal().array() -= lambda(1);
  z(1, 0) = z(0, 1);
  z(2, 0) = z(0, 2);
  z(2, 1) = z(1, 2);
  Eigen::Matrix3d r = b * z + c * symSquare(z);
  r.diagonal().array() += 1.0;
  return std::exp(lambda(1)) * r;
}

Eigen::Matrix3d symLog(const Eigen::Matrix3d& s) {
  if (!s.allFinite()) throw DomainError("symLog: matrix has a non-finite entry");
  const double d = std::max({s(0, 0), s(1, 1), s(2, 2)});
  if (!(d >= sym3_detail::kLogUnscaledMin && d <= sym3_detail::kLogUnscaledMax)) {
    return symLogRescaled(s, d);
  }
  const Eigen::Vector3d mu = symEigenvalues(s);
  if (!(mu(2) > 0.0) || mu(0) > sym3_detail::kLogClosedFormMaxCond * mu(2)) {
    return symLogByEigenDecomposition(s);
  }
  // W = S/mu2 - I has eigenvalues x1 >= 0 = x2 >= x3 > -1. Newton form of the
  // interpolating quadratic of log1p at (0, x1, x3) (eq. (6) in another basis):
  // log S = log(mu2) I + (d1 - x1 d2) W + d2 W^2,
  // d1 = log1p[0, x1], d2 = log1p[0, x1, x3].
  const double x1 = (mu(0) - mu(1)) / mu(1);
  const double x3 = (mu(2) - mu(1)) / mu(1);
  const double h = x1 - x3;
  const double d1 = logDivided(x1);
  double d2;
  if (h < sym3_detail::kLogSeriesSpread) {
    // log1p(x)/x = sum_k (-1)^k x^k/(k+1); its divided difference is
    // sum_{k>=1} (-1)^k h_{k-1}(x1, x3)/(k+1), series through k = 4.
    d2 = -0.5 + (x1 + x3) / 3.0 - (x1 * x1 + x1 * x3 + x3 * x3) / 4.0 +
         (x1 + x3) * (x1 * x1 + x3 * x3) / 5.0;
  } else {
    d2 = (d1 - logDivided(x3)) / h;
  }
  Eigen::Matrix3d w = s / mu(1);
  w.diagonal().array() -= 1.0;
  w(1, 0) = w(0, 1);
  w(2, 0) = w(0, 2);
  w(2, 1) = w(1, 2);
  Eigen::Matrix3d r = (d1 - x1 * d2) * w + d2 * symSquare(w);
  r.diagonal().array() += std::log(mu(1));
  return r;
}

}  // namespace tetblend
