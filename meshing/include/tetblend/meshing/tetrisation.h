#pragma once
// Surface "tetrisation": one tetrahedron per triangle, for open or
// non-watertight surfaces that TetGen cannot fill. The per-tet affine map of
// the shape blender then sends the rest triangle to the example triangle and
// the rest normal to the example normal (Kaji–Ochiai §6.2; Sumner & Popović
// 2004, "Deformation Transfer for Triangle Meshes", §3, eq. 1 — the fourth
// vertex along the normal, scaled by the square root of the face size).
//
// Vertex layout of the result: the #V surface vertices first, unchanged and in
// input order, then one apex per face (vertex #V + f for face f). Tet f is
// (t0, t1, t2, #V + f) for triangle f = (t0, t1, t2), so it is positively
// oriented (det[p1-p0, p2-p0, p3-p0] > 0) because the apex lies on the side of
// the triangle's counter-clockwise normal.

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Tetrises `surface` (#V by 3 positions, #F by 3 triangles): returns
/// #V + #F vertices and #F tets in the layout above. The apex of face f is
///   c_f + n_f * sqrt(|(p1 - p0) x (p2 - p0)|),
/// where c_f is the centroid and n_f the unit normal of the face's own
/// triangle: the height is sqrt(2 * area), so a uniformly scaled triangle gets
/// a uniformly scaled tet and similarities stay similarities (Kaji–Ochiai §3,
/// property V). The same rule applied to each example (with the example
/// triangle's normal) gives compatible tet meshes, since the tets depend only
/// on the triangles. Throws InputError naming the face for an index out of
/// range or a face of zero area (no normal), and for non-finite coordinates.
TetMesh tetrise(const SurfaceMesh& surface);

/// Tetrises `rest` and every example after requireCompatibleExample (names
/// from `exampleNames`, same length as `examples`, used in messages): element
/// 0 is the rest's tet mesh, element k the k-th example's; all share the tets.
std::vector<TetMesh> tetriseCompatible(const SurfaceMesh& rest,
                                       const std::vector<SurfaceMesh>& examples,
                                       const std::vector<std::string>& exampleNames);

}  // namespace tetblend
