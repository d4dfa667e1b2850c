#pragma once
// Dual-quaternion blend methods over a tet mesh (Kavan et al. §3-4 applied to
// the polar factors of the per-tet maps, Kaji–Ochiai §4.4 "Polar+DLB"):
// F_kj = R_kj S_kj; the rotations are blended as unit dual quaternions with
// the rest (identity) at weight 1 - sum(w), the stretches in log space,
// B_j = R(w) exp(sum_k w_k log S_kj).

#include <memory>

#include "tetblend/blending/blend_method.h"

namespace tetblend {

/// Prepares kDualQuaternion (rotation by DLB, Kavan §4) or kDib (DIB, Kavan
/// §4, iterated to convergence); InputError for another method. Any weights;
/// DomainError naming the tet when DLB's blended quaternion vanishes (weights
/// that cancel), NumericalError naming the tet when DIB does not converge.
std::unique_ptr<TetMapBlender> prepareDualQuaternionBlender(BlendMethod method,
                                                            const BlendInput& input);

}  // namespace tetblend
