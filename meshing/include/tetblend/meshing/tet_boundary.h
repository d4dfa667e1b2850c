#pragma once
// The boundary of a tetrahedral mesh: its outward triangles, and a reordering
// that puts boundary vertices first (the layout TetGen's `Y` switch produces
// and that compatible_tets.h expects: surface vertices 0..#S-1, then interior
// Steiner points).

#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Boundary triangles of `mesh` (faces used by exactly one tet), oriented
/// outwards (counter-clockwise seen from outside) given positively oriented
/// tets. The returned SurfaceMesh holds all of mesh.vertices (#V by 3) and
/// its triangles index them, so interior vertices are present but unused.
/// Throws InputError if a face is shared by more than two tets, or if a
/// tet's corner is not a row of mesh.vertices.
SurfaceMesh boundarySurface(const TetMesh& mesh);

/// boundarySurface(mesh).triangles, the same rows in the same order, for a
/// mesh whose boundary vertices are 0..surfaceVertexCount-1 and whose other
/// vertices are interior (compatible_tets.h's layout): only faces with every
/// corner below surfaceVertexCount can be boundary faces, so only those are
/// grouped (at 1 M tets, a few % of the 4 #T faces). Tets' corners must be
/// rows of the mesh's vertices.
Triangles surfaceFirstBoundary(const Tets& tets, int surfaceVertexCount);

/// A tet mesh renumbered so its boundary vertices come first.
struct BoundaryFirstMesh {
  TetMesh mesh;                 ///< renumbered mesh (same tets, same order)
  int boundaryVertexCount = 0;  ///< #S: vertices 0..#S-1 lie on the boundary
  std::vector<int> newToOld;    ///< #V: newToOld[new index] = old index
  std::vector<int> oldToNew;    ///< #V: inverse permutation
};

/// Renumbers the vertices of `mesh` so those on boundary faces come first,
/// each group keeping its original relative order. Vertices used by no tet
/// count as interior.
BoundaryFirstMesh reorderBoundaryFirst(const TetMesh& mesh);

}  // namespace tetblend
