#pragma once
// Private to core/src: exact rescaling by powers of two, used to bring inputs
// of any magnitude the double range holds into the range where the closed
// forms neither overflow nor underflow (the logs then get k ln 2 added back).

#include <Eigen/Core>

#include <cmath>

namespace tetblend::core_detail {

/// ln 2 to double precision.
constexpr double kLn2 = 0.69314718055994530942;

/// 2^k m entry by entry (std::ldexp: exact unless an entry leaves the normal
/// range, then correctly rounded).
inline Eigen::Matrix3d timesPowerOfTwo(const Eigen::Matrix3d& m, int k) {
  return m.unaryExpr([k](double x) { return std::ldexp(x, k); });
}

/// floor(a / 3) for any int a (C++ division truncates towards zero).
constexpr int floorDivide3(int a) { return a >= 0 ? a / 3 : -((-a + 2) / 3); }

}  // namespace tetblend::core_detail
