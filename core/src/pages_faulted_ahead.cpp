#include "tetblend/core/pages_faulted_ahead.h"

#include <algorithm>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace tetblend {
namespace {

// One madvise call per chunk, so that the lowest pages, which a writer
// going up the range reaches first, are ready first.
constexpr std::uintptr_t kChunkBytes = std::uintptr_t{16} << 20;

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
void faultIn(std::uintptr_t begin, std::uintptr_t end) {
  for (std::uintptr_t chunk = begin; chunk < end; chunk += kChunkBytes) {
    const std::uintptr_t length = std::min(kChunkBytes, end - chunk);
    // Fails (EINVAL) on kernels without it: then the writer faults the
    // pages itself, as without this class.
    if (::madvise(reinterpret_cast<void*>(chunk), length, MADV_POPULATE_WRITE) != 0) return;
  }
}
#endif

}  // namespace

PagesFaultedAhead::PagesFaultedAhead(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  if (data == nullptr || bytes < kPagesAheadMinimumBytes) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  // The whole pages inside the range: madvise needs a page-aligned start,
  // and the partial pages at either end are left to the writer.
  const std::uintptr_t begin = (start + page - 1) / page * page;
  const std::uintptr_t end = (start + bytes) / page * page;
  if (begin < end) thread_ = std::thread(faultIn, begin, end);
#else
  static_cast<void>(data);
  static_cast<void>(bytes);
#endif
}

PagesFaultedAhead::~PagesFaultedAhead() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace tetblend
