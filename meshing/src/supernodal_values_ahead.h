#pragma once
// Private: Eigen's CHOLMOD supernodal LLᵀ whose factor's values can be
// allocated before the factorisation, so that their pages are faulted in
// ahead of it on another thread (pages_faulted_ahead.h). Only with CHOLMOD.

#include <cstddef>
#include <utility>

#include <Eigen/CholmodSupport>

#include "tetblend/core/cholmod_values_ahead.h"

namespace tetblend {

template <class Matrix>
class SupernodalValuesAhead : public Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> {
 public:
  /// After analyzePattern: the factor's values, allocated now
  /// (allocateSupernodalValues; Eigen keeps the factor to itself).
  std::pair<void*, std::size_t> allocateValues() {
    return allocateSupernodalValues(this->m_cholmodFactor, &this->cholmod());
  }
};

}  // namespace tetblend
