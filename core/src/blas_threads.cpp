#include "tetblend/core/blas_threads.h"

#include <dlfcn.h>

#include <mutex>

namespace tetblend {
namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

// OpenBLAS's run-time thread control, looked up among the loaded libraries
// (tetblend does not link OpenBLAS itself: CHOLMOD links whichever libblas
// the system chose). OpenBLAS 0.3.21 also exports the count its calls read
// (blas_cpu_number) and whether its thread pool runs (blas_server_avail);
// either may be missing in another version.
struct OpenBlasControl {
  GetThreads get = nullptr;
  SetThreads set = nullptr;
  int* threadCount = nullptr;
  const volatile int* poolRunning = nullptr;
};

const OpenBlasControl& openBlas() {
  static const OpenBlasControl control = [] {
    OpenBlasControl c;
    c.get = reinterpret_cast<GetThreads>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    c.set = reinterpret_cast<SetThreads>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (c.get == nullptr || c.set == nullptr) return OpenBlasControl{};
    c.threadCount = static_cast<int*>(::dlsym(RTLD_DEFAULT, "blas_cpu_number"));
    c.poolRunning = static_cast<const volatile int*>(::dlsym(RTLD_DEFAULT, "blas_server_avail"));
    if (c.threadCount == nullptr || c.poolRunning == nullptr) {
      c.threadCount = nullptr;
      c.poolRunning = nullptr;
    }
    return c;
  }();
  return control;
}

// Gives OpenBLAS's calls `threads` threads. OpenBLAS shuts its thread pool
// down before every fork (its pthread_atfork handler; tetblend forks for
// TetGen), and openblas_set_num_threads then starts it again whatever the
// count, its new workers spinning in sched_yield for 2^28 cycles (its
// THREAD_TIMEOUT, 0.11 s of a core here) before they sleep: bench_meshing's
// hard 10 k row embedded in 265-330 ms so, 185-209 ms with
// OPENBLAS_NUM_THREADS=1. While the pool is down, the count is written where
// OpenBLAS reads it instead; its first call on more than one thread starts
// the pool.
void setOpenBlasThreads(int threads) {
  const OpenBlasControl& c = openBlas();
  if (c.poolRunning != nullptr && *c.poolRunning == 0) {
    *c.threadCount = threads;
  } else {
    c.set(threads);
  }
}

// The scopes alive, and OpenBLAS's thread count before the first SerialBlas.
struct ScopeCounts {
  std::mutex mutex;
  int serial = 0;
  int parallel = 0;
  int ownThreads = 0;
};

ScopeCounts& counts() {
  static ScopeCounts instance;
  return instance;
}

// Sets OpenBLAS's thread count from the scopes alive; `counts().mutex` held.
void applyLocked() {
  const ScopeCounts& c = counts();
  if (c.serial > 0) setOpenBlasThreads(c.parallel > 0 ? c.ownThreads : 1);
}

template <class Change>
void changeScopes(const Change& change) {
  if (openBlas().set == nullptr) return;
  ScopeCounts& c = counts();
  const std::lock_guard<std::mutex> lock(c.mutex);
  change(c);
}

}  // namespace

SerialBlas::SerialBlas() {
  changeScopes([](ScopeCounts& c) {
    if (c.serial++ == 0) c.ownThreads = openBlas().get();
    applyLocked();
  });
}

SerialBlas::~SerialBlas() {
  changeScopes([](ScopeCounts& c) {
    if (--c.serial == 0) {
      setOpenBlasThreads(c.ownThreads);
      return;
    }
    applyLocked();
  });
}

ParallelBlas::ParallelBlas() {
  changeScopes([](ScopeCounts& c) {
    ++c.parallel;
    applyLocked();
  });
}

ParallelBlas::~ParallelBlas() {
  changeScopes([](ScopeCounts& c) {
    --c.parallel;
    applyLocked();
  });
}

int openBlasThreads() { return openBlas().get != nullptr ? openBlas().get() : 0; }

}  // namespace tetblend
