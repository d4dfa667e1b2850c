#include "tetblend/core/polar.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

/// Relative Newton step |X_{k+1} - X_k|_F / |X_{k+1}|_F below which the
/// iteration stops: convergence is quadratic, so the iterate just computed is
/// accurate to about step^2 / 2 < eps once step < sqrt(eps) ~ 1.5e-8.
const double kNewtonStopStep = std::sqrt(2.220446049250313e-16);
/// Relative step below which the Frobenius scaling is switched off (Higham,
/// Functions of Matrices, §8.6: scaling only helps far from convergence).
constexpr double kNewtonUnscaledStep = 1e-2;
/// Iteration cap. With Frobenius scaling, cond(A) = 1e16 needs about 10.
constexpr int kNewtonMaxIterations = 30;

/// Cofactor matrix of x, det(x) x^{-T}: its columns c_i satisfy c_i . x_j =
/// det(x) delta_ij, i.e. c^T x = det(x) I.
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& x) {
  Eigen::Matrix3d c;
  c.col(0) = x.col(1).cross(x.col(2));
  c.col(1) = x.col(2).cross(x.col(0));
  c.col(2) = x.col(0).cross(x.col(1));
  return c;
}

}  // namespace

PolarDecomposition polarDecompose(const Eigen::Matrix3d& a) {
  const double detA = a.determinant();
  if (!a.allFinite() || !(detA > 0.0)) {
    std::ostringstream msg;
    msg << "polarDecompose: det A = " << detA
        << " is not positive (or A is not finite); Aff+(3) needs det > 0 - the map"
           " flattens or mirrors the element";
    throw DomainError(msg.str());
  }
  Eigen::Matrix3d x = a;
  bool scaled = true;
  for (int iteration = 0; iteration < kNewtonMaxIterations; ++iteration) {
    const Eigen::Matrix3d cof = cofactor(x);
    const double det = x.col(0).dot(cof.col(0));
    if (!(det > 0.0)) break;
    double g = 1.0;
    if (scaled) g = std::sqrt(cof.norm() / (det * x.norm()));
    const Eigen::Matrix3d next = 0.5 * (g * x + cof / (g * det));
    const double step = (next - x).norm() / next.norm();
    x = next;
    if (step < kNewtonStopStep) {
      PolarDecomposition result;
      result.rotation = x;
      const Eigen::Matrix3d s = x.transpose() * a;
      result.stretch = 0.5 * (s + s.transpose());
      return result;
    }
    if (step < kNewtonUnscaledStep) scaled = false;
  }
  std::ostringstream msg;
  msg << "polarDecompose: Newton iteration did not converge for a matrix with det " << detA;
  throw NumericalError(msg.str());
}

PolarLogDecomposition polarDecomposeLog(const Eigen::Matrix3d& a) {
  const PolarDecomposition polar = polarDecompose(a);
  return {polar.rotation, symLog(polar.stretch)};
}

}  // namespace tetblend
