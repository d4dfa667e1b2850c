#pragma once
// A parallel loop whose errors do not depend on the schedule (private to
// tetblend_blending).

#include <tbb/parallel_for.h>

#include <exception>
#include <vector>

namespace tetblend {
namespace blend_detail {

/// Runs body(c) for c in [0, count) in parallel. If bodies throw, every c
/// still runs and the exception of the lowest throwing c is rethrown after
/// the loop, so with bodies that visit their elements in order an error
/// names the first bad element whatever the schedule or the thread count.
template <typename Body>
void parallelForFirstError(int count, const Body& body) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(count > 0 ? count : 0));
  tbb::parallel_for(0, count, [&](int c) {
    try {
      body(c);
    } catch (...) {
      errors[static_cast<size_t>(c)] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace blend_detail
}  // namespace tetblend
