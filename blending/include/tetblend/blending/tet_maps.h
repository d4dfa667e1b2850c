#pragma once
// Per-tet affine maps from the rest mesh to each example: the deformation
// gradients F_kj = D_kj D_0j^-1 of the shape blender (Kaji–Ochiai §6.2, the
// A_ij restricted to their linear parts; Sumner–Popović deformation transfer).
// The translation parts are not stored: the stitch only needs the linear
// parts, and translations are fixed afterwards by the blended centroids.

#include <Eigen/Core>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// The rest mesh's per-tet data that every map and the stitch need.
struct RestTetData {
  /// #T inverse edge matrices D_0j^-1 (edges p1-p0, p2-p0, p3-p0 as columns).
  std::vector<Eigen::Matrix3d> inverseEdges;
  /// #T rest volumes (positive; NaN, with a NaN inverse, only for flat tets
  /// a caller leaves out: restTetData's `mayBeFlat`), in the rest mesh's
  /// length unit cubed.
  std::vector<double> volumes;
};

/// Checks that every rest tet is positively oriented and non-degenerate and
/// returns its inverse edge matrix and volume. `rest` holds #V vertices and
/// #T by 4 tets. The tets in `mayBeFlat` (ascending indices; a model's
/// excluded tets) are not checked: where their volume is <= 0 they get a
/// NaN volume and inverse. Throws InputError naming the first other tet with
/// volume <= 0 or an index outside [0, #V).
RestTetData restTetData(const TetMesh& rest, const std::vector<int>& mayBeFlat = {});

/// Deformation gradients F_j = D_example,j D_rest,j^-1 (3 by 3, #T of them)
/// of one example whose vertices (#V by 3, same order as the rest) are
/// `example`. `exampleIndex` (0-based) only names the example in error
/// messages, counted from 1 there as in `tetblend inspect`.
/// Throws InputError naming the example, the tet and its signed volume when an
/// example tet has volume <= 0 (an inverted or flat example is never blended
/// silently), and when the vertex count differs from the rest.
std::vector<Eigen::Matrix3d> deformationGradients(const TetMesh& rest, const RestTetData& restData,
                                                  const Vertices& example, int exampleIndex);

}  // namespace tetblend
