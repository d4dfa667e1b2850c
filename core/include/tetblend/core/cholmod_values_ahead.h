#pragma once
// Header only, for the files built with CHOLMOD and TBB (meshing's interior
// and Newton factorisations, blending's stitch): a supernodal factor's
// values allocated before CHOLMOD's numeric factorisation, so that their
// pages are faulted in ahead of it on another thread (pages_faulted_ahead.h).

#include <cholmod.h>

#include <cstddef>
#include <optional>

#include "tetblend/core/helper_threads.h"
#include "tetblend/core/pages_faulted_ahead.h"

namespace tetblend {

/// Create one after cholmod_analyze, just before the numeric factorisation
/// of a supernodal `factor`, and keep it alive through that factorisation.
/// If the factor is symbolic, allocates its values as the factorisation
/// would (cholmod_super_numeric allocates a symbolic factor's values and
/// writes a numeric factor's in place) and, if helperThreadAllowed(),
/// faults them in on a thread of its own meanwhile. Does nothing for a numeric or simplicial
/// factor, or when CHOLMOD cannot allocate the values (the factorisation
/// then reports it).
class SupernodalValuesAhead {
 public:
  SupernodalValuesAhead(cholmod_factor* factor, cholmod_common* common) {
    if (factor == nullptr || !factor->is_super || factor->xtype != CHOLMOD_PATTERN) return;
    if (!cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, factor, common)) return;
    if (helperThreadAllowed()) pages_.emplace(factor->x, factor->xsize * sizeof(double));
  }

 private:
  std::optional<PagesFaultedAhead> pages_;
};

}  // namespace tetblend
