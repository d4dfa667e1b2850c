#include "tetblend/core/openmp_teams.h"

#ifdef TETBLEND_HAVE_OPENMP
#include <omp.h>
#endif

namespace tetblend {

void letOpenMpShrinkTeams() {
#ifdef TETBLEND_HAVE_OPENMP
  omp_set_dynamic(1);
#endif
}

}  // namespace tetblend
