#include "tetblend/core/polar.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>
#include <sstream>

#include "power_of_two.h"
#include "tetblend/core/cofactor.h"
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
/// Norm above which a Newton iterate is divided by a power of two before its
/// cofactor (entries up to |X|^2) is formed: the scaled iteration is
/// invariant under X -> t X, and the first iterate reaches ~sqrt(cond(A))
/// from a start normalised to det ~ 1, beyond this only for cond(A) > ~1e300.
constexpr double kNewtonRescaleNorm = 0x1p+500;
/// Iteration cap. With Frobenius scaling, cond(A) = 1e16 needs about 10.
constexpr int kNewtonMaxIterations = 30;

/// Frobenius norm; for matrices whose squared norm overflows (after
/// normalisation only at cond(A) beyond ~1e100) the scaled stableNorm.
double frobeniusNorm(const Eigen::Matrix3d& m) {
  const double n = m.norm();
  return std::isinf(n) ? m.stableNorm() : n;
}

[[noreturn]] void throwNotPositive(const char* function, double det) {
  std::ostringstream msg;
  msg << function << ": det A = " << det
      << " is not positive (or A is not finite); Aff+(3) needs det > 0 - the map"
         " flattens or mirrors the element";
  throw DomainError(msg.str());
}

/// k such that det(2^-k A) lies in [1, 8): first the largest entry is scaled
/// into [1, 2) (so the determinant neither overflows nor underflows for any
/// cond below ~1e300), then its determinant's exponent is divided by three.
/// Throws DomainError if A is not finite or det A <= 0.
int normalisingExponent(const Eigen::Matrix3d& a, const char* function) {
  if (!a.allFinite()) throwNotPositive(function, a.determinant());
  const double largest = a.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) throwNotPositive(function, 0.0);
  const int e1 = std::ilogb(largest);
  const double det1 = core_detail::timesPowerOfTwo(a, -e1).determinant();
  if (!(det1 > 0.0)) throwNotPositive(function, std::ldexp(det1, 3 * e1));
  return e1 + core_detail::floorDivide3(std::ilogb(det1));
}

// A = R S with R = polar_detail::svdRotation(A) and S = sym(R^T A). Slower
// than the Newton iteration and without its forward accuracy, but defined
// for every A with det A > 0: the fallback where the iteration meets a
// non-positive det or does not settle (a blended gradient with det 5 made of
// round-off beside a 1e14 column).
PolarDecomposition polarBySvd(const Eigen::Matrix3d& a) {
  PolarDecomposition result;
  result.rotation = polar_detail::svdRotation(a);
  const Eigen::Matrix3d s = result.rotation.transpose() * a;
  result.stretch = 0.5 * (s + s.transpose());
  return result;
}

bool unscaledDet(double det) {
  return det >= polar_detail::kUnscaledMinDet && det <= polar_detail::kUnscaledMaxDet;
}

}  // namespace

PolarDecomposition polarDecompose(const Eigen::Matrix3d& a) {
  const double detA = a.determinant();
  if (!unscaledDet(detA)) {
    const int k = normalisingExponent(a, "polarDecompose");
    PolarDecomposition result = polarDecompose(core_detail::timesPowerOfTwo(a, -k));
    result.stretch = core_detail::timesPowerOfTwo(result.stretch, k);
    return result;
  }
  Eigen::Matrix3d x = a;
  bool scaled = true;
  double xNorm = frobeniusNorm(x);
  for (int iteration = 0; iteration < kNewtonMaxIterations; ++iteration) {
    if (xNorm > kNewtonRescaleNorm) {
      const int k = std::ilogb(xNorm);
      x = core_detail::timesPowerOfTwo(x, -k);
      xNorm = std::ldexp(xNorm, -k);
    }
    const Eigen::Matrix3d cof = cofactor(x);
    const double det = x.col(0).dot(cof.col(0));
    if (!(det > 0.0)) break;
    double g = 1.0;
    if (scaled) g = std::sqrt(frobeniusNorm(cof) / (det * xNorm));
    const Eigen::Matrix3d next = 0.5 * (g * x + cof / (g * det));
    const double nextNorm = frobeniusNorm(next);
    const double step = frobeniusNorm(next - x) / nextNorm;
    x = next;
    xNorm = nextNorm;
    if (step < kNewtonStopStep) {
      PolarDecomposition result;
      result.rotation = x;
      const Eigen::Matrix3d s = x.transpose() * a;
      result.stretch = 0.5 * (s + s.transpose());
      return result;
    }
    if (step < kNewtonUnscaledStep) scaled = false;
  }
  return polarBySvd(a);
}

namespace polar_detail {

Eigen::Matrix3d svdRotation(const Eigen::Matrix3d& a) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0) u.col(2) = -u.col(2);
  return u * svd.matrixV().transpose();
}

bool svdClosedForm(const Eigen::Matrix3d& a, Eigen::Matrix3d& u, Eigen::Vector3d& sigma,
                   Eigen::Matrix3d& v) {
  const Eigen::Matrix3d m = a.transpose() * a;
  const Eigen::Vector3d mu = symEigenvalues(m);
  if (!(mu(2) > 0.0) || !(mu(0) <= kClosedFormMaxCond * kClosedFormMaxCond * mu(2))) return false;
  v.setIdentity();
  // Eigenvalues equal to within the residual bound (A a multiple of a
  // rotation, up to rounding): any orthonormal V fits, and the shifted
  // matrix below is rounding noise that can cancel to zero, so V stays I.
  if (mu(0) - mu(2) > kClosedFormMaxResidual * mu(0)) {
    // The eigenvalue farther from the middle one is separated from the other
    // two by at least half the spread: its eigenvector is well determined.
    const int iso = mu(0) - mu(1) >= mu(1) - mu(2) ? 0 : 2;
    Eigen::Matrix3d shifted = m;
    shifted.diagonal().array() -= mu(iso);
    const Eigen::Vector3d r0 = shifted.row(0), r1 = shifted.row(1), r2 = shifted.row(2);
    const Eigen::Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
    const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
    const Eigen::Vector3d& best = n01 >= n02 ? (n01 >= n12 ? c01 : c12) : (n02 >= n12 ? c02 : c12);
    const double bestNorm = std::sqrt(best.squaredNorm());
    if (!(bestNorm > 0.0)) return false;
    const Eigen::Vector3d w = best / bestNorm;
    // Orthonormal basis (p, q) of the complement of w, then the middle
    // eigenvector from the 2x2 problem B = [p q]^T M [p q].
    Eigen::Vector3d p = std::abs(w.x()) > std::abs(w.y()) ? Eigen::Vector3d(-w.z(), 0.0, w.x())
                                                          : Eigen::Vector3d(0.0, w.z(), -w.y());
    p.normalize();
    const Eigen::Vector3d q = w.cross(p);
    const Eigen::Vector3d mp = m * p, mq = m * q;
    const double b00 = p.dot(mp), b01 = p.dot(mq), b11 = q.dot(mq);
    // Jacobi rotation diagonalising B (Golub & Van Loan, Alg. 8.4.1): its
    // eigenvectors (c, -s), (s, c) are exact to ulps whatever the gap, while
    // the cubic's split of a near-double eigenvalue is only sqrt(eps) accurate.
    double t = 0.0;
    if (b01 != 0.0) {
      const double tau = (b11 - b00) / (2.0 * b01);
      t = (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
    }
    const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
    const Eigen::Vector3d e0 = c * p - s * q, e1 = s * p + c * q;
    const bool e0Larger = b00 - t * b01 >= b11 + t * b01;
    // Middle eigenvector: the larger of the pair if w is the top one, else the smaller.
    const Eigen::Vector3d& middle = (iso == 0) == e0Larger ? e0 : e1;
    v.col(1) = middle;
    if (iso == 0) {
      v.col(0) = w;
      v.col(2) = w.cross(middle);
    } else {
      v.col(2) = w;
      v.col(0) = middle.cross(w);
    }
  }
  const Eigen::Matrix3d av = a * v;
  sigma = Eigen::Vector3d(av.col(0).norm(), av.col(1).norm(), av.col(2).norm());
  u.col(0) = av.col(0) / sigma(0);
  const Eigen::Vector3d u1 = av.col(1) - u.col(0).dot(av.col(1)) * u.col(0);
  u.col(1) = u1.normalized();
  u.col(2) = u.col(0).cross(u.col(1));
  const Eigen::Matrix3d residual = a - u * sigma.asDiagonal() * v.transpose();
  return residual.squaredNorm() <=
         kClosedFormMaxResidual * kClosedFormMaxResidual * a.squaredNorm();
}

namespace {

// One first-order correction of an approximate polar factor R0 of A (with
// A = U diag(sigma) V^T, R0 = U V^T): the exact R = R0 (I + [w]x) makes
// S = R^T A symmetric, i.e. H - H^T = [w]x S + S [w]x = [(tr S I - S) w]x for
// H = R0^T A, solved in S's eigenbasis V, where (tr S I - S) is diagonal
// with entries sigma_j + sigma_k > 0. The closed form's R0 carries up to
// 32 eps * cond(A) of error (its accepted residual times the polar factor's
// condition); after the step, eps * cond(A) to first order. |w| stays at
// that size, so I + [w]x is orthonormal to |w|^2, far below round-off.
Eigen::Matrix3d refinedRotation(const Eigen::Matrix3d& r0, const Eigen::Matrix3d& a,
                                const Eigen::Vector3d& sigma, const Eigen::Matrix3d& v) {
  const Eigen::Matrix3d h = r0.transpose() * a;
  const Eigen::Vector3d skew(h(2, 1) - h(1, 2), h(0, 2) - h(2, 0), h(1, 0) - h(0, 1));
  const Eigen::Vector3d skewInV = v.transpose() * skew;
  const double trace = sigma.sum();
  const Eigen::Vector3d w =
      v * Eigen::Vector3d(skewInV(0) / (trace - sigma(0)), skewInV(1) / (trace - sigma(1)),
                          skewInV(2) / (trace - sigma(2)));
  Eigen::Matrix3d cross;
  cross << 0.0, -w(2), w(1), w(2), 0.0, -w(0), -w(1), w(0), 0.0;
  return r0 + r0 * cross;
}

}  // namespace

bool polarLogClosedForm(const Eigen::Matrix3d& a, PolarLogDecomposition& out) {
  Eigen::Matrix3d u, v;
  Eigen::Vector3d sigma;
  if (!svdClosedForm(a, u, sigma, v)) return false;
  out.rotation = refinedRotation(u * v.transpose(), a, sigma, v);
  const Eigen::Matrix3d logS = v * sigma.array().log().matrix().asDiagonal() * v.transpose();
  out.stretchLog = 0.5 * (logS + logS.transpose());
  return true;
}

}  // namespace polar_detail

PolarLogDecomposition polarDecomposeLog(const Eigen::Matrix3d& a) {
  if (!unscaledDet(a.determinant())) {
    const int k = normalisingExponent(a, "polarDecomposeLog");
    PolarLogDecomposition result = polarDecomposeLog(core_detail::timesPowerOfTwo(a, -k));
    result.stretchLog.diagonal().array() += k * core_detail::kLn2;
    return result;
  }
  PolarLogDecomposition fast;
  if (polar_detail::polarLogClosedForm(a, fast)) return fast;
  const PolarDecomposition polar = polarDecompose(a);
  return {polar.rotation, symLog(polar.stretch)};
}

}  // namespace tetblend
