#pragma once
// Private: ARAP's local/global iteration (Sorkine & Alexa 2007, on tets as
// in CompatibleTetBuilder's arapSearch) over a region of free vertices,
// every other vertex held where it is. For examples whose surface
// intersects itself, ARAP only matters near the fold: the harmonic map is
// already valid elsewhere, and the fold's tets are excluded from the stitch
// whatever the placement does there.

#include <vector>

#include "interior_stiffness.h"
#include "tet_elements.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// When a local ARAP search stops (the global search's rules).
struct LocalArapStops {
  int maxIterations = 5;
  double tolerance = 0.0;     ///< largest vertex move (length) that counts as converged
  double stallFall = 0.0;     ///< relative energy fall below which it stalls
  bool stopWhenValid = true;  ///< end at the first state without inverted tets
};

/// Moves the vertices `region` (distinct vertex indices; stars: of `tets`)
/// by ARAP iterations from `positions`, the other vertices fixed, and
/// leaves `positions` at the state with the fewest inverted tets among those
/// touching the region, then the lowest ARAP energy there (the start is a
/// candidate). Returns the iterations performed.
int localArap(const Tets& tets, const std::vector<TetElement>& elements, const VertexStars& stars,
              const std::vector<int>& region, const LocalArapStops& stops, Vertices& positions);

}  // namespace tetblend
