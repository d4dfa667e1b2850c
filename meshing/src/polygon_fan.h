#pragma once
// Internal: the faces the surface readers meet, polygons of three or more
// corners, and their split into triangles.

#include <cstddef>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend::detail {

/// Faces as read: their corner indices back to back; face f has the corners
/// corners[start[f]] .. corners[start[f + 1] - 1].
struct PolygonFaces {
  std::vector<int> corners;
  std::vector<std::size_t> start{0};

  /// Ends the face whose corners were appended since the last call.
  void closeFace() { start.push_back(corners.size()); }
};

/// Each face split into the fan from its first corner, (c0, ci, ci+1) for
/// i = 1 .. n-2, in face order; a triangle stays as it is. The split depends
/// on the corner lists alone, so a rest and its examples, which share their
/// faces, get the same triangles.
Triangles fanTriangles(const PolygonFaces& faces);

}  // namespace tetblend::detail
