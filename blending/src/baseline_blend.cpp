#include "tetblend/blending/baseline_blend.h"

#include <Eigen/Geometry>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "blend_common.h"
#include "tetblend/core/baselines.h"
#include "tetblend/core/polar.h"

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
  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }
  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    const double rest = restWeight(weights);
    for (int j = begin; j < end; ++j) {
      Eigen::Matrix3d sum = rest * Eigen::Matrix3d::Identity();
      for (int k = 0; k < examples_; ++k) sum += weights[k] * maps_[index(j, k)];
      out[j - begin] = sum;
    }
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
  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }
  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    for (int j = begin; j < end; ++j) {
      Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
      for (int k = 0; k < examples_; ++k) {
        sum += weights[k] * logs_[static_cast<size_t>(j) * examples_ + k];
      }
      out[j - begin] = sum.exp();
    }
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> logs_;  // tet-major
};

// Polar + quaternion slerp (Shoemake–Duff): the combination of core's
// polarSlerpBlend, with the rest (identity) as map 0 at weight 1 - sum w, but
// each example's polar decomposition F = R S done once at preparation. Per
// tet and example: R's unit quaternion (x, y, z, w, Eigen's coefficient
// order) and the upper triangle of S (symmetrised). A blend is then one
// quaternion sum (or a slerp for a single example) and one stretch sum.
constexpr int kQuaternionSize = 4;
constexpr int kPolarParamsPerMap = kQuaternionSize + 6;

class PolarSlerpBlender final : public TetMapBlender {
 public:
  explicit PolarSlerpBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    params_.resize(static_cast<size_t>(tets_) * examples_ * kPolarParamsPerMap);
    for (int k = 0; k < examples_; ++k) {
      const auto& gradients = (*input.gradients)[k];
      forEachTet(tets_, [&](int j) {
        PolarDecomposition polar;
        try {
          polar = polarDecompose(gradients[j]);
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("polar-slerp", k, j, error);
        }
        double* p = param(j, k);
        Eigen::Map<Eigen::Vector4d> quaternion(p);
        quaternion = Eigen::Quaterniond(polar.rotation).coeffs();
        blend_detail::packSymmetric(0.5 * (polar.stretch + polar.stretch.transpose()),
                                    p + kQuaternionSize);
      });
    }
  }
  BlendMethod method() const override { return BlendMethod::kPolarSlerp; }
  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }
  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    const std::vector<double> all = blend_detail::withRestWeight(weights);
    std::vector<Eigen::Quaterniond> rotations(static_cast<size_t>(examples_) + 1,
                                              Eigen::Quaterniond::Identity());
    for (int j = begin; j < end; ++j) {
      Eigen::Matrix3d stretch = all[0] * Eigen::Matrix3d::Identity();
      for (int k = 0; k < examples_; ++k) {
        stretch += all[k + 1] * blend_detail::unpackSymmetric(param(j, k) + kQuaternionSize);
        rotations[static_cast<size_t>(k) + 1].coeffs() =
            Eigen::Map<const Eigen::Vector4d>(param(j, k));
      }
      Eigen::Quaterniond rotation;
      try {
        rotation = polarSlerpRotation(all.data(), rotations.data(), rotations.size());
      } catch (const DomainError& error) {
        blend_detail::rethrowForTet("polar-slerp", -1, j, error);
      }
      out[j - begin] = rotation.toRotationMatrix() * stretch;
    }
  }

 private:
  const double* param(int tet, int example) const {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kPolarParamsPerMap;
  }
  double* param(int tet, int example) {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kPolarParamsPerMap;
  }
  int tets_ = 0;
  int examples_ = 0;
  std::vector<double> params_;  // tet-major, kPolarParamsPerMap per example
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
