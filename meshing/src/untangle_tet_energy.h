#pragma once
// Private: the per-tet energy of the untangler (Garanzha, Kaporin,
// Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free maps in 50 lines of
// code", ACM TOG 40(4), 2021, eqs. (2)-(4) with θ = 1/2 in 3D):
//   f_ε(F) = (1-θ) ‖F‖² / χ(J, ε)^{2/3} + θ (J² + 1) / χ(J, ε),
// J = det F, χ(J, ε) = (J + sqrt(ε² + J²)) / 2, with its gradient and its
// Hessian with respect to F. vec(F) is column-major: entry (i, j) at 3j + i.

#include <Eigen/Core>

namespace tetblend {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

/// θ, the weight of the volume term (the paper's choice in 3D).
constexpr double kUntangleVolumeWeight = 0.5;

/// f_ε(F); its derivative ∂f/∂F into `dEdF` when non-null. Finite for every
/// F and ε > 0 (χ is evaluated in its cancellation-free form for J <= 0).
double untangleTetEnergy(const Eigen::Matrix3d& f, double epsilon, Eigen::Matrix3d* dEdF);

/// The Hessian of f_ε(X Gᵀ) with respect to the tet's corner positions X
/// (3 by 4; entry 3a + k is coordinate k of corner a) for the barycentric
/// gradients G (3 by 4), from the closed-form eigensystem of ∂²f_ε/∂vec(F)²;
/// with `projected`, its eigenvalues below 0 are dropped first: the nearest
/// positive semi-definite matrix in F in the Frobenius norm (projected
/// Newton, Teran, Sifakis, Irving & Fedkiw 2005). For the unit corner tet,
/// G = [-1 1 0 0; -1 0 1 0; -1 0 0 1], its lower-right 9 by 9 block is the
/// Hessian in vec(F).
Matrix12d untangleCornerHessian(const Eigen::Matrix3d& f, const Eigen::Matrix<double, 3, 4>& g,
                                double epsilon, bool projected);

}  // namespace tetblend
