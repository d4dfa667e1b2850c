#pragma once
// Closed components that overlap one another (a game character's eyes or
// teeth through its head, bones through one another) bound no single solid
// that TetGen could mesh, but each bounds a solid of its own. The blend does
// not mind tets of different components overlapping: components share no
// tet, and each is stitched and translated on its own (stitch_solver.h). So
// each component is meshed alone and the meshes are joined.

#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {

/// Some faces of a surface, on their own vertices.
struct SurfacePart {
  SurfaceMesh surface;          ///< the faces, indexing the part's vertices
  std::vector<int> vertexRows;  ///< per part vertex, its row in the whole (ascending)
};

/// The faces of `surface` that `faceComponent` (#F labels) labels
/// `component`, on the vertices they use, in the surface's order.
SurfacePart surfacePart(const SurfaceMesh& surface, const std::vector<int>& faceComponent,
                        int component);

/// Per face of `triangles`, its region: faces joined through edges that
/// exactly two faces share, so that an edge of three or more faces (a fin
/// on a body, two parts touching along an edge) parts the regions meeting
/// there. Faces with a repeated index get -1. Returns the region count;
/// regions are numbered by their first face. Without such edges the regions
/// are surfaceComponents' components. `splitEdges`, when given, receives
/// the number of such edges.
int manifoldRegions(const Triangles& triangles, std::vector<int>& faceRegion,
                    int* splitEdges = nullptr);

/// Tetrahedralises the faces of each label 0..componentCount-1 of
/// `faceComponent` on their own (tetrahedralize, with `options`) and joins
/// the meshes: rows 0..#V-1 are `surface`'s vertices bit for bit (each used
/// by some face), then each component's Steiner points, component by
/// component; the tets component by component. A refusal names the
/// component's first face and says that its numbers count that component's
/// own faces and vertices.
TetMesh tetrahedralizeEachComponent(const SurfaceMesh& surface,
                                    const std::vector<int>& faceComponent, int componentCount,
                                    const TetGenOptions& options);

}  // namespace tetblend
