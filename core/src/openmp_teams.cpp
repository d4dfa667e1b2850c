#include "tetblend/core/openmp_teams.h"

#ifdef TETBLEND_HAVE_OPENMP
#include <omp.h>
#endif

namespace tetblend {

void useOpenMpTeams(bool team) {
#ifdef TETBLEND_HAVE_OPENMP
  // The active levels OpenMP started with (OMP_MAX_ACTIVE_LEVELS or its
  // default), read before the first change.
  static const int startLevels = omp_get_max_active_levels();
  omp_set_dynamic(1);
  omp_set_max_active_levels(team ? startLevels : 0);
#else
  static_cast<void>(team);
#endif
}

}  // namespace tetblend
