#pragma once
// Private: boundary edges whose ring of tets is too short for the fold an
// example makes there, for the example-aware tetrahedralisation
// (example_aware_tets.h). The k tets around a boundary edge e share its
// interior dihedral angle θ_e (the solid's opening angle at e), each less
// than π. An example that folds the surface at e into a crease (the inner
// side of a bent joint, θ_e near 2π) or a twist that turns a reflex edge
// further leaves k = 2 tets two nearly flat wedges with one shared apex,
// which no placement of that apex makes valid; a third tet around e gives
// the crease a second apex. Splitting the edge opposite e in one ring tet
// (its two vertices off e) adds that tet.

#include <vector>

#include "tet_stellar_split.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The interior dihedral angle at the boundary edge (a, b) of the outward
/// faces (a, b, p) and (b, a, q) at `positions`: the angle in (0, 2π) swept
/// inside the solid from the half-plane through p to the one through q
/// (π for a flat surface, below π on a convex edge, above on a reflex one).
double interiorDihedralAngle(const Vertices& positions, int a, int b, int p, int q);

/// The dihedral angle in [0, π] of tet (a, b, c, d) at its edge (a, b).
double tetDihedralAngle(const Vertices& positions, int a, int b, int c, int d);

/// A boundary edge (a, b), the third corners p, q of its outward faces
/// (a, b, p) and (b, a, q), and the tets around it.
struct BoundaryEdgeRing {
  int a = 0, b = 0, p = 0, q = 0;
  std::vector<int> tets;
};

/// The ring of every boundary edge of `mesh`, given its outward boundary
/// triangles (boundarySurface), sorted by (smaller, larger) end. Edges not
/// used by exactly two boundary faces, once each way, are left out.
std::vector<BoundaryEdgeRing> boundaryEdgeRings(const TetMesh& mesh, const Triangles& outward);

/// The edges to split so that every ring of `rings` spans each example of
/// `examples` (surface positions, the rest's surface vertex order) with at
/// most `maxTetDihedral` radians per tet: for each ring and example with
/// θ_e > k · maxTetDihedral, the edge opposite e (not on the boundary) in
/// the ring tet with the largest rest dihedral angle at e. Sorted, each once.
std::vector<Simplex> creaseRingSplits(const TetMesh& mesh,
                                      const std::vector<BoundaryEdgeRing>& rings,
                                      const std::vector<const Vertices*>& examples,
                                      const BoundarySimplices& boundary, double maxTetDihedral);

}  // namespace tetblend
