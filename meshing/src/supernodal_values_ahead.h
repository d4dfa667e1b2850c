#pragma once
// Private: Eigen's CHOLMOD supernodal LLᵀ whose factor's values can be
// allocated before the factorisation, so that their pages are faulted in
// ahead of it on another thread (pages_faulted_ahead.h). Only with CHOLMOD.

#include <cstddef>
#include <utility>

#include <Eigen/CholmodSupport>

namespace tetblend {

template <class Matrix>
class SupernodalValuesAhead : public Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> {
 public:
  /// After analyzePattern and before the first factorize: allocates the
  /// factor's values as that factorisation would (CHOLMOD then writes them
  /// in place; cholmod_super_numeric allocates only a symbolic factor's)
  /// and returns them as (data, bytes). (nullptr, 0) when they were
  /// allocated already, the factor is not supernodal, or CHOLMOD could not
  /// allocate them (the factorisation then reports it).
  std::pair<void*, std::size_t> allocateValues() {
    cholmod_factor* factor = this->m_cholmodFactor;
    if (factor == nullptr || !factor->is_super || factor->xtype != CHOLMOD_PATTERN) {
      return {nullptr, 0};
    }
    if (!cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, factor, &this->cholmod())) {
      return {nullptr, 0};
    }
    return {factor->x, factor->xsize * sizeof(double)};
  }
};

}  // namespace tetblend
