#pragma once
// Private: per-tet P1 finite-element data of a rest mesh, shared by the
// compatible-tet builder and the untangling step.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Rest data of one tet: the deformation gradient of corner positions
/// X (3 by 4, corners as columns) is F = X * gradients^T.
struct TetElement {
  Eigen::Matrix<double, 3, 4> gradients;  ///< gradients of the 4 barycentric coordinates
  double volume = 0.0;                    ///< rest volume (> 0)
};

/// Elements of every tet of `mesh`. Throws InputError naming the first tet
/// whose rest volume is not positive or whose index is out of range.
std::vector<TetElement> buildTetElements(const TetMesh& mesh);

/// `elements` of `mesh` with every sliver thickened, for the untangler's
/// second attempt (compatible_tets.cpp): a tet whose edge matrix
/// D = [x1-x0, x2-x0, x3-x0] has singular values below minSingularRatio
/// times its largest gets those raised to that bound (D = U Σ Vᵀ → U Σ' Vᵀ),
/// its gradients and volume from the thickened D; the others are copied.
/// Only the sign of det F decides validity, and it is the same for any
/// positive reference shape; the thickened one keeps det F of a sliver
/// whose example is slightly inverted small, where the rest's own makes it
/// about −1/(the sliver's relative height).
std::vector<TetElement> thickenedTetElements(const TetMesh& mesh,
                                             const std::vector<TetElement>& elements,
                                             double minSingularRatio);

/// Deformation gradient of tet `t` under `positions` (#V by 3). Inline: the
/// untangling and ARAP loops call it for every tet of every evaluation.
inline Eigen::Matrix3d deformationGradient(const Vertices& positions, const Eigen::RowVector4i& tet,
                                           const TetElement& element) {
  Eigen::Matrix<double, 3, 4> corners;
  for (int a = 0; a < 4; ++a) corners.col(a) = positions.row(tet(a)).transpose();
  return corners * element.gradients.transpose();
}

/// Rotation closest to `f` in the Frobenius norm (SVD, reflection removed);
/// defined for every f, including det f <= 0.
Eigen::Matrix3d closestRotation(const Eigen::Matrix3d& f);

/// out[i] = the rotation closest to f[i], i < n: the elements with
/// det f > 0 through core's batched polar rotation (the closed form,
/// vectorised: 22 M/s against the Newton iteration's 2.6 M/s in bench_core's
/// polar_rotation rows), the others, and a batch whose Newton fallback
/// fails, one by one (core's polarDecompose, else closestRotation's SVD).
void closestRotations(const Eigen::Matrix3d* f, Eigen::Matrix3d* out, std::size_t n);

}  // namespace tetblend
