#include "tetblend/blending/lie_bodies_blend.h"

#include "blend_common.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/lie_bodies.h"
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
      const std::vector<Eigen::Vector3d> references = rotationLogs(
          worldRotations, *input.adjacency, *input.components, input.rotationConsistency);
      blend_detail::forEachTet(tets_, [&](int j) {
        try {
          logs_[static_cast<size_t>(j) * examples_ + k] =
              lieBodyRelativeLog(restBodies_[j], bodies[j], references[j]);
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("liebodies", k, j, error);
        }
      });
    }
    restInverseEdges_ = input.restData->inverseEdges;
  }

  BlendMethod method() const override { return BlendMethod::kLieBodies; }

  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(weights.data(), examples_);
    tbb::parallel_for(tbb::blocked_range<int>(0, tets_, blend_detail::kTetGrain),
                      [&](const tbb::blocked_range<int>& range) {
                        std::vector<LieBodyTangent> logs(examples_);
                        for (int j = range.begin(); j != range.end(); ++j) {
                          for (int k = 0; k < examples_; ++k) {
                            logs[k] = logs_[static_cast<size_t>(j) * examples_ + k];
                          }
                          const LieBody blended = lieBodyBlend(restBodies_[j], logs, w);
                          targets[j] = lieBodyEdges(blended) * restInverseEdges_[j];
                        }
                      });
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<LieBody> restBodies_;
  std::vector<LieBodyTangent> logs_;  // tet-major
  std::vector<Eigen::Matrix3d> restInverseEdges_;
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareLieBodiesBlender(const BlendInput& input) {
  return std::make_unique<LieBodiesBlender>(input);
}

}  // namespace tetblend
