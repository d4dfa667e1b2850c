#include "interior_ordering.h"

#include <malloc.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#ifdef TETBLEND_HAVE_METIS
#include <metis.h>
#endif

#include "interior_stiffness.h"
#include "tetblend/core/helper_threads.h"

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

#ifdef TETBLEND_HAVE_METIS
constexpr bool kHaveMetis = true;
// METIS_NodeND's refinement passes per level (METIS's default: 10) and the
// imbalance it allows between the two parts of a bisection, in thousandths
// (its default for orderings: 200). Measured on the interior graphs of six
// meshes of 103-162 k interior vertices (bench_meshing's 1 M-tet bar; CGAL's
// armadillo, homer, elephant, knot1 and lion filled by TetGen with a volume
// bound of their volume / 600 k, about 1 M tets), 2026-12-03, METIS called
// alone on each graph: 0.52-0.81 s instead of 0.83-1.36 s (−32 to −40 %),
// the factor's flops −6 % to +5 % (bar +4 %, armadillo +2 %, homer −1 %,
// elephant −6 %, knot1 +5 %, lion +2 %). The default passes with an
// imbalance of 50 saved 19-25 %.
constexpr idx_t kMetisRefinementIterations = 1;
constexpr idx_t kMetisImbalance = 30;
#else
constexpr bool kHaveMetis = false;
#endif

}  // namespace

InteriorOrder metisInteriorOrder([[maybe_unused]] const Tets& tets,
                                 [[maybe_unused]] int surfaceVertexCount,
                                 [[maybe_unused]] int vertexCount) {
#ifdef TETBLEND_HAVE_METIS
  const int interiorCount = vertexCount - surfaceVertexCount;
  if (interiorCount <= 0) return {};
  // K_II's graph for METIS: each interior vertex's interior neighbours
  // (tet corners of its star), both ways, no self loops.
  const VertexStars stars = vertexStars(tets, vertexCount);
  std::vector<idx_t> start(static_cast<std::size_t>(interiorCount) + 1, 0);
  std::vector<idx_t> neighbours;
  // About 14 neighbours per TetGen vertex.
  neighbours.reserve(static_cast<std::size_t>(14) * static_cast<std::size_t>(interiorCount));
  // Each neighbour is taken once (lastVertex: the vertex that last took it).
  std::vector<int> lastVertex(static_cast<std::size_t>(interiorCount), -1);
  for (int j = 0; j < interiorCount; ++j) {
    const int v = surfaceVertexCount + j;
    lastVertex[static_cast<std::size_t>(j)] = j;
    for (int k = stars.start[static_cast<std::size_t>(v)];
         k < stars.start[static_cast<std::size_t>(v) + 1]; ++k) {
      for (int a = 0; a < 4; ++a) {
        const int w = tets(stars.tets[static_cast<std::size_t>(k)], a) - surfaceVertexCount;
        if (w < 0) continue;
        int& last = lastVertex[static_cast<std::size_t>(w)];
        if (last == j) continue;
        last = j;
        neighbours.push_back(w);
      }
    }
    start[static_cast<std::size_t>(j) + 1] = static_cast<idx_t>(neighbours.size());
  }
  std::array<idx_t, METIS_NOPTIONS> options{};
  METIS_SetDefaultOptions(options.data());
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_NITER] = kMetisRefinementIterations;
  options[METIS_OPTION_UFACTOR] = kMetisImbalance;
  idx_t count = interiorCount;
  std::vector<idx_t> order(static_cast<std::size_t>(interiorCount));
  std::vector<idx_t> inverse(static_cast<std::size_t>(interiorCount));
  if (METIS_NodeND(&count, start.data(), neighbours.data(), nullptr, options.data(), order.data(),
                   inverse.data()) != METIS_OK) {
    return {};
  }
  return InteriorOrder(order.begin(), order.end());
#else
  return {};
#endif
}

std::shared_future<InteriorOrder> metisInteriorOrderInBackground(const Tets& tets,
                                                                 int surfaceVertexCount,
                                                                 int vertexCount) {
  if (!kHaveMetis || vertexCount - surfaceVertexCount < kMetisOnlyInteriorVertices) return {};
  if (!helperThreadAllowed()) return {};
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
