// Skinning deformations declared in procedural_shapes.h: linear blend
// skinning and dual-quaternion skinning (Kavan et al. §3.4 DLB, §4).

#include <string>
#include <vector>

#include "tetblend/core/dual_quaternion.h"
#include "tetblend/core/dual_quaternion_blend.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

void checkSkinningInput(const Vertices& vertices, const Eigen::MatrixXd& weights,
                        const std::vector<Eigen::Isometry3d>& bones, const char* function) {
  if (weights.rows() != vertices.rows() ||
      weights.cols() != static_cast<Eigen::Index>(bones.size()) || bones.empty()) {
    throw InputError(std::string(function) + ": weights are " + std::to_string(weights.rows()) +
                     " by " + std::to_string(weights.cols()) + " but there are " +
                     std::to_string(vertices.rows()) + " vertices and " +
                     std::to_string(bones.size()) + " bones (need at least one bone)");
  }
}

}  // namespace

Vertices linearBlendSkinning(const Vertices& vertices, const Eigen::MatrixXd& weights,
                             const std::vector<Eigen::Isometry3d>& bones) {
  checkSkinningInput(vertices, weights, bones, "linearBlendSkinning");
  Vertices result(vertices.rows(), 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const Eigen::Vector3d p = vertices.row(v).transpose();
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    for (size_t b = 0; b < bones.size(); ++b) {
      q += weights(v, static_cast<Eigen::Index>(b)) * (bones[b] * p);
    }
    result.row(v) = q.transpose();
  }
  return result;
}

Vertices dualQuaternionSkinning(const Vertices& vertices, const Eigen::MatrixXd& weights,
                                const std::vector<Eigen::Isometry3d>& bones) {
  checkSkinningInput(vertices, weights, bones, "dualQuaternionSkinning");
  // Unit dual quaternions of the bones (Kavan et al. eq. 1), blended per
  // vertex by DLB (Kavan et al. §4), which picks the antipodes.
  std::vector<DualQuaternion> dq;
  for (const Eigen::Isometry3d& bone : bones)
    dq.push_back(DualQuaternion::fromRigid(bone.matrix()));
  std::vector<double> w(bones.size());
  Vertices result(vertices.rows(), 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    for (std::size_t b = 0; b < dq.size(); ++b) w[b] = weights(v, static_cast<Eigen::Index>(b));
    DualQuaternion blended;
    try {
      blended = dlb(dq, w);
    } catch (const DomainError&) {
      throw DomainError("dualQuaternionSkinning: blended dual quaternion of vertex " +
                        std::to_string(v) + " has a zero real part (weights cancel)");
    }
    result.row(v) = blended.transformPoint(vertices.row(v).transpose()).transpose();
  }
  return result;
}

}  // namespace tetblend
