#pragma once
// Closing the holes of an open surface without adding vertices, so that an
// open rest (a scan, a game character) can be tetrahedralised: every example
// shares the rest's vertices, so the same fill triangles close every example,
// and the surface vertices stay bit for bit and in order. Each hole is
// triangulated by CGAL's minimum-weight hole triangulation (Liepa 2003,
// CGAL::Polygon_mesh_processing::triangulate_hole), searched among the faces
// of the 3D Delaunay triangulation of the hole's boundary first.

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The triangles that close a surface's holes.
struct HoleFilling {
  /// #T by 3 vertex indices into the surface's vertices; oriented like the
  /// surface, so the surface's faces followed by these form a closed,
  /// consistently oriented surface. Empty when the surface is closed.
  Triangles triangles;
  int holeCount = 0;  ///< boundary loops closed
};

/// Finds the boundary loops of `surface` (#V by 3 positions, #F by 3
/// indices, read from `sourceName`, used in messages only) and triangulates
/// each without adding vertices; no fill edge duplicates an edge of the
/// surface (for holes through a pinched vertex, below, the closed surface's
/// validation checks that). A closed surface gets no triangles (and is not
/// checked further). Otherwise the surface must be an oriented manifold with
/// boundary, but for pinched vertices: a vertex on four boundary edges where
/// two fans of faces meet (two holes touching there, or one touching
/// itself). At such a vertex each hole goes on in the other fan, and its
/// fill (CGAL's triangulate_hole_polyline) takes a corner of its own there,
/// which makes the closed surface manifold. Throws InputError naming the
/// vertex for any other vertex on more than two boundary edges, the first
/// other problem of validateSurface (without the closed and
/// self-intersection checks) if there is one, and naming the hole if CGAL
/// finds no triangulation of it. Whether the fill intersects the surface is
/// not checked here (validate the closed surface).
///
/// `poses` (positions of the surface's vertices in the examples, which
/// share the fill) steer each hole's fill away from folding: where the
/// rest's fill turns by more than 90° across one of its edges in some pose,
/// CGAL's fill of the hole in that pose replaces it if it folds less over
/// the rest and all poses, cuts no face at the rest and cuts the surface in
/// no more poses (hole_refill.h).
/// Holes through a pinched vertex keep the rest's fill. Throws InputError
/// if a pose has another vertex count or a non-finite position.
HoleFilling fillHoles(const SurfaceMesh& surface, const std::string& sourceName,
                      const std::vector<Vertices>& poses = {});

}  // namespace tetblend
