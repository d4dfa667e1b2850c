#include "tetblend/core/shear_group.h"

#include <algorithm>
#include <sstream>

#include "tetblend/core/error.h"

namespace tetblend {

namespace {

// Number of series terms (degrees 0..kSeriesDegree) of f[x, y, z]; see
// kShearSeriesSpread for the truncation bound.
constexpr int kSeriesDegree = 10;

}  // namespace

double expDividedDifference(double x, double y) {
  const double lo = std::min(x, y);
  const double h = std::abs(x - y);
  if (h == 0.0) return std::exp(lo);
  return std::exp(lo) * (std::expm1(h) / h);
}

double expDividedDifference(double x, double y, double z) {
  double n[3] = {x, y, z};
  std::sort(n, n + 3);
  const double spread = n[2] - n[0];
  if (spread >= kShearSeriesSpread) {
    return (expDividedDifference(n[1], n[2]) - expDividedDifference(n[0], n[1])) / spread;
  }
  // f[x, y, z] = e^m sum_j h_j(d) / (j + 2)!, d = nodes - m, m their mean, h_j
  // the complete homogeneous symmetric polynomial of degree j. With e1 = 0,
  // Newton's identity gives h_j = -e2 h_{j-2} + e3 h_{j-3}.
  const double m = (n[0] + n[1] + n[2]) / 3.0;
  const double d0 = n[0] - m, d1 = n[1] - m, d2 = n[2] - m;
  const double e2 = d0 * d1 + d0 * d2 + d1 * d2;
  const double e3 = d0 * d1 * d2;
  double h[kSeriesDegree + 1];
  h[0] = 1.0;
  h[1] = 0.0;
  h[2] = -e2;
  for (int j = 3; j <= kSeriesDegree; ++j) h[j] = -e2 * h[j - 2] + e3 * h[j - 3];
  double sum = 0.0;
  double factorial = 1.0;  // (j + 2)! for j = kSeriesDegree, built up first
  for (int k = 2; k <= kSeriesDegree + 2; ++k) factorial *= k;
  for (int j = kSeriesDegree; j >= 0; --j) {  // smallest terms first
    sum += h[j] / factorial;
    factorial /= (j + 2);
  }
  return std::exp(m) * sum;
}

Eigen::Matrix3d shearExp(const Eigen::Matrix3d& x) {
  const double b1 = x(0, 1), b2 = x(1, 1), b3 = x(0, 2), b4 = x(1, 2), b5 = x(2, 2);
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  a(0, 0) = 1.0;
  a(1, 1) = std::exp(b2);
  a(2, 2) = std::exp(b5);
  a(0, 1) = b1 * expDividedDifference(0.0, b2);
  a(1, 2) = b4 * expDividedDifference(b2, b5);
  a(0, 2) = b3 * expDividedDifference(0.0, b5) + b1 * b4 * expDividedDifference(0.0, b2, b5);
  return a;
}

Eigen::Matrix3d shearLog(const Eigen::Matrix3d& a) {
  const double a1 = a(0, 1), a2 = a(1, 1), a3 = a(0, 2), a4 = a(1, 2), a5 = a(2, 2);
  if (!(a2 > 0.0) || !(a5 > 0.0) || !std::isfinite(a1) || !std::isfinite(a2) ||
      !std::isfinite(a3) || !std::isfinite(a4) || !std::isfinite(a5)) {
    std::ostringstream msg;
    msg << "shearLog: not an element of the shear group G_A (needs finite entries and "
           "diagonal entries A(1,1) > 0, A(2,2) > 0); got A(1,1) = "
        << a2 << ", A(2,2) = " << a5 << ". Pass a positively oriented, non-degenerate shear.";
    throw DomainError(msg.str());
  }
  const double l2 = std::log(a2), l5 = std::log(a5);
  Eigen::Matrix3d x = Eigen::Matrix3d::Zero();
  x(1, 1) = l2;
  x(2, 2) = l5;
  x(0, 1) = a1 / expDividedDifference(0.0, l2);
  x(1, 2) = a4 / expDividedDifference(l2, l5);
  x(0, 2) =
      (a3 - x(0, 1) * x(1, 2) * expDividedDifference(0.0, l2, l5)) / expDividedDifference(0.0, l5);
  return x;
}

Eigen::Matrix3d shearInverse(const Eigen::Matrix3d& a) {
  const double a1 = a(0, 1), a2 = a(1, 1), a3 = a(0, 2), a4 = a(1, 2), a5 = a(2, 2);
  Eigen::Matrix3d inv = Eigen::Matrix3d::Zero();
  inv(0, 0) = 1.0;
  inv(1, 1) = 1.0 / a2;
  inv(2, 2) = 1.0 / a5;
  inv(0, 1) = -a1 / a2;
  inv(1, 2) = -a4 / (a2 * a5);
  inv(0, 2) = (a1 * a4 - a2 * a3) / (a2 * a5);
  return inv;
}

}  // namespace tetblend
