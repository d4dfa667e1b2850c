#pragma once
// Header only, for the files built with CHOLMOD (meshing's interior and
// Newton factorisations, blending's stitch): a supernodal factor's values
// allocated before CHOLMOD's numeric factorisation, so that their pages can
// be faulted in ahead of it on another thread (pages_faulted_ahead.h).

#include <cholmod.h>

#include <cstddef>
#include <utility>

namespace tetblend {

/// After cholmod_analyze and before the first numeric factorisation of a
/// supernodal `factor`: allocates its values as that factorisation would
/// (cholmod_super_numeric allocates a symbolic factor's values, and writes
/// a numeric factor's in place) and returns them as (data, bytes).
/// (nullptr, 0) when the factor is numeric already or not supernodal, or
/// when CHOLMOD could not allocate them (the factorisation then reports it).
inline std::pair<void*, std::size_t> allocateSupernodalValues(cholmod_factor* factor,
                                                              cholmod_common* common) {
  if (factor == nullptr || !factor->is_super || factor->xtype != CHOLMOD_PATTERN) {
    return {nullptr, 0};
  }
  if (!cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, factor, common)) return {nullptr, 0};
  return {factor->x, factor->xsize * sizeof(double)};
}

}  // namespace tetblend
