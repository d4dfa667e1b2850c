#pragma once
// The Kaji–Ochiai blend methods over a tet mesh (Kaji & Ochiai §5, §6.2):
// "kaji" blends psi(F_kj) linearly in R^3 x so(3) x sym(3) and maps back with
// phi; "kaji-frechet" uses the refined weighted Fréchet sum (Alg. 2).

#include <memory>

#include "tetblend/blending/blend_cache.h"
#include "tetblend/blending/blend_method.h"

namespace tetblend {

/// Prepares kKaji or kKajiFrechet (InputError for another method).
/// kKaji: psi(F_kj) once per example and tet, the rotation logarithms made
/// consistent over face adjacency when input.rotationConsistency is set
/// (Alg. 1, rotation_consistency.h); per blend B_j = phi(sum_k w_k psi(F_kj))
/// (the rest's psi is 0, so its weight 1 - sum w drops out). Any weights.
/// kKajiFrechet: B_j = kajiFrechetBlend(w, F_1j..F_nj) (Alg. 2, identity at
/// weight 1 - sum w). Its iteration takes principal logarithms relative to
/// the running mean, so it ignores input.rotationConsistency and cannot keep
/// more than half a turn per tet. NumericalError naming the tet when the
/// iteration does not converge for a weight vector.
std::unique_ptr<TetMapBlender> prepareKajiBlender(BlendMethod method, const BlendInput& input);

/// The parameters of a kKaji blender, to be stored (blend_cache.h); InputError
/// for a blender of another method.
KajiParameterData kajiParameterData(const TetMapBlender& blender);

/// A kKaji blender from parameters kajiParameterData gave, blending exactly
/// as the blender that gave them. InputError when their sizes or indices are
/// inconsistent (the caller checks tets, examples and rotationConsistency
/// against its own).
std::unique_ptr<TetMapBlender> kajiBlenderFromData(KajiParameterData data);

}  // namespace tetblend
