#pragma once
// Private: does a segment or triangle between surface vertices lie inside the
// solid a closed, clean surface bounds? Exact predicates (CGAL); the header
// is CGAL-free (CGAL stays in meshing's CGAL object library).
//
// Why: a valid tet mesh of a clean example (every tet positively oriented,
// its boundary mapped onto the example surface) covers exactly the solid the
// surface bounds. An interior edge or face of the rest mesh whose vertices
// all lie on the surface is fixed by the example alone, so when it leaves the
// example's solid no placement of the interior vertices can make every tet
// valid; example_aware_tets.cpp splits such simplices before any placement.

#include <memory>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

class SurfaceInterior {
 public:
  /// `vertices` (#V by 3) and `triangles` (#F by 3): a closed, consistently
  /// oriented surface without self-intersections (not checked; a surface
  /// that cannot be built as a manifold mesh makes every answer true).
  SurfaceInterior(const Vertices& vertices, const Triangles& triangles);
  ~SurfaceInterior();
  SurfaceInterior(const SurfaceInterior&) = delete;
  SurfaceInterior& operator=(const SurfaceInterior&) = delete;

  /// False when the segment between vertices a and b (distinct) meets a face
  /// that has neither as a corner, or when its midpoint lies outside; true
  /// when it lies in the closed solid.
  bool segmentInside(int a, int b) const;

  /// False when the triangle of vertices a, b, c meets a face other than at
  /// the corners and edges they share, or when its centroid lies outside.
  /// (A face sharing an edge with it meets it elsewhere only when coplanar
  /// and folded onto it: not tested.)
  bool triangleInside(int a, int b, int c) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetblend
