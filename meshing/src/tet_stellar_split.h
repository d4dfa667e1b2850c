#pragma once
// Private: local refinement of a tet mesh by stellar subdivision, for the
// example-aware tetrahedralisation (example_aware_tets.h). Splitting an
// interior edge or face at its centroid p replaces every tet containing it by
// one copy per vertex s of the simplex, with s replaced by p: the copies have
// λ_s(p) times the parent's volume (1/2 for an edge, 1/3 for a face), so they
// keep its orientation and the mesh stays conforming. Boundary edges and
// faces are never split: the boundary is untouched and p is interior.

#include <array>
#include <initializer_list>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// An edge or a face as its vertex indices, ascending (count 2 or 3).
struct Simplex {
  std::array<int, 3> vertices{};
  int count = 0;
  bool operator<(const Simplex& other) const;
  bool operator==(const Simplex& other) const;
};

/// The edge or face through `vertices` (2 or 3 of them), ascending.
Simplex makeSimplex(std::initializer_list<int> vertices);

/// The boundary edges and faces of a tet mesh, sorted (the ones split never).
struct BoundarySimplices {
  std::vector<Simplex> edges;
  std::vector<Simplex> faces;
};

/// The edges and faces of a tet mesh's boundary triangles (boundarySurface's;
/// faces of one tet only).
BoundarySimplices boundarySimplices(const Triangles& triangles);

/// What to split so tet `tet` of `mesh` is replaced by tets with a movable
/// vertex (one >= `surfaceCount`): its interior edges joining two surface
/// vertices, and its interior faces whose three edges lie on the surface
/// (both are fixed by the example surface alone); when it has neither, its
/// longest interior edge (more freedom where an interior vertex already
/// exists); nothing when every edge and face of the tet is on the boundary.
std::vector<Simplex> simplicesToSplit(const TetMesh& mesh, int tet, int surfaceCount,
                                      const BoundarySimplices& boundary);

/// Every interior edge of `mesh` joining two surface vertices (< surfaceCount)
/// and every interior face whose three vertices lie on the surface, once
/// each, sorted (edges first): the simplices the example surfaces alone fix.
std::vector<Simplex> rigidSimplices(const TetMesh& mesh, int surfaceCount,
                                    const BoundarySimplices& boundary);

/// Splits each simplex of `simplices` (distinct interior edges and faces of
/// `mesh`, edges first) at its centroid, in order. New vertices are appended
/// after the existing ones (a mesh with surface vertices first keeps them
/// first); each split tet keeps its index for its first copy, the others are
/// appended. Throws InputError if a simplex is not in the mesh.
TetMesh splitSimplices(const TetMesh& mesh, const std::vector<Simplex>& simplices);

}  // namespace tetblend
