#pragma once
// Header only, for the modules built with TBB: whether tetblend may start a
// thread of its own beside TBB's workers (METIS's background order,
// interior_ordering.h; a factor's pages faulted in ahead,
// cholmod_values_ahead.h). Not when the caller allowed one thread
// (tbb::global_control, `--threads 1`).

#include <tbb/global_control.h>

namespace tetblend {

inline bool helperThreadAllowed() {
  return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) >= 2;
}

}  // namespace tetblend
