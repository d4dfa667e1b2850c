#pragma once
// Private: Eigen's CHOLMOD supernodal LLᵀ whose first factorisation has its
// factor's values faulted in ahead on another thread
// (cholmod_values_ahead.h). Only with CHOLMOD.

#include <Eigen/CholmodSupport>

#include "tetblend/core/cholmod_values_ahead.h"

namespace tetblend {

template <class Matrix>
class SupernodalLLTValuesAhead : public Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> {
 public:
  /// Eigen's factorize, after analyzePattern (hides it).
  void factorize(const Matrix& matrix) {
    const SupernodalValuesAhead ahead(this->m_cholmodFactor, &this->cholmod());
    Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower>::factorize(matrix);
  }
};

}  // namespace tetblend
