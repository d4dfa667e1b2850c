#pragma once
// Branch-free scalar elementary functions for the batched kernels
// (batch_kernels.h): exp, expm1, log, log1p, atan2 and sin/cos written with
// selects instead of branches and bit manipulation instead of ldexp/frexp, so
// that GCC vectorises a loop that inlines them (glibc's exp/log are opaque
// calls). Range reduction + Taylor polynomials truncated where the dropped
// term is below 1e-17 relative; measured accuracy is stated per function and
// tested against the C library (lane_math_test.cpp). Each function states the
// argument range it is valid on: the batched kernels flag lanes outside it and
// recompute them with the scalar kernel.

#include <cstdint>
#include <cstring>

/// The lane functions are forced inline: the batched kernels' loops
/// vectorise only when every call in them is inlined, and with -march=native
/// GCC chose to call them instead (4-5 times slower; issue 14).
#if defined(__GNUC__)
#define TETBLEND_LANE_INLINE inline __attribute__((always_inline))
#else
#define TETBLEND_LANE_INLINE inline
#endif

namespace tetblend::lane_math {

/// Largest |x| for expLane/expm1Lane (and the largest k of 2^k they build):
/// well inside the normal range of 2^k, k in [-1010, 1010].
constexpr double kExpMaxArg = 700.0;
/// Largest x for sinCosLane: k pi/2 with k < 2^17 keeps the three-part
/// Cody–Waite reduction exact (pi/2 split into 33-bit pieces).
constexpr double kSinCosMaxArg = 1e5;

constexpr double kLn2Hi = 6.93147180369123816490e-01;  // fdlibm: 32 bits, k*kLn2Hi exact
constexpr double kLn2Lo = 1.90821492927058770002e-10;
constexpr double kInvLn2 = 1.44269504088896338700e+00;
constexpr double kRoundShift = 6755399441055744.0;  // 1.5 * 2^52: adding rounds to an integer

TETBLEND_LANE_INLINE std::uint64_t bitsOf(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

TETBLEND_LANE_INLINE double fromBits(std::uint64_t u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

/// expm1(r) for |r| <= ln2/2 by its Taylor series through r^15 (dropped term
/// < 0.35^15/16! ~ 7e-21 relative to r).
TETBLEND_LANE_INLINE double expm1Reduced(double r) {
  double p = 1.0 / 1307674368000.0;  // 1/15!
  p = p * r + 1.0 / 87178291200.0;
  p = p * r + 1.0 / 6227020800.0;
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  return r + (r * r) * p;
}

/// exp(x) and expm1(x) for |x| <= kExpMaxArg from one reduction x = k ln2 + r:
/// exp = 2^k (1 + expm1(r)), expm1 = (2^k - 1) + 2^k expm1(r) (exact
/// expm1(r) for k = 0, no cancellation otherwise since |x| > ln2/2).
/// Both within 2 ulp of the correctly rounded value (tested).
TETBLEND_LANE_INLINE void expExpm1Lane(double x, double& e, double& em1) {
  const double shifted = x * kInvLn2 + kRoundShift;
  const double k = shifted - kRoundShift;
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  // The low bits of `shifted` hold k in two's complement.
  const auto ki = static_cast<std::int64_t>(bitsOf(shifted) - bitsOf(kRoundShift));
  const double scale = fromBits(static_cast<std::uint64_t>(ki + 1023) << 52);
  const double p = expm1Reduced(r);
  e = scale + scale * p;
  em1 = (scale - 1.0) + scale * p;
}

/// exp(x) for |x| <= kExpMaxArg, within 2 ulp.
TETBLEND_LANE_INLINE double expLane(double x) {
  double e, em1;
  expExpm1Lane(x, e, em1);
  return e;
}

/// expm1(x) for |x| <= kExpMaxArg, within 2 ulp.
TETBLEND_LANE_INLINE double expm1Lane(double x) {
  double e, em1;
  expExpm1Lane(x, e, em1);
  return em1;
}

/// log(x) for positive normal finite x (fdlibm's reduction: x = 2^e m, m in
/// [sqrt(1/2), sqrt 2), log m = f - s (f - R), s = f/(2 + f), R the atanh
/// series 2 s^2/3 + 2 s^4/5 + ... through s^22 (dropped < 1e-18)). Within 2 ulp.
TETBLEND_LANE_INLINE double logLane(double x) {
  const std::uint64_t u = bitsOf(x);
  const std::uint64_t mantissa = (u & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double m = fromBits(mantissa);  // [1, 2)
  // Biased exponent as a double: 2^52 + E read back and shifted (no int->double
  // conversion, which AVX2 lacks for 64-bit integers).
  double e = fromBits((u >> 52) | 0x4330000000000000ULL) - 4503599627370496.0 - 1023.0;
  const bool high = m > 1.4142135623730951;
  m = high ? 0.5 * m : m;
  e = high ? e + 1.0 : e;
  const double f = m - 1.0;  // exact (Sterbenz)
  const double s = f / (2.0 + f);
  const double z = s * s;
  double r = 2.0 / 23.0;
  r = r * z + 2.0 / 21.0;
  r = r * z + 2.0 / 19.0;
  r = r * z + 2.0 / 17.0;
  r = r * z + 2.0 / 15.0;
  r = r * z + 2.0 / 13.0;
  r = r * z + 2.0 / 11.0;
  r = r * z + 2.0 / 9.0;
  r = r * z + 2.0 / 7.0;
  r = r * z + 2.0 / 5.0;
  r = r * z + 2.0 / 3.0;
  r *= z;
  return e * kLn2Hi + ((e * kLn2Lo) + (f - s * (f - r)));
}

/// log1p(x) for x > -1 with 1 + x normal (Goldberg's correction: log(u) -
/// ((u - 1) - x)/u, u = fl(1 + x)). Within 3 ulp.
TETBLEND_LANE_INLINE double log1pLane(double x) {
  const double u = 1.0 + x;
  const double correction = u == 1.0 ? x : ((u - 1.0) - x) / u;
  return u == 1.0 ? x : logLane(u) - correction;
}

/// atan2(y, x) for finite y, x (0 for y = x = 0). Reduction to |t| <=
/// tan(pi/8) and the atan series through t^43 (dropped < 2e-18). Within 3 ulp:
/// the rounding of min/max(|x|, |y|) alone moves the result by up to one ulp
/// where atan(a) < 1/2 <= a.
TETBLEND_LANE_INLINE double atan2Lane(double y, double x) {
  constexpr double kPiO4 = 7.85398163397448278999e-01;
  constexpr double kPiO2 = 1.57079632679489655800e+00;
  constexpr double kPi = 3.14159265358979311600e+00;
  constexpr double kTanPiO8 = 0.41421356237309503;
  const double ax = x < 0.0 ? -x : x, ay = y < 0.0 ? -y : y;
  const bool swap = ay > ax;
  const double num = swap ? ax : ay, den = swap ? ay : ax;
  const double a = den == 0.0 ? 0.0 : num / den;  // [0, 1]
  const bool big = a > kTanPiO8;
  const double t = big ? (a - 1.0) / (a + 1.0) : a;
  const double z = t * t;
  double p = -1.0 / 43.0;
  p = p * z + 1.0 / 41.0;
  p = p * z - 1.0 / 39.0;
  p = p * z + 1.0 / 37.0;
  p = p * z - 1.0 / 35.0;
  p = p * z + 1.0 / 33.0;
  p = p * z - 1.0 / 31.0;
  p = p * z + 1.0 / 29.0;
  p = p * z - 1.0 / 27.0;
  p = p * z + 1.0 / 25.0;
  p = p * z - 1.0 / 23.0;
  p = p * z + 1.0 / 21.0;
  p = p * z - 1.0 / 19.0;
  p = p * z + 1.0 / 17.0;
  p = p * z - 1.0 / 15.0;
  p = p * z + 1.0 / 13.0;
  p = p * z - 1.0 / 11.0;
  p = p * z + 1.0 / 9.0;
  p = p * z - 1.0 / 7.0;
  p = p * z + 1.0 / 5.0;
  p = p * z - 1.0 / 3.0;
  const double at = t + t * (z * p);
  double r = big ? kPiO4 + at : at;
  r = swap ? kPiO2 - r : r;
  r = x < 0.0 ? kPi - r : r;
  return y < 0.0 ? -r : r;
}

/// sin(x) and cos(x) for |x| <= kSinCosMaxArg: x = k pi/2 + r by three-part
/// Cody–Waite reduction (fdlibm's pio2_1, pio2_2, pio2_3), |r| <= pi/4, Taylor
/// series through r^19 (sin) and r^20 (cos), quadrant by k mod 4. Within
/// 2 ulp of the C library.
TETBLEND_LANE_INLINE void sinCosLane(double x, double& sine, double& cosine) {
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kPio2_1 = 1.57079632673412561417e+00;
  constexpr double kPio2_2 = 6.07710050630396597660e-11;
  constexpr double kPio2_3 = 2.02226624871116645580e-21;
  const double shifted = x * kTwoOverPi + kRoundShift;
  const double k = shifted - kRoundShift;
  const double r = ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
  const std::uint64_t quadrant = (bitsOf(shifted) - bitsOf(kRoundShift)) & 3u;
  const double z = r * r;
  double ps = -1.0 / 121645100408832000.0;  // -1/19!
  ps = ps * z + 1.0 / 355687428096000.0;
  ps = ps * z - 1.0 / 1307674368000.0;
  ps = ps * z + 1.0 / 6227020800.0;
  ps = ps * z - 1.0 / 39916800.0;
  ps = ps * z + 1.0 / 362880.0;
  ps = ps * z - 1.0 / 5040.0;
  ps = ps * z + 1.0 / 120.0;
  ps = ps * z - 1.0 / 6.0;
  const double s = r + r * (z * ps);
  double pc = 1.0 / 2432902008176640000.0;  // 1/20!
  pc = pc * z - 1.0 / 6402373705728000.0;
  pc = pc * z + 1.0 / 20922789888000.0;
  pc = pc * z - 1.0 / 87178291200.0;
  pc = pc * z + 1.0 / 479001600.0;
  pc = pc * z - 1.0 / 3628800.0;
  pc = pc * z + 1.0 / 40320.0;
  pc = pc * z - 1.0 / 720.0;
  pc = pc * z + 1.0 / 24.0;
  const double c = 1.0 - 0.5 * z + (z * z) * pc;
  const bool odd = (quadrant & 1u) != 0;
  const double sv = odd ? c : s, cv = odd ? s : c;
  sine = (quadrant & 2u) != 0 ? -sv : sv;
  cosine = (quadrant == 1u || quadrant == 2u) ? -cv : cv;
}

/// x^(-2/3) for positive normal finite x (the untangling energy's χ^(-2/3),
/// meshing/src/untangle.h): a first guess of x^(-1/3) from the bits (the
/// exponent divided by -3, a few per cent off), four Newton steps
/// y <- y (4 - x y^3) / 3 (the error squares each step, to below rounding),
/// squared. Within 8 ulp (measured 6.5; 1 / cbrt(x)^2 is within 11).
TETBLEND_LANE_INLINE double inverseCbrtSquaredLane(double x) {
  double y = fromBits(0x553ef0ff289dd796ULL - bitsOf(x) / 3u);
  for (int step = 0; step < 4; ++step) y = y * (4.0 - x * y * y * y) * (1.0 / 3.0);
  return y * y;
}

}  // namespace tetblend::lane_math
