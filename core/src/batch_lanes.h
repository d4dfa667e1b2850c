#pragma once
// Private to batch_kernels.cpp: the scalar kernels of so3.h, sym3.cpp and
// polar.cpp rewritten lane by lane (plain doubles, selects instead of
// branches, lane_math.h instead of libm) so that a loop over a block of
// elements vectorises. Each lane function follows its scalar original step by
// step (same formulas, thresholds and branch choices) and returns false where
// the scalar kernel must decide instead (argument outside the lane_math
// ranges, a fallback branch of the scalar kernel, or an error to throw).

#include <algorithm>
#include <cmath>

#include "tetblend/core/lane_math.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

#define TETBLEND_LANE TETBLEND_LANE_INLINE

namespace tetblend::batch_detail {

/// Smallest positive normal double: logLane's domain.
constexpr double kMinNormal = 2.2250738585072014e-308;

/// A symmetric 3x3 matrix by its upper triangle.
struct Sym {
  double xx, xy, xz, yy, yz, zz;
};

/// A 3x3 matrix, row-major.
struct Mat {
  double m[9];
};

/// symEigenvalues (sym3.cpp), descending.
TETBLEND_LANE void eigenvaluesLane(const Sym& y, double& l1, double& l2, double& l3) {
  const double q = (y.xx + y.yy + y.zz) / 3.0;
  const double b00 = y.xx - q, b11 = y.yy - q, b22 = y.zz - q;
  const double p2 =
      (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * (y.xy * y.xy + y.xz * y.xz + y.yz * y.yz)) / 6.0;
  const double p = std::sqrt(p2);
  const double ip = 1.0 / p;
  const double c00 = b00 * ip, c11 = b11 * ip, c22 = b22 * ip;
  const double c01 = y.xy * ip, c02 = y.xz * ip, c12 = y.yz * ip;
  const double det =
      c00 * (c11 * c22 - c12 * c12) - c01 * (c01 * c22 - c12 * c02) + c02 * (c01 * c12 - c11 * c02);
  const double halfDet = 0.5 * det;
  const double r = halfDet > 1.0 ? 1.0 : (halfDet < -1.0 ? -1.0 : halfDet);
  const double a = std::abs(r);
  double x = 1.7320508075688774 + a * (0.3213885435806343 - 0.053439351149511705 * a);
#pragma GCC unroll 9
  for (int it = 0; it < 2; ++it) {
    const double f = x * (x * x - 3.0) - 2.0 * a;
    const double df = 3.0 * (x * x - 1.0);
    x -= 2.0 * f * df / (2.0 * df * df - 6.0 * x * f);
  }
  const double d = std::sqrt(3.0 * std::max(0.0, (2.0 - x) * (2.0 + x)));
  const double top = r >= 0.0 ? x : 0.5 * (x + d);
  const double bottom = r >= 0.0 ? -0.5 * (x + d) : -x;
  const bool flat = p2 == 0.0;
  l1 = flat ? q : q + p * top;
  l3 = flat ? q : q + p * bottom;
  l2 = flat ? q : 3.0 * q - l1 - l3;
}

/// r = z^2 for symmetric z.
TETBLEND_LANE Sym symSquareLane(const Sym& z) {
  return {z.xx * z.xx + z.xy * z.xy + z.xz * z.xz, z.xx * z.xy + z.xy * z.yy + z.xz * z.yz,
          z.xx * z.xz + z.xy * z.yz + z.xz * z.zz, z.xy * z.xy + z.yy * z.yy + z.yz * z.yz,
          z.xy * z.xz + z.yy * z.yz + z.yz * z.zz, z.xz * z.xz + z.yz * z.yz + z.zz * z.zz};
}

/// symExp (sym3.cpp, Kaji–Ochiai eq. (4)-(5)).
TETBLEND_LANE bool symExpLane(const Sym& y, Sym& out) {
  double lambda1, lambda2, lambda3;
  eigenvaluesLane(y, lambda1, lambda2, lambda3);
  const double l1 = lambda1 - lambda2, l3 = lambda3 - lambda2, h = l1 - l3;
  // exp(lambda2), expm1(l1), expm1(l3) in range (|l1|, |l3| <= h); the
  // scalar kernel's closed-form range, so the rest goes to its fallback.
  static_assert(sym3_detail::kExpDirectMaxArg <= lane_math::kExpMaxArg &&
                sym3_detail::kExpDirectMaxSpread <= lane_math::kExpMaxArg);
  const bool ok =
      (std::max(std::abs(lambda1), std::abs(lambda3)) <= sym3_detail::kExpDirectMaxArg) &
      (h <= sym3_detail::kExpDirectMaxSpread);
  double e2, unused, em1, em3;
  lane_math::expExpm1Lane(ok ? lambda2 : 0.0, e2, unused);
  lane_math::expExpm1Lane(ok ? l1 : 0.0, unused, em1);
  lane_math::expExpm1Lane(ok ? l3 : 0.0, unused, em3);
  const double e1 = l1 == 0.0 ? 1.0 : em1 / l1;
  const double e3 = l3 == 0.0 ? 1.0 : em3 / l3;
  const double series = 0.5 + (l1 + l3) / 6.0 + (l1 * l1 + l1 * l3 + l3 * l3) / 24.0 +
                        (l1 + l3) * (l1 * l1 + l3 * l3) / 120.0;
  const double c = h < sym3_detail::kExpSeriesSpread ? series : (e1 - e3) / h;
  const double b = e1 - l1 * c;
  const Sym z{y.xx - lambda2, y.xy, y.xz, y.yy - lambda2, y.yz, y.zz - lambda2};
  const Sym z2 = symSquareLane(z);
  out = {e2 * (b * z.xx + c * z2.xx + 1.0), e2 * (b * z.xy + c * z2.xy),
         e2 * (b * z.xz + c * z2.xz),       e2 * (b * z.yy + c * z2.yy + 1.0),
         e2 * (b * z.yz + c * z2.yz),       e2 * (b * z.zz + c * z2.zz + 1.0)};
  return ok;
}

/// symLog (sym3.cpp, Kaji–Ochiai eq. (6)) on its closed-form range
/// (cond <= kLogClosedFormMaxCond, largest diagonal entry in the unscaled
/// range); false elsewhere.
TETBLEND_LANE bool symLogLane(const Sym& s, Sym& out) {
  double mu1, mu2, mu3;
  eigenvaluesLane(s, mu1, mu2, mu3);
  const double d = std::max(s.xx, std::max(s.yy, s.zz));
  const bool ok = mu3 >= kMinNormal && mu1 <= sym3_detail::kLogClosedFormMaxCond * mu3 &&
                  d >= sym3_detail::kLogUnscaledMin && d <= sym3_detail::kLogUnscaledMax;
  const double m2 = ok ? mu2 : 1.0;
  const double x1 = (mu1 - mu2) / m2, x3 = (mu3 - mu2) / m2, h = x1 - x3;
  const double d1 = x1 == 0.0 ? 1.0 : lane_math::log1pLane(ok ? x1 : 0.0) / x1;
  const double d3 = x3 == 0.0 ? 1.0 : lane_math::log1pLane(ok ? x3 : 0.0) / x3;
  const double series = -0.5 + (x1 + x3) / 3.0 - (x1 * x1 + x1 * x3 + x3 * x3) / 4.0 +
                        (x1 + x3) * (x1 * x1 + x3 * x3) / 5.0;
  const double d2 = h < sym3_detail::kLogSeriesSpread ? series : (d1 - d3) / h;
  const double b = d1 - x1 * d2;
  const double logMu2 = lane_math::logLane(m2);
  const Sym w{s.xx / m2 - 1.0, s.xy / m2, s.xz / m2, s.yy / m2 - 1.0, s.yz / m2, s.zz / m2 - 1.0};
  const Sym w2 = symSquareLane(w);
  out = {b * w.xx + d2 * w2.xx + logMu2, b * w.xy + d2 * w2.xy, b * w.xz + d2 * w2.xz,
         b * w.yy + d2 * w2.yy + logMu2, b * w.yz + d2 * w2.yz, b * w.zz + d2 * w2.zz + logMu2};
  return ok;
}

/// so3Exp (so3.h, Rodrigues); false for |omega|/2 > kSinCosMaxArg.
TETBLEND_LANE bool so3ExpLane(double x, double y, double z, Mat& r) {
  const double theta2 = x * x + y * y + z * z;
  const double theta = std::sqrt(theta2);
  const bool ok = 0.5 * theta <= lane_math::kSinCosMaxArg;
  double s, c;
  lane_math::sinCosLane(ok ? 0.5 * theta : 0.0, s, c);
  const bool small = theta2 < so3_detail::kSmallAngle * so3_detail::kSmallAngle;
  const double a = small ? 1.0 - theta2 / 6.0 : 2.0 * s * c / theta;
  const double b = small ? 0.5 - theta2 / 24.0 : 2.0 * s * s / theta2;
  const double bxy = b * x * y, bxz = b * x * z, byz = b * y * z;
  r = {{1.0 - b * (y * y + z * z), bxy - a * z, bxz + a * y, bxy + a * z, 1.0 - b * (x * x + z * z),
        byz - a * x, bxz - a * y, byz + a * x, 1.0 - b * (x * x + y * y)}};
  return ok;
}

/// so3Log (so3.h, Kaji–Ochiai eq. (7), Eberly eq. (11)); false for
/// non-finite input.
TETBLEND_LANE bool so3LogLane(const Mat& rm, double w[3]) {
  const double* r = rm.m;
  const double vx = 0.5 * (r[7] - r[5]), vy = 0.5 * (r[2] - r[6]), vz = 0.5 * (r[3] - r[1]);
  const double c = 0.5 * (r[0] + r[4] + r[8] - 1.0);
  const double s = std::sqrt(vx * vx + vy * vy + vz * vz);
  const bool ok = std::abs(c) <= 1e300 && s <= 1e300;
  const double theta = lane_math::atan2Lane(ok ? s : 0.0, ok ? c : 1.0);
  const double f = theta < so3_detail::kSmallAngle ? 1.0 + theta * theta / 6.0 : theta / s;
  // Symmetric-part axis: column k of (R + R^T)/2 - c I, k the largest diagonal.
  const int k = r[0] >= r[4] ? (r[0] >= r[8] ? 0 : 2) : (r[4] >= r[8] ? 1 : 2);
  const double s01 = 0.5 * (r[1] + r[3]), s02 = 0.5 * (r[2] + r[6]), s12 = 0.5 * (r[5] + r[7]);
  double ax = k == 0 ? r[0] - c : (k == 1 ? s01 : s02);
  double ay = k == 0 ? s01 : (k == 1 ? r[4] - c : s12);
  double az = k == 0 ? s02 : (k == 1 ? s12 : r[8] - c);
  const double norm = std::sqrt(ax * ax + ay * ay + az * az);
  const double sign = ax * vx + ay * vy + az * vz < 0.0 ? -1.0 : 1.0;
  const double g = theta * sign / norm;
  const bool skew = c >= so3_detail::kAxisFromSymmetricCos;
  w[0] = skew ? f * vx : g * ax;
  w[1] = skew ? f * vy : g * ay;
  w[2] = skew ? f * vz : g * az;
  return ok;
}

/// Cross product.
TETBLEND_LANE void crossLane(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

TETBLEND_LANE double dotLane(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The factors of polar_detail::svdClosedForm (polar.cpp) on a (row-major):
/// v[j] and u[j] the j-th columns of V and U, sigma[j] = |A v_j|, and the
/// polar rotation rot = U V^T. False where the scalar kernels must decide
/// (det outside [kUnscaledMinDet, kUnscaledMaxDet], including det <= 0 and
/// non-finite; cond > kClosedFormMaxCond; residual check failed).
TETBLEND_LANE bool polarSvdLane(const Mat& am, double v[3][3], double sigma[3], Mat& rot) {
  const double* a = am.m;
  const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                     a[2] * (a[3] * a[7] - a[4] * a[6]);
  // M = A^T A.
  const Sym m{a[0] * a[0] + a[3] * a[3] + a[6] * a[6], a[0] * a[1] + a[3] * a[4] + a[6] * a[7],
              a[0] * a[2] + a[3] * a[5] + a[6] * a[8], a[1] * a[1] + a[4] * a[4] + a[7] * a[7],
              a[1] * a[2] + a[4] * a[5] + a[7] * a[8], a[2] * a[2] + a[5] * a[5] + a[8] * a[8]};
  double mu1, mu2, mu3;
  eigenvaluesLane(m, mu1, mu2, mu3);
  constexpr double kMaxCond2 = polar_detail::kClosedFormMaxCond * polar_detail::kClosedFormMaxCond;
  const bool inRange = (det >= polar_detail::kUnscaledMinDet) &
                       (det <= polar_detail::kUnscaledMaxDet) & (mu3 > 0.0) &
                       (mu1 <= kMaxCond2 * mu3);
  // Most isolated eigenvector w by cross products of the rows of M - mu I.
  const bool top = mu1 - mu2 >= mu2 - mu3;
  const double muIso = top ? mu1 : mu3;
  const double r0[3] = {m.xx - muIso, m.xy, m.xz}, r1[3] = {m.xy, m.yy - muIso, m.yz},
               r2[3] = {m.xz, m.yz, m.zz - muIso};
  double c01[3], c02[3], c12[3];
  crossLane(r0, r1, c01);
  crossLane(r0, r2, c02);
  crossLane(r1, r2, c12);
  const double n01 = dotLane(c01, c01), n02 = dotLane(c02, c02), n12 = dotLane(c12, c12);
  const bool pick01 = n01 >= n02 && n01 >= n12, pick02 = !(n01 >= n02) && n02 >= n12;
  double best[3];
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) best[i] = pick01 ? c01[i] : (pick02 ? c02[i] : c12[i]);
  const double bestNorm = std::sqrt(dotLane(best, best));
  const bool distinct = mu1 > mu3;
  const double w[3] = {best[0] / bestNorm, best[1] / bestNorm, best[2] / bestNorm};
  const bool xFirst = std::abs(w[0]) > std::abs(w[1]);
  double p[3] = {xFirst ? -w[2] : 0.0, xFirst ? 0.0 : w[2], xFirst ? w[0] : -w[1]};
  const double pNorm = std::sqrt(dotLane(p, p));
#pragma GCC unroll 9
  for (double& x : p) x /= pNorm;
  double q[3];
  crossLane(w, p, q);
  const double mp[3] = {m.xx * p[0] + m.xy * p[1] + m.xz * p[2],
                        m.xy * p[0] + m.yy * p[1] + m.yz * p[2],
                        m.xz * p[0] + m.yz * p[1] + m.zz * p[2]};
  const double mq[3] = {m.xx * q[0] + m.xy * q[1] + m.xz * q[2],
                        m.xy * q[0] + m.yy * q[1] + m.yz * q[2],
                        m.xz * q[0] + m.yz * q[1] + m.zz * q[2]};
  const double b00 = dotLane(p, mp), b01 = dotLane(p, mq), b11 = dotLane(q, mq);
  // Jacobi rotation of the 2x2 problem (Golub & Van Loan, Alg. 8.4.1).
  const double tau = (b11 - b00) / (2.0 * b01);
  const double tJacobi = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
  const double t = b01 != 0.0 ? tJacobi : 0.0;
  const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
  const bool e0Larger = b00 - t * b01 >= b11 + t * b01;
  double middle[3], other[3];
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) {
    const double e0 = c * p[i] - s * q[i], e1 = s * p[i] + c * q[i];
    middle[i] = top ? (e0Larger ? e0 : e1) : (e0Larger ? e1 : e0);
  }
  // Third vector: w x middle if w is the top eigenvector, else middle x w.
  crossLane(w, middle, other);
#pragma GCC unroll 9
  for (double& x : other) x = top ? x : -x;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) {
    v[0][i] = distinct ? (top ? w[i] : other[i]) : (i == 0 ? 1.0 : 0.0);
    v[1][i] = distinct ? middle[i] : (i == 1 ? 1.0 : 0.0);
    v[2][i] = distinct ? (top ? other[i] : w[i]) : (i == 2 ? 1.0 : 0.0);
  }
  double av[3][3];
#pragma GCC unroll 9
  for (int j = 0; j < 3; ++j) {
#pragma GCC unroll 9
    for (int i = 0; i < 3; ++i)
      av[j][i] = a[3 * i] * v[j][0] + a[3 * i + 1] * v[j][1] + a[3 * i + 2] * v[j][2];
    sigma[j] = std::sqrt(dotLane(av[j], av[j]));
  }
  double u[3][3];
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) u[0][i] = av[0][i] / sigma[0];
  const double proj = dotLane(u[0], av[1]);
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) u[1][i] = av[1][i] - proj * u[0][i];
  const double u1Norm2 = dotLane(u[1], u[1]);
  const double u1Scale = u1Norm2 > 0.0 ? 1.0 / std::sqrt(u1Norm2) : 1.0;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) u[1][i] *= u1Scale;
  crossLane(u[0], u[1], u[2]);
  double residual2 = 0.0, norm2 = 0.0;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) {
#pragma GCC unroll 9
    for (int j = 0; j < 3; ++j) {
      const double usv = u[0][i] * sigma[0] * v[0][j] + u[1][i] * sigma[1] * v[1][j] +
                         u[2][i] * sigma[2] * v[2][j];
      const double d = a[3 * i + j] - usv;
      residual2 += d * d;
      norm2 += a[3 * i + j] * a[3 * i + j];
      rot.m[3 * i + j] = u[0][i] * v[0][j] + u[1][i] * v[1][j] + u[2][i] * v[2][j];
    }
  }
  constexpr double kTol = polar_detail::kClosedFormMaxResidual;
  return inRange & ((bestNorm > 0.0) | (mu1 <= mu3)) & (residual2 <= kTol * kTol * norm2) &
         (sigma[2] >= kMinNormal);
}

/// polar_detail::polarLogClosedForm (polar.cpp) on a (row-major): the
/// rotation factor and log S. False where the scalar psi must decide (as
/// polarSvdLane).
TETBLEND_LANE bool polarLogLane(const Mat& am, Mat& rot, Sym& logS) {
  double v[3][3], sigma[3];
  const bool ok = polarSvdLane(am, v, sigma, rot);
  double logSigma[3];
#pragma GCC unroll 9
  for (int j = 0; j < 3; ++j) logSigma[j] = lane_math::logLane(ok ? sigma[j] : 1.0);
  const auto entry = [&](int i, int k) {
    return logSigma[0] * v[0][i] * v[0][k] + logSigma[1] * v[1][i] * v[1][k] +
           logSigma[2] * v[2][i] * v[2][k];
  };
  logS = {entry(0, 0), entry(0, 1), entry(0, 2), entry(1, 1), entry(1, 2), entry(2, 2)};
  return ok;
}

}  // namespace tetblend::batch_detail
