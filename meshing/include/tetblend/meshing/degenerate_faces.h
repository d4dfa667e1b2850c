#pragma once
// Degenerate faces of a closed surface, flipped away for meshing. Scans and
// exporters leave faces of (almost) zero area: three vertices on one line,
// the middle one a vertex of the faces along the line's other side. TetGen
// cannot mesh such a face, and removing it per frame would break the
// correspondence between the rest and the examples. Instead the face and its
// neighbour across its longest edge are re-split along the other diagonal
// (from the face's middle vertex to the neighbour's far vertex): the two new
// faces split the neighbour, so the surface keeps its shape, its vertices
// and its face count, and only the meshing sees the change (the blended
// surfaces keep the input's faces).

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// What flipDegenerateFaces did.
struct DegenerateFaceFlips {
  int flipped = 0;  ///< degenerate faces flipped away
  int left = 0;     ///< degenerate faces no flip could remove (for the validation to name)
};

/// A face is also degenerate for flipDegenerateFaces when its vertex
/// opposite its longest edge is within this fraction of that edge's length
/// of the edge's line (2 area < ratio × longest edge²): a cap whose middle
/// vertex an exporter's welding left just off the edge. Its tet has almost
/// no rest volume, and an example that moves the middle vertex across the
/// edge turns the face over: 48 gallop-like frames of CGAL's triceratops
/// (two caps of relative height 3e-6) kept 1 inverted tet each in 2 clean
/// frames; CGAL's elephant with 30 caps of relative height up to 1e-4 had 13
/// of 16 skinned frames reported as intersecting themselves, 33 to 54 tets
/// excluded. Re-split, the meshing surface departs from the input's by at
/// most this fraction of an edge, where the cap lies.
constexpr double kCapRelativeHeight = 1e-3;

/// Flips every face of `mesh` whose area is below `zeroAreaRelTol` times the
/// squared bounding-box diagonal (surface_validation.h's zero-area rule), or
/// which is a cap of relative height below `capRelHeight`
/// (kCapRelativeHeight), and whose three vertices differ: with its
/// neighbour across its longest edge
/// u v, faces (u, v, c) and (v, u, d) become (u, d, c) and (d, v, c), in
/// place (face numbers kept). A flip is skipped when the edge has no
/// neighbour running it the other way (a boundary or an inconsistent
/// orientation), when the edge c d exists already (it would become
/// non-manifold), or when a new face would be degenerate too (a needle, a
/// face with one short edge, is therefore kept); a face is tried again after
/// its neighbours change, so runs of collinear faces resolve one by one.
DegenerateFaceFlips flipDegenerateFaces(SurfaceMesh& mesh, double zeroAreaRelTol,
                                        double capRelHeight = kCapRelativeHeight);

}  // namespace tetblend
