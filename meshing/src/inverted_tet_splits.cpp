#include "inverted_tet_splits.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "crease_rings.h"
#include "tetblend/core/constants.h"

namespace tetblend {
namespace {

// The widest dihedral angle a tet around a boundary edge is left when a
// clean example keeps a tet there inverted (creaseRingSplits): a ring of k
// tets whose example opens the edge by more than k × 150° gets a tet more.
// A tet's volume on given faces goes with the sine of that angle (½ at
// 150°). The femur's crease (355° over 2 tets) is caught by any bound below
// 177.5°; only 150° was measured (2026-11-29, the README's The untangler).
constexpr double kCreaseTetDihedral = 150.0 * kPi / 180.0;

// `tets` of `mesh` and every tet sharing a vertex with one of them, sorted.
std::vector<int> tetsSharingAVertex(const TetMesh& mesh, const std::vector<int>& tets) {
  std::vector<char> touched(static_cast<std::size_t>(mesh.vertices.rows()), 0);
  for (int t : tets) {
    for (int c = 0; c < 4; ++c) touched[static_cast<std::size_t>(mesh.tets(t, c))] = 1;
  }
  std::vector<int> result;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      if (touched[static_cast<std::size_t>(mesh.tets(t, c))]) {
        result.push_back(static_cast<int>(t));
        break;
      }
    }
  }
  return result;
}

}  // namespace

// Splitting a tet's longest edge never adds a tet around its boundary edges:
// the new vertex becomes the shared apex of both boundary faces again. A
// 540° twist of CGAL's femur folded a reflex edge with two tets into a
// 355° crease, and its tet stayed inverted through every round: hence the
// crease rings first.
std::vector<Simplex> splitsForInverted(const TetMesh& mesh, const std::vector<int>& inverted,
                                       const Vertices& exampleSurface, const Triangles& outward,
                                       int surfaceCount, const BoundarySimplices& boundary) {
  const std::vector<BoundaryEdgeRing> rings = boundaryEdgeRings(mesh, outward);
  auto ends = [](int u, int v) { return std::pair(std::min(u, v), std::max(u, v)); };
  auto ringOf = [&](int u, int v) -> const BoundaryEdgeRing* {
    const auto found = std::lower_bound(rings.begin(), rings.end(), ends(u, v),
                                        [&](const BoundaryEdgeRing& ring, std::pair<int, int> key) {
                                          return ends(ring.a, ring.b) < key;
                                        });
    return found != rings.end() && ends(found->a, found->b) == ends(u, v) ? &*found : nullptr;
  };
  const std::vector<const Vertices*> example = {&exampleSurface};
  std::vector<Simplex> simplices;
  for (int t : tetsSharingAVertex(mesh, inverted)) {
    std::vector<BoundaryEdgeRing> around;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        if (const BoundaryEdgeRing* ring = ringOf(mesh.tets(t, i), mesh.tets(t, j))) {
          around.push_back(*ring);
        }
      }
    }
    std::vector<Simplex> splits =
        creaseRingSplits(mesh, around, example, boundary, kCreaseTetDihedral);
    if (splits.empty()) splits = simplicesToSplit(mesh, t, surfaceCount, boundary);
    simplices.insert(simplices.end(), splits.begin(), splits.end());
  }
  std::sort(simplices.begin(), simplices.end());
  simplices.erase(std::unique(simplices.begin(), simplices.end()), simplices.end());
  return simplices;
}

}  // namespace tetblend
