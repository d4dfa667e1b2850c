#pragma once
// Polar decomposition A = R S of a 3x3 matrix with det A > 0: R in SO(3), S
// symmetric positive definite (the rotation and stretch factors of
// Kaji–Ochiai eq. (3), S = sqrt(A^T A), computed without forming A^T A).

#include <Eigen/Core>

namespace tetblend {

/// The factors of A = rotation * stretch.
struct PolarDecomposition {
  Eigen::Matrix3d rotation;  ///< R in SO(3).
  Eigen::Matrix3d stretch;   ///< S = R^T A, symmetric positive definite.
};

/// The rotation factor and the logarithm of the stretch factor of A.
struct PolarLogDecomposition {
  Eigen::Matrix3d rotation;    ///< R in SO(3).
  Eigen::Matrix3d stretchLog;  ///< log S = V log(Sigma) V^T, symmetric.
};

/// Polar decomposition A = R S (3x3, any units; S has the units of A) by
/// Higham's scaled Newton iteration X <- (g X + X^{-T}/g)/2 with Frobenius
/// scaling g (Higham, Functions of Matrices, §8.6), which works on A itself
/// and so keeps the accuracy of near-singular A (cond(A) up to ~1e12) instead
/// of squaring the condition number through A^T A.
/// Throws DomainError if det A <= 0 or A is not finite (no reflection is ever
/// returned), NumericalError if the iteration fails to converge.
PolarDecomposition polarDecompose(const Eigen::Matrix3d& a);

/// Rotation factor of A and log S computed from the eigen-decomposition of the
/// polar factor S = V Sigma V^T (Sigma = singular values of A), so the
/// logarithm of a stretch with a tiny singular value keeps its accuracy
/// (Kaji–Ochiai eq. (3), psi_S). Same errors as polarDecompose.
PolarLogDecomposition polarDecomposeLog(const Eigen::Matrix3d& a);

}  // namespace tetblend
