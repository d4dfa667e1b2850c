#include "tetblend/blending/lie_bodies_blend.h"

#include "blend_common.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/lie_bodies.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

TetCorners tetCorners(const Vertices& vertices, const Eigen::RowVector4i& tet) {
  TetCorners corners;
  for (int c = 0; c < 4; ++c) corners.col(c) = vertices.row(tet(c)).transpose();
  return corners;
}

class LieBodiesBlender final : public TetMapBlender {
 public:
  explicit LieBodiesBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    restBodies_.resize(tets_);
    logs_.resize(static_cast<size_t>(tets_) * examples_);
    lifts_.resize(logs_.size());
    corrected_.assign(tets_, 0);
    const TetMesh& rest = *input.rest;
    blend_detail::forEachTet(tets_, [&](int j) {
      try {
        restBodies_[j] = lieBodyFromCorners(tetCorners(rest.vertices, rest.tets.row(j)));
      } catch (const DomainError& error) {
        blend_detail::rethrowForTet("liebodies (rest)", -1, j, error);
      }
    });
    std::vector<LieBody> bodies(tets_);
    std::vector<Eigen::Matrix3d> worldRotations(tets_);
    for (int k = 0; k < examples_; ++k) {
      const Vertices& example = (*input.examples)[k];
      blend_detail::forEachTet(tets_, [&](int j) {
        try {
          bodies[j] = lieBodyFromCorners(tetCorners(example, rest.tets.row(j)));
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("liebodies", k, j, error);
        }
        worldRotations[j] = lieBodyWorldRotation(restBodies_[j], bodies[j]);
      });
      const std::vector<RotationLift> lifts = rotationLifts(
          worldRotations, *input.adjacency, *input.components, input.rotationConsistency);
      blend_detail::forEachTet(tets_, [&](int j) {
        const size_t slot = static_cast<size_t>(j) * examples_ + k;
        try {
          logs_[slot] = lieBodyRelativeLog(restBodies_[j], bodies[j]);
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("liebodies", k, j, error);
        }
        logs_[slot].rigid.setZero();  // the rotation is blended as a lift below
        lifts_[slot] = lifts[j];
        if (!lifts[j].correction.isZero(0.0)) corrected_[j] = 1;
      });
    }
    restInverseEdges_ = input.restData->inverseEdges;
  }

  BlendMethod method() const override { return BlendMethod::kLieBodies; }

  // The blended body is p0 exp(sum_k w_k X_k) for the shear and scale
  // (Bansal & Tatu eq. 4), with the rigid rotation R0 W(w)^T, where
  // W(w) = exp(sum_k w_k base_k) exp(sum_k w_k correction_k) blends the lifts
  // of the world rotations W_k = R_k^T R_0 (rotation_consistency.h; for
  // corrections 0 this is exactly the rotation part of p0 exp(sum_k w_k X_k)).
  // The translation of E is irrelevant: the target uses only the edges.
  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }
  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(weights.data(), examples_);
    std::vector<LieBodyTangent> logs(examples_);
    for (int j = begin; j < end; ++j) {
      Eigen::Vector3d base = Eigen::Vector3d::Zero();
      Eigen::Vector3d correction = Eigen::Vector3d::Zero();
      for (int k = 0; k < examples_; ++k) {
        const size_t slot = static_cast<size_t>(j) * examples_ + k;
        logs[k] = logs_[slot];
        base += w(k) * lifts_[slot].base;
        correction += w(k) * lifts_[slot].correction;
      }
      Eigen::Matrix3d world = so3Exp(base);
      if (corrected_[j] != 0) world *= so3Exp(correction);
      LieBody blended = lieBodyBlend(restBodies_[j], logs, w);
      blended.rigid.topLeftCorner<3, 3>() =
          restBodies_[j].rigid.topLeftCorner<3, 3>() * world.transpose();
      out[j - begin] = lieBodyEdges(blended) * restInverseEdges_[j];
    }
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<LieBody> restBodies_;
  std::vector<LieBodyTangent> logs_;  // tet-major; shear and scale parts only
  std::vector<RotationLift> lifts_;   // tet-major: lifts of W_k = R_k^T R_0
  std::vector<char> corrected_;       // 1 where some example's lift correction is non-zero
  std::vector<Eigen::Matrix3d> restInverseEdges_;
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareLieBodiesBlender(const BlendInput& input) {
  return std::make_unique<LieBodiesBlender>(input);
}

}  // namespace tetblend
