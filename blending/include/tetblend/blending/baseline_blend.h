#pragma once
// Baseline blend methods over a tet mesh: linear blending of deformation
// gradients, Alexa's matrix log-blend, and polar + quaternion slerp (the
// precursors compared in Kaji–Ochiai §4.4 Table 2 and §7).

#include <memory>

#include "tetblend/blending/blend_method.h"

namespace tetblend {

/// Prepares kLinear, kAlexa or kPolarSlerp (InputError for another method).
/// kLinear: B_j = (1 - sum w) I + sum_k w_k F_kj, any weights.
/// kAlexa: B_j = exp(sum_k w_k log F_kj) with the real principal matrix
/// logarithm taken once per example; DomainError naming the example and tet
/// when F_kj has no real logarithm (negative real eigenvalues).
/// kPolarSlerp: see polarSlerpBlend in core/baselines.h.
std::unique_ptr<TetMapBlender> prepareBaselineBlender(BlendMethod method, const BlendInput& input);

}  // namespace tetblend
