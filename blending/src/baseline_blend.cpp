#include "tetblend/blending/baseline_blend.h"

#include "blend_common.h"

namespace tetblend {
namespace {

using blend_detail::forEachTet;
using blend_detail::restWeight;

// (1 - sum w) I + sum_k w_k F_kj: linear blending of deformation gradients.
class LinearBlender final : public TetMapBlender {
 public:
  explicit LinearBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    maps_.resize(static_cast<size_t>(tets_) * examples_);
    forEachTet(tets_, [&](int j) {
      for (int k = 0; k < examples_; ++k) maps_[index(j, k)] = (*input.gradients)[k][j];
    });
  }
  BlendMethod method() const override { return BlendMethod::kLinear; }
  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    const double rest = restWeight(weights);
    targets.resize(tets_);
    forEachTet(tets_, [&](int j) {
      Eigen::Matrix3d sum = rest * Eigen::Matrix3d::Identity();
      for (int k = 0; k < examples_; ++k) sum += weights[k] * maps_[index(j, k)];
      targets[j] = sum;
    });
  }

 private:
  size_t index(int tet, int example) const {
    return static_cast<size_t>(tet) * examples_ + example;
  }
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> maps_;  // tet-major: all examples of a tet together
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareBaselineBlender(BlendMethod method, const BlendInput& input) {
  switch (method) {
    case BlendMethod::kLinear:
      return std::make_unique<LinearBlender>(input);
    default:
      break;
  }
  throw InputError("prepareBaselineBlender: '" + blendMethodName(method) +
                   "' is not a baseline method");
}

}  // namespace tetblend
