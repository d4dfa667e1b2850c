#include "interior_stiffness.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// Vertices per TBB task: a star holds ~20–30 tets, so a few hundred
// microseconds of work per task.
constexpr int kVertexGrain = 1024;

// Runs body(begin, end) on chunks of [first, last) on TBB's threads.
template <typename Body>
void parallelChunks(int first, int last, const Body& body) {
  tbb::parallel_for(
      tbb::blocked_range<int>(first, last, kVertexGrain),
      [&](const tbb::blocked_range<int>& range) { body(range.begin(), range.end()); });
}

// Face status of a vertex's star.
enum FaceStatus : char { kClosed = 0, kOnBoundary = 1, kOverShared = 2 };

}  // namespace

VertexStars vertexStars(const Tets& tets, int vertexCount) {
  VertexStars stars;
  stars.start.assign(static_cast<size_t>(vertexCount) + 1, 0);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) ++stars.start[static_cast<size_t>(tets(t, a)) + 1];
  }
  for (size_t v = 0; v < static_cast<size_t>(vertexCount); ++v) {
    stars.start[v + 1] += stars.start[v];
  }
  stars.tets.resize(static_cast<size_t>(stars.start.back()));
  std::vector<int> fill(stars.start.begin(), stars.start.end() - 1);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      stars.tets[static_cast<size_t>(fill[static_cast<size_t>(tets(t, a))]++)] =
          static_cast<int>(t);
    }
  }
  return stars;
}

void requireInteriorVerticesInside(const Tets& tets, const VertexStars& stars, int surfaceCount) {
  const int vertexCount = static_cast<int>(stars.start.size()) - 1;
  // Each face is examined once, at its smallest corner v, as the key
  // (b << 32 | c) of its other corners b < c: a key may occur at most twice
  // in v's star, and exactly twice if c (the largest corner) is interior.
  std::vector<char> status(static_cast<size_t>(vertexCount), kClosed);
  std::vector<int> offender(static_cast<size_t>(vertexCount), -1);
  parallelChunks(0, vertexCount, [&](int begin, int end) {
    std::vector<std::uint64_t> keys;
    for (int v = begin; v < end; ++v) {
      keys.clear();
      for (int k = stars.start[static_cast<size_t>(v)]; k < stars.start[static_cast<size_t>(v) + 1];
           ++k) {
        std::array<int, 3> others{};
        int n = 0;
        for (int a = 0; a < 4; ++a) {
          const int w = tets(stars.tets[static_cast<size_t>(k)], a);
          if (w != v && n < 3) others[static_cast<size_t>(n++)] = w;
        }
        std::sort(others.begin(), others.end());
        for (int x = 0; x < 3; ++x) {
          for (int y = x + 1; y < 3; ++y) {
            if (others[static_cast<size_t>(x)] > v) {
              keys.push_back(static_cast<std::uint64_t>(others[static_cast<size_t>(x)]) << 32 |
                             static_cast<std::uint32_t>(others[static_cast<size_t>(y)]));
            }
          }
        }
      }
      std::sort(keys.begin(), keys.end());
      for (size_t i = 0; i < keys.size();) {
        size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        const int largest = static_cast<int>(keys[i] & 0xffffffffu);
        if (j - i > 2 || (j - i == 1 && largest >= surfaceCount)) {
          status[static_cast<size_t>(v)] = j - i > 2 ? kOverShared : kOnBoundary;
          offender[static_cast<size_t>(v)] = j - i > 2 ? v : largest;
          break;
        }
        i = j;
      }
    }
  });
  const auto bad = std::find_if(status.begin(), status.end(), [](char s) { return s != kClosed; });
  if (bad == status.end()) return;
  const std::string vertex = std::to_string(offender[static_cast<size_t>(bad - status.begin())]);
  if (*bad == kOverShared) {
    throw InputError("CompatibleTetBuilder: a face at vertex " + vertex +
                     " is shared by more than 2 tets; a tet mesh needs at most 2 (non-manifold "
                     "or duplicated tets)");
  }
  throw InputError("CompatibleTetBuilder: vertex " + vertex +
                   " lies on the boundary but is not among the first " +
                   std::to_string(surfaceCount) +
                   " (surface) vertices; reorder with reorderBoundaryFirst");
}

StiffnessBlocks assembleStiffnessBlocks(const Tets& tets, const std::vector<TetElement>& elements,
                                        const VertexStars& stars, int surfaceCount) {
  const int vertexCount = static_cast<int>(stars.start.size()) - 1;
  const int interiorCount = vertexCount - surfaceCount;
  // Row v of K for each interior vertex v: its entries K(v, w), ascending in
  // w, accumulated in a per-task sparse accumulator (slot[w]: position of w in
  // the row, or -1) in star order, so each sum has a fixed order.
  std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(interiorCount));
  parallelChunks(0, interiorCount, [&](int begin, int end) {
    std::vector<int> slot(static_cast<size_t>(vertexCount), -1);
    std::vector<std::pair<int, double>> row;
    for (int i = begin; i < end; ++i) {
      const int v = surfaceCount + i;
      row.clear();
      for (int k = stars.start[static_cast<size_t>(v)]; k < stars.start[static_cast<size_t>(v) + 1];
           ++k) {
        const int t = stars.tets[static_cast<size_t>(k)];
        const TetElement& element = elements[static_cast<size_t>(t)];
        int a = 0;
        while (tets(t, a) != v) ++a;
        for (int b = 0; b < 4; ++b) {
          const int w = tets(t, b);
          int& position = slot[static_cast<size_t>(w)];
          if (position < 0) {
            position = static_cast<int>(row.size());
            row.emplace_back(w, 0.0);
          }
          row[static_cast<size_t>(position)].second +=
              element.volume * element.gradients.col(a).dot(element.gradients.col(b));
        }
      }
      for (const auto& entry : row) slot[static_cast<size_t>(entry.first)] = -1;
      std::sort(row.begin(), row.end());
      rows[static_cast<size_t>(i)] = row;
    }
  });
  // K_II's lower triangle by columns (column i: rows w − #S for w ≥ v) and
  // K_IB by rows (row i: columns w < #S); both from row i of K by symmetry.
  StiffnessBlocks blocks;
  blocks.interiorLower.resize(interiorCount, interiorCount);
  blocks.coupling.resize(interiorCount, surfaceCount);
  Eigen::Index lowerCount = 0;
  Eigen::Index couplingCount = 0;
  for (int i = 0; i < interiorCount; ++i) {
    for (const auto& entry : rows[static_cast<size_t>(i)]) {
      if (entry.first >= surfaceCount + i) ++lowerCount;
      if (entry.first < surfaceCount) ++couplingCount;
    }
  }
  blocks.interiorLower.resizeNonZeros(lowerCount);
  blocks.coupling.resizeNonZeros(couplingCount);
  Eigen::Index lower = 0;
  Eigen::Index coupling = 0;
  for (int i = 0; i < interiorCount; ++i) {
    blocks.interiorLower.outerIndexPtr()[i] = static_cast<int>(lower);
    blocks.coupling.outerIndexPtr()[i] = static_cast<int>(coupling);
    for (const auto& [w, value] : rows[static_cast<size_t>(i)]) {
      if (w >= surfaceCount + i) {
        blocks.interiorLower.innerIndexPtr()[lower] = w - surfaceCount;
        blocks.interiorLower.valuePtr()[lower++] = value;
      } else if (w < surfaceCount) {
        blocks.coupling.innerIndexPtr()[coupling] = w;
        blocks.coupling.valuePtr()[coupling++] = value;
      }
    }
  }
  blocks.interiorLower.outerIndexPtr()[interiorCount] = static_cast<int>(lower);
  blocks.coupling.outerIndexPtr()[interiorCount] = static_cast<int>(coupling);
  return blocks;
}

}  // namespace tetblend
