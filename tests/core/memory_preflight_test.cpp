// memory_preflight.h: the memory check before a factorisation (issue 11).

#include "tetblend/core/memory_preflight.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "address_sanitizer.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// Sets OPENBLAS_NUM_THREADS for one scope and restores it after.
class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(const char* value) {
    if (const char* old = std::getenv(kName)) saved_ = old, hadValue_ = true;
    if (value != nullptr) {
      setenv(kName, value, 1);
    } else {
      unsetenv(kName);
    }
  }
  ~ScopedBlasThreads() {
    if (hadValue_) {
      setenv(kName, saved_.c_str(), 1);
    } else {
      unsetenv(kName);
    }
  }

 private:
  static constexpr const char* kName = "OPENBLAS_NUM_THREADS";
  std::string saved_;
  bool hadValue_ = false;
};

TEST(MemoryPreflight, BlasThreadsFollowOpenblasNumThreads) {
  {
    const ScopedBlasThreads one("1");
    EXPECT_EQ(blasThreadCount(), 1);
    EXPECT_EQ(blasWorkspaceBytes(), kBlasBufferBytesPerThread);
  }
  {
    const ScopedBlasThreads three("3");
    EXPECT_EQ(blasWorkspaceBytes(), 3 * kBlasBufferBytesPerThread);
  }
  int hardware = 0;
  {
    const ScopedBlasThreads unset(nullptr);
    hardware = blasThreadCount();
  }
  EXPECT_GE(hardware, 1);
  for (const char* ignored : {"0", "-2", "two", "4x", "", "100000"}) {
    const ScopedBlasThreads bad(ignored);
    EXPECT_EQ(blasThreadCount(), hardware) << "OPENBLAS_NUM_THREADS=" << ignored;
  }
}

TEST(MemoryPreflight, AllocatableBytesPass) {
  EXPECT_NO_THROW(requireAllocatable(std::size_t{1} << 20, "a small block"));
}

TEST(MemoryPreflight, BytesNoMachineHasAreOneResourceErrorWithTheRemedy) {
  if (test::kAddressSanitizer) GTEST_SKIP() << "ASan aborts on allocations beyond its maximum";
  const ScopedBlasThreads two("2");
  const std::size_t exabyte = std::size_t{1} << 60;
  try {
    requireAllocatable(exabyte, "the test's factor");
    FAIL() << "an exabyte was allocated";
  } catch (const ResourceError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("not enough memory for the test's factor: it needs about " +
                                std::to_string(exabyte >> 20) + " MB (with 2 BLAS work buffers",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("OPENBLAS_NUM_THREADS=1 to need 128 MB less"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  const ScopedBlasThreads one("1");
  try {
    requireAllocatable(exabyte, "the test's factor");
    FAIL() << "an exabyte was allocated";
  } catch (const ResourceError& e) {
    EXPECT_EQ(std::string(e.what()).find("OPENBLAS_NUM_THREADS"), std::string::npos)
        << "with one BLAS thread already, fewer threads cannot help: " << e.what();
  }
}

}  // namespace
}  // namespace tetblend
