#include "tetblend/blending/kaji_blend.h"

#include <sstream>

#include "blend_common.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

using blend_detail::forEachTet;
using blend_detail::homogeneous;

// Parameters per tet and example: rotation lift base (3), lift correction
// (3), then the upper triangle of the stretch log (6), tet-major so one
// tet's examples are contiguous.
constexpr int kParamsPerMap = 12;
constexpr int kCorrectionOffset = 3;
constexpr int kStretchOffset = 6;

class KajiBlender final : public TetMapBlender {
 public:
  explicit KajiBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    params_.resize(static_cast<size_t>(tets_) * examples_ * kParamsPerMap);
    corrected_.assign(tets_, 0);
    std::vector<Eigen::Matrix3d> stretchLogs(tets_);
    std::vector<Eigen::Matrix3d> rotations(tets_);
    for (int k = 0; k < examples_; ++k) {
      const auto& gradients = (*input.gradients)[k];
      forEachTet(tets_, [&](int j) {
        try {
          const AffineParams principal = psi(homogeneous(gradients[j]));
          stretchLogs[j] = principal.stretchLog;
          rotations[j] = so3Exp(principal.rotationLog);
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet("kaji", k, j, error);
        }
      });
      const std::vector<RotationLift> lifts =
          rotationLifts(rotations, *input.adjacency, *input.components, input.rotationConsistency);
      forEachTet(tets_, [&](int j) {
        double* p = param(j, k);
        const Eigen::Matrix3d& y = stretchLogs[j];
        for (int i = 0; i < 3; ++i) {
          p[i] = lifts[j].base(i);
          p[kCorrectionOffset + i] = lifts[j].correction(i);
        }
        p[6] = y(0, 0);
        p[7] = y(0, 1);
        p[8] = y(0, 2);
        p[9] = y(1, 1);
        p[10] = y(1, 2);
        p[11] = y(2, 2);
        if (!lifts[j].correction.isZero(0.0)) corrected_[j] = 1;
      });
    }
  }

  BlendMethod method() const override { return BlendMethod::kKaji; }

  // B_j = exp(sum w base) exp(sum w correction) exp(sum w Y): Kaji–Ochiai
  // phi (eq. (2)) of the blended parameters, with the rotation lift of
  // rotation_consistency.h (its correction factor skipped for the tets whose
  // corrections are all 0, where this is exactly phi(sum_k w_k psi(F_kj))).
  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const override {
    checkWeights(weights, examples_);
    targets.resize(tets_);
    forEachTet(tets_, [&](int j) {
      double sum[kParamsPerMap] = {};
      const bool corrected = corrected_[j] != 0;
      for (int k = 0; k < examples_; ++k) {
        const double* p = param(j, k);
        const double w = weights[k];
        for (int i = 0; i < kCorrectionOffset; ++i) sum[i] += w * p[i];
        if (corrected) {
          for (int i = kCorrectionOffset; i < kStretchOffset; ++i) sum[i] += w * p[i];
        }
        for (int i = kStretchOffset; i < kParamsPerMap; ++i) sum[i] += w * p[i];
      }
      Eigen::Matrix3d y;
      y << sum[6], sum[7], sum[8],  //
          sum[7], sum[9], sum[10],  //
          sum[8], sum[10], sum[11];
      Eigen::Matrix3d rotation = so3Exp(Eigen::Map<const Eigen::Vector3d>(sum));
      if (corrected) rotation *= so3Exp(Eigen::Map<const Eigen::Vector3d>(sum + kCorrectionOffset));
      targets[j] = rotation * symExp(y);
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
  std::vector<char> corrected_;  // 1 where some example's lift correction is non-zero
};

class KajiFrechetBlender final : public TetMapBlender {
 public:
  explicit KajiFrechetBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    maps_ = blend_detail::tetMajorGradients(input, sizes);
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
