#pragma once
// The Lie-Bodies blend method over a tet mesh (Bansal & Tatu §3-4, §6.2):
// each tet is a body p = (E, A, s) in SE(3) x G_A x R+; the blended body is
// p0 exp(sum_k w_k log(p0^-1 p_k)) per component, and the target map is the
// deformation gradient from the rest tet to the blended tet.

#include <memory>

#include "tetblend/blending/blend_method.h"

namespace tetblend {

/// Prepares kLieBodies: p0 and log(p0^-1 p_k) once per tet and example, the
/// rotation parts made consistent over face adjacency when
/// input.rotationConsistency is set (rotation_consistency.h applied to the
/// world rotations lieBodyWorldRotation). Any weights. DomainError naming the
/// example and tet when a body cannot be formed.
std::unique_ptr<TetMapBlender> prepareLieBodiesBlender(const BlendInput& input);

}  // namespace tetblend
