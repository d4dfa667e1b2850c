#include "tetblend/blending/kaji_blend.h"

#include <algorithm>
#include <sstream>

#include "blend_common.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/batch_kernels.h"
#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

using blend_detail::forEachTet;
using blend_detail::homogeneous;

// Parameters per tet and example: rotation lift base (3), then the upper
// triangle of the stretch log (6), tet-major so one tet's examples are
// contiguous. The lift corrections are zero except where a lift had to leave
// the principal branch (rotation_consistency.h), so they are kept only for
// those tets and examples (3 doubles and an example index each).
constexpr int kParamsPerMap = 9;
constexpr int kStretchOffset = 3;
constexpr int kCorrectionSize = 3;

class KajiBlender final : public TetMapBlender {
 public:
  explicit KajiBlender(const BlendInput& input) {
    const auto sizes = blend_detail::checkInput(input);
    tets_ = sizes.tets;
    examples_ = sizes.examples;
    data_.tets = tets_;
    data_.examples = examples_;
    data_.rotationConsistency = input.rotationConsistency;
    data_.params.resize(static_cast<size_t>(tets_) * examples_ * kParamsPerMap);
    std::vector<char> corrected(tets_, 0);
    std::vector<std::vector<RotationLift>> lifts(examples_);
    {
      std::vector<Eigen::Matrix3d> rotations(tets_);
      for (int k = 0; k < examples_; ++k) {
        const auto& gradients = (*input.gradients)[k];
        forEachTet(tets_, [&](int j) {
          try {
            const AffineParams principal = psi(homogeneous(gradients[j]));
            blend_detail::packSymmetric(principal.stretchLog, param(j, k) + kStretchOffset);
            rotations[j] = so3Exp(principal.rotationLog);
          } catch (const DomainError& error) {
            blend_detail::rethrowForTet("kaji", k, j, error);
          }
        });
        lifts[k] = rotationLifts(rotations, *input.adjacency, *input.components,
                                 input.rotationConsistency);
        forEachTet(tets_, [&](int j) {
          Eigen::Map<Eigen::Vector3d>(param(j, k)) = lifts[k][j].base;
          if (!lifts[k][j].correction.isZero(0.0)) corrected[j] = 1;
        });
      }
    }
    data_.correctionStart.push_back(0);
    for (int j = 0; j < tets_; ++j) {
      if (corrected[j] == 0) continue;
      data_.correctedTets.push_back(j);
      for (int k = 0; k < examples_; ++k) {
        const Eigen::Vector3d& correction = lifts[k][j].correction;
        if (correction.isZero(0.0)) continue;
        data_.correctionExample.push_back(k);
        data_.corrections.insert(data_.corrections.end(), correction.data(),
                                 correction.data() + kCorrectionSize);
      }
      data_.correctionStart.push_back(static_cast<int>(data_.correctionExample.size()));
    }
    data_.correctedTets.shrink_to_fit();
    data_.correctionStart.shrink_to_fit();
    data_.correctionExample.shrink_to_fit();
    data_.corrections.shrink_to_fit();
  }

  // Stored parameters (KajiParameterData's layout is this class's).
  explicit KajiBlender(KajiParameterData data)
      : tets_(data.tets), examples_(data.examples), data_(std::move(data)) {
    const auto fail = [](const std::string& what) {
      throw InputError("stored kaji parameters: " + what);
    };
    const auto& d = data_;
    if (tets_ < 0 || examples_ < 1 ||
        d.params.size() != static_cast<size_t>(tets_) * examples_ * kParamsPerMap) {
      fail(std::to_string(d.params.size()) + " values for " + std::to_string(tets_) + " tets and " +
           std::to_string(examples_) + " examples");
    }
    if (d.correctionStart.size() != d.correctedTets.size() + 1 || d.correctionStart[0] != 0 ||
        static_cast<size_t>(d.correctionStart.back()) != d.correctionExample.size() ||
        d.corrections.size() != d.correctionExample.size() * kCorrectionSize) {
      fail("the lift corrections' sizes do not match");
    }
    for (size_t i = 0; i < d.correctedTets.size(); ++i) {
      const int tet = d.correctedTets[i];
      if (tet < 0 || tet >= tets_ || (i > 0 && tet <= d.correctedTets[i - 1]) ||
          d.correctionStart[i + 1] < d.correctionStart[i]) {
        fail("corrected tet " + std::to_string(tet) + " is out of range or order");
      }
    }
    for (int k : d.correctionExample) {
      if (k < 0 || k >= examples_) fail("a correction names example " + std::to_string(k));
    }
  }

  const KajiParameterData& data() const { return data_; }

  BlendMethod method() const override { return BlendMethod::kKaji; }

  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }

  // B_j = exp(sum w base) exp(sum w correction) exp(sum w Y): Kaji–Ochiai
  // phi (eq. (2)) of the blended parameters, with the rotation lift of
  // rotation_consistency.h (its correction factor only in the tets with a
  // non-zero correction; elsewhere this is exactly phi(sum_k w_k psi(F_kj))).
  // The range (one fixed chunk of blendTargets) sums its parameters into one
  // contiguous array of blended logarithms (w, then Y's upper triangle:
  // phiLinearBatch's layout) and maps it through core's batched exponentials.
  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    std::vector<double> logs(static_cast<size_t>(end - begin) * kParamsPerMap, 0.0);
    for (int j = begin; j < end; ++j) {
      double* sum = logs.data() + static_cast<size_t>(j - begin) * kParamsPerMap;
      const double* p = param(j, 0);
      for (int k = 0; k < examples_; ++k, p += kParamsPerMap) {
        const double w = weights[k];
        for (int i = 0; i < kParamsPerMap; ++i) sum[i] += w * p[i];
      }
    }
    // Corrected tets: B = exp(base) [exp(correction) exp(Y)], the bracket
    // batched with the others (the correction in place of the base).
    const auto& corrected = data_.correctedTets;
    const auto first = std::lower_bound(corrected.begin(), corrected.end(), begin);
    const auto last = std::lower_bound(first, corrected.end(), end);
    std::vector<Eigen::Vector3d> bases(last - first);
    for (auto t = first; t != last; ++t) {
      const auto index = t - corrected.begin();
      double* sum = logs.data() + static_cast<size_t>(*t - begin) * kParamsPerMap;
      Eigen::Map<Eigen::Vector3d> rotationLog(sum);
      bases[t - first] = rotationLog;
      rotationLog.setZero();
      // The zero corrections of the other examples add nothing.
      for (int i = data_.correctionStart[index]; i < data_.correctionStart[index + 1]; ++i) {
        rotationLog += weights[data_.correctionExample[i]] *
                       Eigen::Map<const Eigen::Vector3d>(data_.corrections.data() +
                                                         static_cast<size_t>(i) * kCorrectionSize);
      }
    }
    phiLinearBatch(logs.data(), out, static_cast<size_t>(end - begin));
    for (auto t = first; t != last; ++t) {
      out[*t - begin] = so3Exp(bases[t - first]) * out[*t - begin];
    }
  }

 private:
  double* param(int tet, int example) {
    return data_.params.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }
  const double* param(int tet, int example) const {
    return data_.params.data() + (static_cast<size_t>(tet) * examples_ + example) * kParamsPerMap;
  }
  int tets_ = 0;
  int examples_ = 0;
  // The parameters, and the lift corrections stored only where non-zero
  // (blend_cache.h).
  KajiParameterData data_;
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

  int tetCount() const override { return tets_; }
  int exampleCount() const override { return examples_; }

  void blendChunk(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const override {
    std::vector<Eigen::Matrix4d> transforms(examples_);
    for (int j = begin; j < end; ++j) {
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
      out[j - begin] = result.matrix.topLeftCorner<3, 3>();
    }
  }

 private:
  int tets_ = 0;
  int examples_ = 0;
  std::vector<Eigen::Matrix3d> maps_;
};

}  // namespace

KajiParameterData kajiParameterData(const TetMapBlender& blender) {
  const auto* kaji = dynamic_cast<const KajiBlender*>(&blender);
  if (kaji == nullptr) {
    throw InputError("kajiParameterData: '" + blendMethodName(blender.method()) +
                     "' is not the kaji method");
  }
  return kaji->data();
}

std::unique_ptr<TetMapBlender> kajiBlenderFromData(KajiParameterData data) {
  return std::make_unique<KajiBlender>(std::move(data));
}

std::unique_ptr<TetMapBlender> prepareKajiBlender(BlendMethod method, const BlendInput& input) {
  if (method == BlendMethod::kKaji) return std::make_unique<KajiBlender>(input);
  if (method == BlendMethod::kKajiFrechet) return std::make_unique<KajiFrechetBlender>(input);
  throw InputError("prepareKajiBlender: '" + blendMethodName(method) + "' is not a Kaji method");
}

}  // namespace tetblend
