#include "tetblend/blending/kaji_blend.h"

#include <sstream>

#include "blend_common.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

using blend_detail::forEachTet;

Eigen::Matrix4d homogeneous(const Eigen::Matrix3d& linear) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a.topLeftCorner<3, 3>() = linear;
  return a;
}

// Parameters per tet and example: rotation log (3) then the upper triangle
// of the stretch log (6), tet-major so one tet's examples are contiguous.
constexpr int kParamsPerMap = 9;

class KajiBlender final : public TetMapBlender {
 public:
  explicit KajiBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    params_.resize(static_cast<size_t>(tets_) * examples_ * kParamsPerMap);
    std::vector<AffineParams> principal(tets_);
    std::vector<Eigen::Matrix3d> rotations(tets_);
    for (int k = 0; k < examples_; ++k) {
      const auto& gradients = (*input.gradients)[k];
      forEachTet(tets_, [&](int j) {
        try {
          principal[j] = psi(homogeneous(gradients[j]));
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("kaji", k, j, error);
        }
        rotations[j] = so3Exp(principal[j].rotationLog);
      });
      const std::vector<Eigen::Vector3d> logs =
          rotationLogs(rotations, *input.adjacency, *input.components, input.rotationConsistency);
      forEachTet(tets_, [&](int j) {
        double* p = param(j, k);
        const Eigen::Matrix3d& y = principal[j].stretchLog;
        p[0] = logs[j].x();
        p[1] = logs[j].y();
        p[2] = logs[j].z();
        p[3] = y(0, 0);
        p[4] = y(0, 1);
        p[5] = y(0, 2);
        p[6] = y(1, 1);
        p[7] = y(1, 2);
        p[8] = y(2, 2);
      });
    }
  }

  BlendMethod method() const override { return BlendMethod::kKaji; }

  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    forEachTet(tets_, [&](int j) {
      double sum[kParamsPerMap] = {};
      for (int k = 0; k < examples_; ++k) {
        const double* p = param(j, k);
        for (int i = 0; i < kParamsPerMap; ++i) sum[i] += weights[k] * p[i];
      }
      AffineParams blended = AffineParams::Zero();
      blended.rotationLog = Eigen::Vector3d(sum[0], sum[1], sum[2]);
      blended.stretchLog << sum[3], sum[4], sum[5],  //
          sum[4], sum[6], sum[7],                    //
          sum[5], sum[7], sum[8];
      targets[j] = phi(blended).topLeftCorner<3, 3>();
    });
  }

 private:
  double* param(int tet, int example) {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }
  const double* param(int tet, int example) const {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }
  int tets_ = 0;
  int examples_ = 0;
  std::vector<double> params_;
};

class KajiFrechetBlender final : public TetMapBlender {
 public:
  explicit KajiFrechetBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    maps_.resize(static_cast<size_t>(tets_) * examples_);
    forEachTet(tets_, [&](int j) {
      for (int k = 0; k < examples_; ++k) {
        maps_[static_cast<size_t>(j) * examples_ + k] = (*input.gradients)[k][j];
      }
    });
  }

  BlendMethod method() const override { return BlendMethod::kKajiFrechet; }

  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    forEachTet(tets_, [&](int j) {
      std::vector<Eigen::Matrix4d> transforms(examples_);
      for (int k = 0; k < examples_; ++k) {
        transforms[k] = homogeneous(maps_[static_cast<size_t>(j) * examples_ + k]);
      }
      FrechetBlendResult result;
      try {
        result = kajiFrechetBlend(weights, transforms);
      } catch (const DomainError& error) {
        blend_detail::rethrowForTet("kaji-frechet", -1, j, error);
      }
      if (!result.converged) {
        std::ostringstream message;
        message << "kaji-frechet: tet " << j << ": the Fréchet iteration did not converge in "
                << result.iterations << " iterations for these weights; use 'kaji'";
        throw NumericalError(message.str());
      }
      targets[j] = result.matrix.topLeftCorner<3, 3>();
    });
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> maps_;
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareKajiBlender(BlendMethod method, const BlendInput& input) {
  if (method == BlendMethod::kKaji) return std::make_unique<KajiBlender>(input);
  if (method == BlendMethod::kKajiFrechet) return std::make_unique<KajiFrechetBlender>(input);
  throw InputError("prepareKajiBlender: '" + blendMethodName(method) + "' is not a Kaji method");
}

}  // namespace tetblend
