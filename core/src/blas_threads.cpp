#include "tetblend/core/blas_threads.h"

#include <dlfcn.h>

#include <mutex>

namespace tetblend {
namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

// OpenBLAS's run-time thread control, looked up among the loaded libraries
// (tetblend does not link OpenBLAS itself: CHOLMOD links whichever libblas
// the system chose).
struct OpenBlasControl {
  GetThreads get = nullptr;
  SetThreads set = nullptr;
};

const OpenBlasControl& openBlas() {
  static const OpenBlasControl control = [] {
    OpenBlasControl c;
    c.get = reinterpret_cast<GetThreads>(::dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    c.set = reinterpret_cast<SetThreads>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (c.get == nullptr || c.set == nullptr) c = OpenBlasControl{};
    return c;
  }();
  return control;
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
  if (c.serial > 0) openBlas().set(c.parallel > 0 ? c.ownThreads : 1);
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
      openBlas().set(c.ownThreads);
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
