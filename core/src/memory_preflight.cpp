#include "tetblend/core/memory_preflight.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>

#include "tetblend/core/error.h"

namespace tetblend {

int blasThreadCount() {
  if (const char* text = std::getenv("OPENBLAS_NUM_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && n > 0 && n <= 1024) return static_cast<int>(n);
  }
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

std::size_t blasWorkspaceBytes() {
  return kBlasBufferBytesPerThread * static_cast<std::size_t>(blasThreadCount());
}

void requireAllocatable(std::size_t bytes, const std::string& what) {
  void* block = std::malloc(bytes);
  if (block != nullptr) {
    std::free(block);
    return;
  }
  const long long megabytes = static_cast<long long>(std::ceil(bytes / 1048576.0));
  const int threads = blasThreadCount();
  std::string remedy = "raise the memory limit (ulimit -v)";
  if (threads > 1) {
    remedy += ", or set OPENBLAS_NUM_THREADS=1 to need " +
              std::to_string((threads - 1) * (kBlasBufferBytesPerThread >> 20)) + " MB less";
  }
  throw ResourceError("not enough memory for " + what + ": it needs about " +
                      std::to_string(megabytes) + " MB (with " + std::to_string(threads) +
                      " BLAS work buffer" + (threads > 1 ? "s" : "") +
                      " of 128 MB) and that much cannot be allocated; " + remedy);
}

}  // namespace tetblend
