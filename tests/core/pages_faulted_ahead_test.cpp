#include "tetblend/core/pages_faulted_ahead.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tetblend {
namespace {

// A fresh anonymous mapping (no page resident until written), unmapped on
// destruction.
class FreshMapping {
 public:
  explicit FreshMapping(std::size_t bytes)
      : bytes_(bytes),
        data_(::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)) {}
  ~FreshMapping() {
    if (data_ != MAP_FAILED) ::munmap(data_, bytes_);
  }
  FreshMapping(const FreshMapping&) = delete;
  FreshMapping& operator=(const FreshMapping&) = delete;
  bool valid() const { return data_ != MAP_FAILED; }
  double* doubles() const { return static_cast<double*>(data_); }
  std::size_t bytes() const { return bytes_; }

  // How many of its pages are resident (mincore).
  std::size_t residentPages() const {
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> resident((bytes_ + page - 1) / page);
    if (::mincore(data_, bytes_, resident.data()) != 0) return 0;
    std::size_t count = 0;
    for (unsigned char flag : resident) count += flag & 1u;
    return count;
  }

 private:
  std::size_t bytes_;
  void* data_;
};

// Whether this kernel has MADV_POPULATE_WRITE (Linux 5.14 on).
bool kernelPopulates() {
#ifdef MADV_POPULATE_WRITE
  FreshMapping probe(static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)));
  return probe.valid() && ::madvise(probe.doubles(), probe.bytes(), MADV_POPULATE_WRITE) == 0;
#else
  return false;
#endif
}

constexpr std::size_t kBytes = std::size_t{4} * kPagesAheadMinimumBytes;

TEST(PagesFaultedAhead, LeavesEveryPageResident) {
  if (!kernelPopulates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE";
  const FreshMapping mapping(kBytes);
  ASSERT_TRUE(mapping.valid());
  ASSERT_EQ(mapping.residentPages(), 0u);
  { const PagesFaultedAhead pages(mapping.doubles(), mapping.bytes()); }
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  EXPECT_EQ(mapping.residentPages(), mapping.bytes() / page);
}

// The caller writes the range while the pages are faulted in: every value
// written, before or during, is there afterwards.
TEST(PagesFaultedAhead, KeepsWhatIsWrittenBeforeAndMeanwhile) {
  const FreshMapping mapping(kBytes);
  ASSERT_TRUE(mapping.valid());
  const std::size_t count = mapping.bytes() / sizeof(double);
  double* values = mapping.doubles();
  for (std::size_t i = 0; i < count / 2; ++i) values[i] = static_cast<double>(i);
  {
    const PagesFaultedAhead pages(values, mapping.bytes());
    for (std::size_t i = count / 2; i < count; ++i) values[i] = static_cast<double>(i);
  }
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < count; ++i) wrong += values[i] != static_cast<double>(i);
  EXPECT_EQ(wrong, 0u);
}

// Below kPagesAheadMinimumBytes no thread starts and no page is touched.
TEST(PagesFaultedAhead, LeavesSmallRangesAlone) {
  const FreshMapping mapping(kPagesAheadMinimumBytes / 2);
  ASSERT_TRUE(mapping.valid());
  { const PagesFaultedAhead pages(mapping.doubles(), mapping.bytes()); }
  EXPECT_EQ(mapping.residentPages(), 0u);
}

}  // namespace
}  // namespace tetblend
