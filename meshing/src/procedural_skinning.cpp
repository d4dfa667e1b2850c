// Skinning deformations declared in procedural_shapes.h: linear blend
// skinning and dual-quaternion skinning (Kavan et al. §3.4 DLB, §4).

#include <string>
#include <vector>

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

// Unit dual quaternion q_r + ε q_d of a rigid motion: q_d = ½ (0, t) q_r
// (Kavan et al. §3.3).
struct UnitDualQuaternion {
  Eigen::Quaterniond real;
  Eigen::Quaterniond dual;
};

UnitDualQuaternion toDualQuaternion(const Eigen::Isometry3d& motion) {
  UnitDualQuaternion q;
  q.real = Eigen::Quaterniond(motion.linear());
  const Eigen::Vector3d t = motion.translation();
  const Eigen::Quaterniond translation(0.0, t.x(), t.y(), t.z());
  q.dual.coeffs() = 0.5 * (translation * q.real).coeffs();
  return q;
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
  std::vector<UnitDualQuaternion> dq;
  for (const Eigen::Isometry3d& bone : bones) {
    dq.push_back(toDualQuaternion(bone));
    // Antipodality: align every bone with the first (shortest path, §3.4).
    if (dq.back().real.coeffs().dot(dq.front().real.coeffs()) < 0.0) {
      dq.back().real.coeffs() *= -1.0;
      dq.back().dual.coeffs() *= -1.0;
    }
  }
  Vertices result(vertices.rows(), 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    Eigen::Vector4d real = Eigen::Vector4d::Zero();
    Eigen::Vector4d dual = Eigen::Vector4d::Zero();
    for (size_t b = 0; b < dq.size(); ++b) {
      const double w = weights(v, static_cast<Eigen::Index>(b));
      real += w * dq[b].real.coeffs();
      dual += w * dq[b].dual.coeffs();
    }
    const double norm = real.norm();
    if (!(norm > 0.0)) {
      throw DomainError("dualQuaternionSkinning: blended dual quaternion of vertex " +
                        std::to_string(v) + " has a zero real part (weights cancel)");
    }
    Eigen::Quaterniond r;
    r.coeffs() = real / norm;
    Eigen::Quaterniond d;
    d.coeffs() = dual / norm;
    // Translation = vector part of 2 q_d conj(q_r) (Kavan et al. Alg. 1).
    const Eigen::Vector3d t = 2.0 * (d * r.conjugate()).vec();
    result.row(v) = (r * vertices.row(v).transpose() + t).transpose();
  }
  return result;
}

}  // namespace tetblend
