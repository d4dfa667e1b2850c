// Spatial order of a tet mesh: tets along a Morton (Z-order) curve of their
// centroids, interior vertices in the order the sorted tets first use them,
// surface vertices untouched. Consecutive tets then share vertices, so every
// pass over a range of tets (placement, blending, the stitch's right-hand
// side) touches a compact set of vertices.
#pragma once

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// `mesh` renumbered into spatial order: the tets sorted by the Morton code
/// of their centroid (21 bits per axis over the bounding box; ties keep the
/// input order), each tet's corners in their input order; vertices
/// [0, surfaceVertexCount) keep their indices and positions, the others are
/// numbered from surfaceVertexCount in the order the sorted tets first use
/// them (a vertex no tet uses keeps its relative order, after them). The
/// same tets and positions, so volumes, orientation and boundary are
/// unchanged.
TetMesh inSpatialOrder(const TetMesh& mesh, int surfaceVertexCount);

}  // namespace tetblend
