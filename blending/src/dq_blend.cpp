#include "tetblend/blending/dq_blend.h"

#include <sstream>

#include "blend_common.h"
#include "tetblend/core/dual_quaternion_blend.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

// Per tet and example: unit quaternion (w, x, y, z) then the upper triangle
// of log S (6), tet-major.
constexpr int kParamsPerMap = 10;

class DualQuaternionBlender final : public TetMapBlender {
 public:
  DualQuaternionBlender(BlendMethod method, const BlendInput& input) : method_(method) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    params_.resize(static_cast<size_t>(tets_) * examples_ * kParamsPerMap);
    for (int k = 0; k < examples_; ++k) {
      blend_detail::forEachTet(tets_, [&](int j) {
        PolarLogDecomposition polar;
        try {
          polar = polarDecomposeLog((*input.gradients)[k][j]);
        } catch (const DomainError& error) {
          blend_detail::rethrowForTet(blendMethodName(method_), k, j, error);
        }
        const Eigen::Quaterniond q(polar.rotation);
        const Eigen::Matrix3d& y = polar.stretchLog;
        double* p = param(j, k);
        const double values[kParamsPerMap] = {q.w(),   q.x(),   q.y(),   q.z(),   y(0, 0),
                                              y(0, 1), y(0, 2), y(1, 1), y(1, 2), y(2, 2)};
        std::copy(values, values + kParamsPerMap, p);
      });
    }
  }

  BlendMethod method() const override { return method_; }

  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }

  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    const std::vector<double> allWeights = blend_detail::withRestWeight(weights);
    std::vector<DualQuaternion> rotations(examples_ + 1);  // [0] is the rest
    for (int j = begin; j < end; ++j) {
      Eigen::Matrix<double, 6, 1> logStretch = Eigen::Matrix<double, 6, 1>::Zero();
      for (int k = 0; k < examples_; ++k) {
        const double* p = param(j, k);
        rotations[k + 1] = DualQuaternion::fromRotationTranslation(
            Eigen::Quaterniond(p[0], p[1], p[2], p[3]), Eigen::Vector3d::Zero());
        logStretch += weights[k] * Eigen::Map<const Eigen::Matrix<double, 6, 1>>(p + 4);
      }
      out[j - begin] = blendRotation(rotations, allWeights, j) * stretch(logStretch);
    }
  }

 private:
  Eigen::Matrix3d blendRotation(const std::vector<DualQuaternion>& rotations,
                                const std::vector<double>& allWeights, int tet) const {
    if (method_ == BlendMethod::kDualQuaternion) {
      try {
        return dlb(rotations.data(), allWeights.data(), static_cast<int>(rotations.size()))
            .real()
            .toRotationMatrix();
      } catch (const DomainError& error) {
        blend_detail::rethrowForTet("dq", -1, tet, error);
      }
    }
    const DibResult result = dib(rotations, allWeights);
    if (!result.converged) {
      std::ostringstream message;
      message << "dib: tet " << tet << ": the iteration did not converge in " << result.iterations
              << " steps (residual " << result.residual << ") for these weights; use 'dq'";
      throw NumericalError(message.str());
    }
    return result.blend.real().toRotationMatrix();
  }

  static Eigen::Matrix3d stretch(const Eigen::Matrix<double, 6, 1>& u) {
    Eigen::Matrix3d y;
    y << u(0), u(1), u(2), u(1), u(3), u(4), u(2), u(4), u(5);
    return symExp(y);
  }
  double* param(int tet, int example) {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }
  const double* param(int tet, int example) const {
    return params_.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }

  BlendMethod method_;
  int tets_ = 0;
  int examples_ = 0;
  std::vector<double> params_;
};

}  // namespace

std::unique_ptr<TetMapBlender> prepareDualQuaternionBlender(BlendMethod method,
                                                            const BlendInput& input) {
  if (method == BlendMethod::kDualQuaternion || method == BlendMethod::kDib) {
    return std::make_unique<DualQuaternionBlender>(method, input);
  }
  throw InputError("prepareDualQuaternionBlender: '" + blendMethodName(method) +
                   "' is not a dual-quaternion method");
}

}  // namespace tetblend
