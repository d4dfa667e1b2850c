#pragma once
// Private: how many examples buildCompatibleTetMeshes places at once, and
// the loop that places them (example_aware_tets.cpp).

#include <algorithm>
#include <cstddef>

#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <Eigen/Core>

namespace tetblend {

// Working memory of one example's placement per rest tet, an upper bound:
// a clean example that frees the whole interior holds the Newton untangler's
// per-tet Hessians (1.2 kB) and its factor. Measured, a second placement at
// once added 100 MB to the peak at 54 k tets (the bear's 48 frames), 12 MB at
// 15 k (the dino's) and nothing measurable at 1 M (bench_meshing's hard set).
inline constexpr double kPlacementBytesPerTet = 2000.0;
// The same without the untangling: the harmonic map, ARAP's rotations and
// candidates (a few 3x3 matrices and positions per tet). Measured: placing
// bench_meshing's three 1 M examples two at a time instead of one raised
// its peak from 997-1006 MB to 1032-1038 MB (three runs each).
inline constexpr double kHarmonicArapBytesPerTet = 500.0;
// The most the examples placed at once may use together.
inline constexpr double kConcurrentPlacementBytes = 2e9;

// How many examples are placed at once when each needs `bytesPerTet` of
// working memory per rest tet: one per thread while together they stay
// within kConcurrentPlacementBytes, at least one. A placement's own loops
// are parallel too, but its sparse factorisations and sequential steps are
// not: the bear's 48 frames took 63.6 s instead of 87.2 s on 2 cores, with
// the same model bit for bit.
inline std::size_t concurrentExamples(Eigen::Index tets, std::size_t examples,
                                      double bytesPerTet = kPlacementBytesPerTet) {
  const double byMemory = kConcurrentPlacementBytes /
                          (bytesPerTet * static_cast<double>(std::max<Eigen::Index>(tets, 1)));
  const std::size_t threads =
      std::min(static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
               tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  return std::max<std::size_t>(1,
                               std::min({examples, threads, static_cast<std::size_t>(byMemory)}));
}

// Runs body(k) for k = 0..count-1, at most `concurrency` at a time (in
// order on this thread when 1). Each body writes only its own example's
// slots, so the results do not depend on the order.
template <class Body>
void forEachExample(std::size_t count, std::size_t concurrency, const Body& body) {
  if (concurrency <= 1) {
    for (std::size_t k = 0; k < count; ++k) body(k);
    return;
  }
  std::size_t next = 0;
  tbb::parallel_pipeline(concurrency,
                         tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                                             [&](tbb::flow_control& control) {
                                                               if (next == count) control.stop();
                                                               return next++;
                                                             }) &
                             tbb::make_filter<std::size_t, void>(tbb::filter_mode::parallel, body));
}

}  // namespace tetblend
