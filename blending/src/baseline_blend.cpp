#include "tetblend/blending/baseline_blend.h"

#include <unsupported/Eigen/MatrixFunctions>

#include "blend_common.h"
#include "tetblend/core/baselines.h"

namespace tetblend {
namespace {

using blend_detail::forEachTet;
using blend_detail::homogeneous;
using blend_detail::restWeight;

// (1 - sum w) I + sum_k w_k F_kj: linear blending of deformation gradients.
class LinearBlender final : public TetMapBlender {
 public:
  explicit LinearBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    maps_ = blend_detail::tetMajorGradients(input, sizes);
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

// Alexa: exp(sum_k w_k log F_kj). alexaBlend (core/baselines.h) checks each
// map for a real principal logarithm once; the logarithms are kept so a
// blend costs one matrix exponential per tet.
class AlexaBlender final : public TetMapBlender {
 public:
  explicit AlexaBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    logs_.resize(static_cast<size_t>(tets_) * examples_);
    for (int k = 0; k < examples_; ++k) {
      forEachTet(tets_, [&](int j) {
        const Eigen::Matrix3d& f = (*input.gradients)[k][j];
        try {
          alexaBlend({1.0}, {homogeneous(f)});
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("alexa", k, j, error);
        }
        logs_[static_cast<size_t>(j) * examples_ + k] = f.log();
      });
    }
  }
  BlendMethod method() const override { return BlendMethod::kAlexa; }
  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    forEachTet(tets_, [&](int j) {
      Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
      for (int k = 0; k < examples_; ++k) {
        sum += weights[k] * logs_[static_cast<size_t>(j) * examples_ + k];
      }
      targets[j] = sum.exp();
    });
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> logs_;  // tet-major
};

// Polar + quaternion slerp (Shoemake–Duff) via polarSlerpBlend with the rest
// (identity) as map 0 at weight 1 - sum w. The kernel decomposes its inputs
// on every call, so this baseline costs n polar decompositions per tet and
// blend.
class PolarSlerpBlender final : public TetMapBlender {
 public:
  explicit PolarSlerpBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    maps_ = blend_detail::tetMajorGradients(input, sizes);
  }
  BlendMethod method() const override { return BlendMethod::kPolarSlerp; }
  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    const std::vector<double> allWeights = blend_detail::withRestWeight(weights);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tets_, blend_detail::kTetGrain),
        [&](const tbb::blocked_range<int>& range) {
          std::vector<Eigen::Matrix4d> maps(examples_ + 1, Eigen::Matrix4d::Identity());
          for (int j = range.begin(); j != range.end(); ++j) {
            for (int k = 0; k < examples_; ++k) {
              maps[k + 1] = homogeneous(maps_[static_cast<size_t>(j) * examples_ + k]);
            }
            try {
              targets[j] = polarSlerpBlend(allWeights, maps).topLeftCorner<3, 3>();
            } catch (const DomainError& error) {
              blend_detail::rethrowForTet("polar-slerp", -1, j, error);
            }
          }
        });
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> maps_;  // tet-major
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareBaselineBlender(BlendMethod method, const BlendInput& input) {
  switch (method) {
    case BlendMethod::kLinear:
      return std::make_unique<LinearBlender>(input);
    case BlendMethod::kAlexa:
      return std::make_unique<AlexaBlender>(input);
    case BlendMethod::kPolarSlerp:
      return std::make_unique<PolarSlerpBlender>(input);
    default:
      break;
  }
  throw InputError("prepareBaselineBlender: '" + blendMethodName(method) +
                   "' is not a baseline method");
}

}  // namespace tetblend
