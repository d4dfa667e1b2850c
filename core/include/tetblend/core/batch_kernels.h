#pragma once
// Batched versions of the per-element kernels for whole meshes: so3Log,
// symExp, symLog, phi, psi and the polar decomposition over arrays. Each element's result equals
// the scalar kernel's to a few ulps times the kernel's conditioning (the lanes use the same
// formulas, thresholds and branches, with lane_math.h's polynomials for exp/log/atan2/sin/cos).
// Internally the elements are transposed in blocks into structure-of-arrays form and processed by a
// loop that GCC vectorises; the best of AVX-512, AVX2+FMA or baseline code is chosen at run time
// (function multi-versioning), so the library stays portable. Elements the lanes do not cover
// (arguments outside the lane_math ranges, the scalar kernels' fallback branches, errors) are
// recomputed by the scalar kernel, so the batched call throws exactly what the scalar loop would
// throw, for the first such element.
//
// Input and output arrays hold n elements each and must not overlap.

#include <cstddef>

#include <Eigen/Core>

#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/polar.h"

namespace tetblend {

/// out[i] = so3Exp(omega[i]) (Rodrigues, Kaji–Ochiai §4.1), omega in
/// radians; any finite omega (angles past the lanes' sin/cos range go to the
/// scalar kernel).
void so3ExpBatch(const Eigen::Vector3d* omega, Eigen::Matrix3d* out, std::size_t n);

/// out[i] = so3Log(rotations[i]) (principal log, Kaji–Ochiai eq. (7)),
/// radians.
void so3LogBatch(const Eigen::Matrix3d* rotations, Eigen::Vector3d* out, std::size_t n);

/// out[i] = symExp(y[i]) (Kaji–Ochiai eq. (4)); y[i] symmetric, upper
/// triangle read.
void symExpBatch(const Eigen::Matrix3d* y, Eigen::Matrix3d* out, std::size_t n);

/// out[i] = symLog(s[i]) (Kaji–Ochiai eq. (6)); s[i] symmetric positive
/// definite, upper triangle read. Throws DomainError like symLog.
void symLogBatch(const Eigen::Matrix3d* s, Eigen::Matrix3d* out, std::size_t n);

/// out[i] = phi(params[i]) (Kaji–Ochiai eq. (2)), 4x4 homogeneous.
void phiBatch(const AffineParams* params, Eigen::Matrix4d* out, std::size_t n);

/// out[i] = psi(a[i]) (Kaji–Ochiai eq. (3), principal rotation log); a[i] 4x4
/// homogeneous, bottom row not read. Throws DomainError like psi if some
/// det a[i] <= 0.
void psiBatch(const Eigen::Matrix4d* a, AffineParams* out, std::size_t n);

/// Packed form of phi's linear block for per-tet parameter arrays: out[i] =
/// so3Exp(w_i) * symExp(Y_i) (Kaji–Ochiai eq. (2) without translation), where
/// logs[9 i .. 9 i + 8] holds w_i (3, radians) then the upper triangle of the
/// symmetric Y_i as (xx, xy, xz, yy, yz, zz).
void phiLinearBatch(const double* logs, Eigen::Matrix3d* out, std::size_t n);

/// out[i] = polarDecomposeLog(a[i]) (3x3, det > 0): the rotation factor and
/// log S (Kaji–Ochiai eq. (3)) without the rotation log. Throws DomainError
/// like polarDecomposeLog if some det a[i] <= 0.
void polarDecomposeLogBatch(const Eigen::Matrix3d* a, PolarLogDecomposition* out, std::size_t n);

/// out[i] = polarDecompose(a[i]).rotation (3x3, det > 0): the rotation
/// closest to a[i] (ARAP's local step). Throws DomainError like
/// polarDecompose if some det a[i] <= 0, NumericalError if its iteration
/// fails for an element the closed form declines.
void polarRotationBatch(const Eigen::Matrix3d* a, Eigen::Matrix3d* out, std::size_t n);

}  // namespace tetblend
