#pragma once
// Private: untangling of a tet mesh by moving its free vertices (Garanzha,
// Kaporin, Kudryavtseva, Protais, Ray, Sokolov, "Foldover-free maps in 50
// lines of code", ACM TOG 40(4), 2021): minimise
//   E_ε(x) = Σ_t vol_t [ (1-θ) ‖F_t‖² / χ(J_t, ε)^{2/3} + θ (J_t² + 1) / χ(J_t, ε) ]
// with J_t = det F_t and χ(J, ε) = (J + sqrt(ε² + J²)) / 2, a smooth positive
// stand-in for J, while the regularisation ε decreases to 0.

#include <vector>

#include "tet_elements.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

struct UntangleOutcome {
  int rounds = 0;       ///< outer (ε-decrease) rounds performed
  double minDet = 0.0;  ///< smallest det F_t at the end (unitless)
};

/// Moves the vertices listed in `freeVertices` (distinct indices into
/// `positions`, #V by 3) to remove inverted tets among the tets touching
/// them; every other vertex stays put. Stops as soon as all those tets have
/// det F > 0, or after maxRounds rounds of at most iterationsPerRound L-BFGS
/// iterations each.
UntangleOutcome untangle(const Tets& tets, const std::vector<TetElement>& elements,
                         const std::vector<int>& freeVertices, int maxRounds,
                         int iterationsPerRound, Vertices& positions);

}  // namespace tetblend
