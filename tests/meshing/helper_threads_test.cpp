// helperThreadAllowed (core/include/tetblend/core/helper_threads.h): the
// rule for the threads tetblend starts beside TBB's (METIS's background
// order, a factor's pages faulted in ahead) follows the caller's limit.

#include "tetblend/core/helper_threads.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

namespace tetblend {
namespace {

TEST(HelperThreads, NoneWhenTheCallerAllowsOneThread) {
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_FALSE(helperThreadAllowed());
  }
  const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  EXPECT_TRUE(helperThreadAllowed());
}

}  // namespace
}  // namespace tetblend
