#pragma once
// Private: untangling of a tet mesh by moving its free vertices (Garanzha,
// Kaporin, Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free maps in 50
// lines of code", ACM TOG 40(4), 2021): minimise
//   E_ε(x) = Σ_t vol_t [ (1-θ) ‖F_t‖² / χ(J_t, ε)^{2/3} + θ (J_t² + 1) / χ(J_t, ε) ]
// with J_t = det F_t and χ(J, ε) = (J + sqrt(ε² + J²)) / 2, a smooth positive
// stand-in for J, while the regularisation ε decreases to 0 (the paper's
// Alg. 1). Each ε is minimised by projected Newton steps (every tet's
// Hessian made positive semi-definite from its closed-form eigensystem,
// untangle_tet_energy.h; one sparse Cholesky factorisation per round at
// most, kept while it predicts the decrease, the pattern analysed once)
// instead of the paper's L-BFGS: on the hard-pose
// corpus L-BFGS with 30 iterations per ε left 6 of 48 clean poses with 492
// inverted tets (44 s), and knot1's 1080° twist alone kept 4 tets after 14
// minutes with 300 iterations per ε; Newton with 2 steps per ε, with the
// stall and start rules of untangle.cpp, leaves 1 pose with 75 (50 s).

#include <functional>
#include <vector>

#include "tet_elements.h"
#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/compatible_tets.h"

namespace tetblend {

struct UntangleOutcome {
  int rounds = 0;       ///< outer (ε-decrease) rounds performed
  double minDet = 0.0;  ///< smallest det F_t of the state returned (unitless)
};

/// The free vertices for untangling the given tets (the caller's rings
/// around them): untangle narrows its free region to these once most of
/// its inverted tets are repaired (untangle.cpp, kRefocusFall).
using FreeRegionAround = std::function<std::vector<int>(const std::vector<int>& invertedTets)>;

/// Whether a full-length Newton step d = -B⁻¹g of slope gᵀd < 0 that took
/// the energy from `before` to `after` agreed with the quadratic model of
/// the factored matrix B, whose predicted decrease is -gᵀd / 2: the actual
/// decrease lies within [kModelAgreement, 2 - kModelAgreement] times it
/// (untangle.cpp). Then the next round keeps B's factor.
bool newtonModelAgrees(double slope, double before, double after);

/// Moves the vertices listed in `freeVertices` (distinct indices into
/// `positions`, #V by 3) to remove inverted tets among the tets touching
/// them; every other vertex stays put. Stops as soon as all those tets have
/// det F > 0, or after effort.maxRounds rounds of at most
/// effort.iterationsPerRound Newton steps each, or when it stalls
/// (effort.maxRings is the caller's). With `regionAround`, the free region
/// narrows as the inverted tets become few. `positions` ends at the best
/// state reached (fewest inverted tets, then the largest min det F), which
/// outcome.minDet describes.
UntangleOutcome untangle(const Tets& tets, const std::vector<TetElement>& elements,
                         const std::vector<int>& freeVertices, const UntangleEffort& effort,
                         Vertices& positions, const FreeRegionAround& regionAround = {});

}  // namespace tetblend
