#include "interior_ordering.h"

#include <malloc.h>

#include <algorithm>
#include <cstddef>
#include <utility>

#include <tbb/global_control.h>

#ifdef TETBLEND_HAVE_CHOLMOD
#include <cholmod.h>
#endif

#include "interior_stiffness.h"

namespace tetblend {
namespace {

// Vertices appended to an order, at most this fraction of it. An appended
// vertex is eliminated after all others, so its row of L holds the
// elimination-tree paths from its neighbours to the root: about the
// separators met on the way, O(n^(2/3)) for a 3D mesh of n vertices (a few
// thousand at the 1 M-tet bar's 1.5e5). At 1 % appended that is under a
// tenth of the factor there (lnz 5.5e7); bench_meshing's stage 1 appends 15
// vertices at 1 M tets, stage 3 may append as many as the mesh had.
constexpr std::size_t kAppendedPerOrdered = 100;

#ifdef TETBLEND_HAVE_CHOLMOD
constexpr bool kHaveMetis = true;  // CHOLMOD's Partition module
#else
constexpr bool kHaveMetis = false;
#endif

}  // namespace

InteriorOrder metisInteriorOrder([[maybe_unused]] const Tets& tets,
                                 [[maybe_unused]] int surfaceVertexCount,
                                 [[maybe_unused]] int vertexCount) {
#ifdef TETBLEND_HAVE_CHOLMOD
  const int interiorCount = vertexCount - surfaceVertexCount;
  if (interiorCount <= 0) return {};
  // The strictly lower triangle of K_II's pattern, one column per interior
  // vertex from its star: the interior corners of its tets above it.
  const VertexStars stars = vertexStars(tets, vertexCount);
  std::vector<int> columnStart(static_cast<std::size_t>(interiorCount) + 1, 0);
  std::vector<int> rows;
  // About 7 neighbours above each vertex: half of a TetGen vertex's ~14.
  rows.reserve(static_cast<std::size_t>(7) * static_cast<std::size_t>(interiorCount));
  // Each neighbour is taken once (lastColumn: the column that last took
  // it), then the few of them sorted: sorting every tet corner of the star
  // took 0.25-0.3 s of the METIS thread at 1 M tets, before METIS began.
  std::vector<int> column;
  std::vector<int> lastColumn(static_cast<std::size_t>(interiorCount), -1);
  for (int j = 0; j < interiorCount; ++j) {
    const int v = surfaceVertexCount + j;
    column.clear();
    for (int k = stars.start[static_cast<std::size_t>(v)];
         k < stars.start[static_cast<std::size_t>(v) + 1]; ++k) {
      for (int a = 0; a < 4; ++a) {
        const int w = tets(stars.tets[static_cast<std::size_t>(k)], a);
        if (w <= v) continue;
        int& last = lastColumn[static_cast<std::size_t>(w - surfaceVertexCount)];
        if (last == j) continue;
        last = j;
        column.push_back(w - surfaceVertexCount);
      }
    }
    std::sort(column.begin(), column.end());
    rows.insert(rows.end(), column.begin(), column.end());
    columnStart[static_cast<std::size_t>(j) + 1] = static_cast<int>(rows.size());
  }
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse pattern{};
  pattern.nrow = pattern.ncol = static_cast<std::size_t>(interiorCount);
  pattern.nzmax = rows.size();
  pattern.p = columnStart.data();
  pattern.i = rows.data();
  pattern.stype = -1;  // symmetric, lower triangle stored
  pattern.itype = CHOLMOD_INT;
  pattern.xtype = CHOLMOD_PATTERN;
  pattern.dtype = CHOLMOD_DOUBLE;
  pattern.sorted = 1;
  pattern.packed = 1;
  InteriorOrder order(static_cast<std::size_t>(interiorCount));
  const int ok = cholmod_metis(&pattern, nullptr, 0, /*postorder=*/1, order.data(), &common);
  cholmod_finish(&common);
  if (!ok) order.clear();
  return order;
#else
  return {};
#endif
}

std::shared_future<InteriorOrder> metisInteriorOrderInBackground(const Tets& tets,
                                                                 int surfaceVertexCount,
                                                                 int vertexCount) {
  if (!kHaveMetis || vertexCount - surfaceVertexCount < kMetisOnlyInteriorVertices) return {};
  // A thread beside TBB's: not when the caller allowed one (--threads 1).
  if (tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) < 2) {
    return {};
  }
  // The copy of the tets is freed as soon as the order is made, and so is
  // what the thread's malloc arena keeps of its work space (glibc returns a
  // thread arena's free pages only when trimmed): without both, bench_meshing's
  // 1 M row peaked at 1090 MB instead of 1013 MB, with the trim alone at 1039.
  return std::async(std::launch::async,
                    [copy = tets, surfaceVertexCount, vertexCount]() mutable {
                      InteriorOrder order =
                          metisInteriorOrder(copy, surfaceVertexCount, vertexCount);
                      copy = Tets();
                      malloc_trim(0);
                      return order;
                    })
      .share();
}

InteriorOrder extendedInteriorOrder(const InteriorOrder& order, int interiorCount) {
  const std::size_t ordered = order.size();
  const auto count = static_cast<std::size_t>(std::max(interiorCount, 0));
  if (ordered == 0 || ordered > count || kAppendedPerOrdered * (count - ordered) > ordered) {
    return {};
  }
  std::vector<char> seen(ordered, 0);
  for (int v : order) {
    if (v < 0 || static_cast<std::size_t>(v) >= ordered || seen[static_cast<std::size_t>(v)]) {
      return {};
    }
    seen[static_cast<std::size_t>(v)] = 1;
  }
  InteriorOrder extended = order;
  extended.reserve(count);
  for (std::size_t v = ordered; v < count; ++v) extended.push_back(static_cast<int>(v));
  return extended;
}

}  // namespace tetblend
