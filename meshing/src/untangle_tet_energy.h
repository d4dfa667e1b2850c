#pragma once
// Private: the per-tet energy of the untangler (Garanzha, Kaporin,
// Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free maps in 50 lines of
// code", ACM TOG 40(4), 2021, eqs. (2)-(4) with θ = 1/2 in 3D):
//   f_ε(F) = (1-θ) ‖F‖² / χ(J, ε)^{2/3} + θ (J² + 1) / χ(J, ε),
// J = det F, χ(J, ε) = (J + sqrt(ε² + J²)) / 2, with its gradient and its
// Hessian with respect to F. vec(F) is column-major: entry (i, j) at 3j + i.

#include <Eigen/Core>

namespace tetblend {

using Matrix9d = Eigen::Matrix<double, 9, 9>;

/// θ, the weight of the volume term (the paper's choice in 3D).
constexpr double kUntangleVolumeWeight = 0.5;

/// f_ε(F); its derivative ∂f/∂F into `dEdF` when non-null. Finite for every
/// F and ε > 0 (χ is evaluated in its cancellation-free form for J <= 0).
double untangleTetEnergy(const Eigen::Matrix3d& f, double epsilon, Eigen::Matrix3d* dEdF);

/// ∂²f_ε/∂vec(F)² from its closed-form eigensystem; with `projected`, the
/// eigenvalues below 0 are dropped: the nearest positive semi-definite
/// matrix in the Frobenius norm (projected Newton, Teran, Sifakis, Irving &
/// Fedkiw 2005).
Matrix9d untangleTetHessian(const Eigen::Matrix3d& f, double epsilon, bool projected);

}  // namespace tetblend
