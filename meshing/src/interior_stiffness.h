#pragma once
// Private: the vertex stars of a rest tet mesh and the blocks of its P1
// stiffness matrix K = Σ_t vol_t G_tᵀ G_t (G_t: 3 by 4 gradients of the
// barycentric coordinates) split into interior (I) and surface (B) vertices,
// for the compatible-tet builder. Vertices 0..#S-1 are the surface vertices.

#include <vector>

#include <Eigen/SparseCore>

#include "tet_elements.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Tets around each vertex in CSR form: the tets of vertex v are
/// tets[start[v] .. start[v+1]), ascending.
struct VertexStars {
  std::vector<int> start;  ///< #V + 1 offsets
  std::vector<int> tets;   ///< 4 #T tet indices
};

/// Stars of the #V vertices of `tets` (#T by 4, indices in [0, #V)).
VertexStars vertexStars(const Tets& tets, int vertexCount);

/// Checks from the stars that no vertex ≥ `surfaceCount` lies on a boundary
/// face (every face around it is shared by exactly 2 tets) and that no face
/// is shared by more than 2 tets. Throws InputError naming the first
/// offending vertex.
void requireInteriorVerticesInside(const Tets& tets, const VertexStars& stars, int surfaceCount);

/// K_II (lower triangle only, column-major, #I by #I) and K_IB (row-major,
/// #I by #S) with #I = #V − #S, entries in units of length (vol · |∇λ|²).
struct StiffnessBlocks {
  Eigen::SparseMatrix<double> interiorLower;
  Eigen::SparseMatrix<double, Eigen::RowMajor> coupling;
};

/// Assembles the blocks, one interior vertex (a column of K_II's lower
/// triangle and a row of K_IB) per task from its star, so the sums run in a
/// fixed order whatever the threads.
StiffnessBlocks assembleStiffnessBlocks(const Tets& tets, const std::vector<TetElement>& elements,
                                        const VertexStars& stars, int surfaceCount);

}  // namespace tetblend
