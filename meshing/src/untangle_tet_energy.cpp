#include "untangle_tet_energy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "tetblend/core/cofactor.h"
#include "tetblend/core/lane_math.h"

namespace tetblend {
namespace {

// Below this ratio σ_1² / σ_0² rotationVariantSvd takes Jacobi's eigenvalue
// iteration instead of the closed form (whose σ_1² then has lost most of its
// digits), and a residual F v_1 below this fraction of F v_0 is taken as 0.
constexpr double kRank1Ratio = 1e-12;

// χ(J, ε) and its first two derivatives in J, with r = sqrt(ε² + J²):
// χ' = χ / r, χ'' = ε² / (2 r³).
struct Chi {
  double value;
  double first;
  double second;
};

Chi chi(double j, double epsilon) {
  const double root = std::sqrt(epsilon * epsilon + j * j);
  // χ = (J + r) / 2, written for J <= 0 as ε² / (2 (r − J)): the sum cancels
  // catastrophically there (to 0 once ε² < ulp(J²)).
  const double value = j > 0.0 ? 0.5 * (j + root) : 0.5 * epsilon * epsilon / (root - j);
  return {value, value / root, 0.5 * epsilon * epsilon / (root * root * root)};
}

// f = ψ(s, J) with s = ‖F‖² and its partial derivatives (ψ_ss = 0); the
// second ones only when asked (the Hessian needs them, the energy does not).
struct Psi {
  double value;
  double s;   // ∂ψ/∂s
  double j;   // ∂ψ/∂J
  double sj;  // ∂²ψ/∂s∂J
  double jj;  // ∂²ψ/∂J²
};

Psi psi(double s, double j, double epsilon, bool second) {
  constexpr double a = 1.0 - kUntangleVolumeWeight;
  constexpr double b = kUntangleVolumeWeight;
  const Chi c = chi(j, epsilon);
  const double x = c.value;
  const double power = x >= std::numeric_limits<double>::min()  // χ^{-2/3}
                           ? lane_math::inverseCbrtSquaredLane(x)
                           : std::pow(x, -2.0 / 3.0);
  Psi result{};
  result.value = a * s * power + b * (j * j + 1.0) / x;
  result.s = a * power;
  result.j = a * s * (-2.0 / 3.0) * power / x * c.first +
             b * (2.0 * j / x - (j * j + 1.0) * c.first / (x * x));
  if (second) {
    result.sj = a * (-2.0 / 3.0) * power / x * c.first;
    result.jj =
        a * s * power / x * ((10.0 / 9.0) * c.first * c.first / x - (2.0 / 3.0) * c.second) +
        b * (2.0 / x - 4.0 * j * c.first / (x * x) - (j * j + 1.0) * c.second / (x * x) +
             2.0 * (j * j + 1.0) * c.first * c.first / (x * x * x));
  }
  return result;
}

// F = U diag(σ) Vᵀ with U, V rotations and σ_0 >= σ_1 >= |σ_2|, σ_2 of the
// sign of det F: V from the eigenvectors of FᵀF (closed form, or Jacobi's
// iteration when F is close to rank 1, where the closed form's small
// eigenvalues lose their digits), U by Gram-Schmidt of F V completed to a
// rotation. A Newton model only needs it to rounding accuracy: the line
// search measures the true energy.
void rotationVariantSvd(const Eigen::Matrix3d& f, Eigen::Matrix3d& u, Eigen::Vector3d& sigma,
                        Eigen::Matrix3d& v) {
  const Eigen::Matrix3d gram = f.transpose() * f;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(gram);
  if (!(eigen.eigenvalues()(1) > kRank1Ratio * eigen.eigenvalues()(2))) eigen.compute(gram);
  v.col(0) = eigen.eigenvectors().col(2);  // eigenvalues ascending
  v.col(1) = eigen.eigenvectors().col(1);
  v.col(2) = v.col(0).cross(v.col(1)).normalized();
  const Eigen::Vector3d image0 = f * v.col(0);
  u.col(0) = image0.norm() > 0.0 ? image0.normalized() : Eigen::Vector3d::UnitX();
  Eigen::Vector3d image1 = f * v.col(1);
  image1 -= u.col(0).dot(image1) * u.col(0);
  u.col(1) = image1.norm() > kRank1Ratio * image0.norm() ? image1.normalized()
                                                          : u.col(0).unitOrthogonal();
  u.col(2) = u.col(0).cross(u.col(1));
  for (int i = 0; i < 3; ++i) sigma(i) = u.col(i).dot(f * v.col(i));
}

}  // namespace

double untangleTetEnergy(const Eigen::Matrix3d& f, double epsilon, Eigen::Matrix3d* dEdF) {
  const Psi p = psi(f.squaredNorm(), f.determinant(), epsilon, /*second=*/false);
  if (dEdF != nullptr) *dEdF = 2.0 * p.s * f + p.j * cofactor(f);
  return p.value;
}

// f = ψ(I2, I3) with I2 = ‖F‖², I3 = J, so its Hessian in F has the
// closed-form eigensystem of Smith, de Goes & Kim, "Analytic eigensystems for
// isotropic distortion energies" (ACM TOG 38(1), 2019, sec. 4-5): with the
// rotation-variant SVD F = U diag(σ) Vᵀ (U, V rotations, σ_3 carrying the
// sign of J) and (i, j, k) a permutation of (0, 1, 2),
//   twist U (e_i e_jᵀ − e_j e_iᵀ) Vᵀ / √2: λ = 2 ψ_2 + ψ_3 σ_k,
//   flip  U (e_i e_jᵀ + e_j e_iᵀ) Vᵀ / √2: λ = 2 ψ_2 − ψ_3 σ_k,
// and the scalings U diag(a) Vᵀ, whose block in the basis U e_i e_iᵀ Vᵀ is S,
// the 3 by 3 Hessian of ψ(Σ σ_i², σ_0 σ_1 σ_2) in σ (ψ_22 = 0 here). An
// eigenvector Q maps to the corners as Q G = U M P with P = Vᵀ G, so every
// 3 by 3 block of the corner Hessian is U M_ab Uᵀ, with M_ab (corners a, b)
// summed in U's frame from P's entries and the eigenvalues:
//   M_ab[i][i] = S_ii P_ia P_ib + Σ_{j≠i} (λ_twist,k + λ_flip,k)/2 P_ja P_jb,
//   M_ab[i][j] = S_ij P_ia P_jb + (λ_flip,k − λ_twist,k)/2 P_ja P_ib  (i ≠ j),
// k the index other than i and j. S is projected through its own
// eigendecomposition only when it is not positive definite.
Matrix12d untangleCornerHessian(const Eigen::Matrix3d& f, const Eigen::Matrix<double, 3, 4>& g,
                                double epsilon, bool projected) {
  Eigen::Matrix3d u;
  Eigen::Matrix3d v;
  Eigen::Vector3d sigma;
  rotationVariantSvd(f, u, sigma, v);
  const Psi p = psi(sigma.squaredNorm(), sigma.prod(), epsilon, /*second=*/true);
  const Eigen::Matrix<double, 3, 4> pv = v.transpose() * g;

  Eigen::Matrix3d scaling;  // S
  for (int i = 0; i < 3; ++i) {
    const double product = sigma((i + 1) % 3) * sigma((i + 2) % 3);  // ∂I3/∂σ_i
    for (int l = 0; l <= i; ++l) {
      const double otherProduct = sigma((l + 1) % 3) * sigma((l + 2) % 3);
      scaling(i, l) = 2.0 * p.sj * (sigma(i) * otherProduct + product * sigma(l)) +
                      p.jj * product * otherProduct +
                      (l == i ? 2.0 * p.s : p.j * sigma(3 - i - l));
      scaling(l, i) = scaling(i, l);
    }
  }
  if (projected && Eigen::LLT<Eigen::Matrix3d>(scaling).info() != Eigen::Success) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scaling);
    scaling = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
              eigen.eigenvectors().transpose();
  }
  // Per k: the mean of the twist and flip eigenvalues (the weight of
  // P_j P_jᵀ on M's diagonal) and half their difference (off it).
  Eigen::Vector3d mean;
  Eigen::Vector3d halfDifference;
  for (int k = 0; k < 3; ++k) {
    double twist = 2.0 * p.s + p.j * sigma(k);
    double flip = 2.0 * p.s - p.j * sigma(k);
    if (projected) {
      twist = std::max(twist, 0.0);
      flip = std::max(flip, 0.0);
    }
    mean(k) = 0.5 * (twist + flip);
    halfDifference(k) = 0.5 * (flip - twist);
  }
  Matrix12d h;
  for (int b = 0; b < 4; ++b) {
    for (int a = b; a < 4; ++a) {
      const Eigen::Vector3d pa = pv.col(a);
      const Eigen::Vector3d pb = pv.col(b);
      const Eigen::Vector3d same = pa.cwiseProduct(pb);  // P_ja P_jb
      Eigen::Matrix3d m = scaling.cwiseProduct(pa * pb.transpose());
      m(0, 0) += mean(2) * same(1) + mean(1) * same(2);
      m(1, 1) += mean(0) * same(2) + mean(2) * same(0);
      m(2, 2) += mean(1) * same(0) + mean(0) * same(1);
      m(0, 1) += halfDifference(2) * pa(1) * pb(0);
      m(1, 0) += halfDifference(2) * pa(0) * pb(1);
      m(0, 2) += halfDifference(1) * pa(2) * pb(0);
      m(2, 0) += halfDifference(1) * pa(0) * pb(2);
      m(1, 2) += halfDifference(0) * pa(2) * pb(1);
      m(2, 1) += halfDifference(0) * pa(1) * pb(2);
      const Eigen::Matrix3d block = u * m * u.transpose();
      h.block<3, 3>(3 * a, 3 * b) = block;
      if (a != b) h.block<3, 3>(3 * b, 3 * a) = block.transpose();
    }
  }
  return h;
}

}  // namespace tetblend
