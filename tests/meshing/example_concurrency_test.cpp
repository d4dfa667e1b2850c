// How many examples buildCompatibleTetMeshes places at once
// (meshing/src/example_concurrency.h): one per thread within the memory
// bound, at least one, and fewer untanglings than placements where the
// untangler's working memory is the bound.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "example_concurrency.h"

namespace tetblend {
namespace {

std::size_t threads() {
  return std::min(static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
                  tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

TEST(ExampleConcurrency, OnePerThreadWithinTheMemoryBound) {
  // 10 k tets: 2e9 / (2000 · 1e4) = 100 placements' worth of memory.
  EXPECT_EQ(concurrentExamples(10'000, 3), std::min<std::size_t>(3, threads()));
  EXPECT_EQ(concurrentExamples(10'000, 1), 1u);
}

TEST(ExampleConcurrency, AMillionTetsUntangleOneAtATimeButPlaceSeveral) {
  // 2e9 / (2000 · 1e6) = 1 untangling; 2e9 / (500 · 1e6) = 4 placements.
  EXPECT_EQ(concurrentExamples(1'000'000, 3), 1u);
  EXPECT_EQ(concurrentExamples(1'000'000, 3, kHarmonicArapBytesPerTet),
            std::min<std::size_t>(3, threads()));
  // Beyond the bound for even one: still one.
  EXPECT_EQ(concurrentExamples(100'000'000, 3), 1u);
}

TEST(ExampleConcurrency, OneThreadAllowedPlacesOneAtATime) {
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(concurrentExamples(10'000, 3, kHarmonicArapBytesPerTet), 1u);
}

}  // namespace
}  // namespace tetblend
