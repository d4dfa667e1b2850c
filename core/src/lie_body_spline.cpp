#include "tetblend/core/lie_body_spline.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "tetblend/core/error.h"
#include "tetblend/core/shear_group.h"

namespace tetblend {

namespace {

// exp(-C) B exp(C) per component (the adjoint action of exp(-C) on B).
LieBodyTangent conjugate(const LieBodyTangent& b, const LieBodyTangent& c) {
  const Eigen::Matrix4d g = se3Exp(c.rigid);
  const Eigen::Matrix3d h = shearExp(c.shear);
  return {se3Vee(rigidInverse(g) * se3Hat(b.rigid) * g), shearInverse(h) * b.shear * h, b.scale};
}

}  // namespace

LieBodySpline::LieBodySpline(std::vector<LieBody> keys) : keys_(std::move(keys)) {
  if (keys_.size() < 2) {
    std::ostringstream msg;
    msg << "LieBodySpline: needs at least 2 keys, got " << keys_.size() << ".";
    throw InputError(msg.str());
  }
  const std::size_t n = keys_.size() - 1;
  b_.resize(n);
  c_.resize(n);
  b_[0] = lieBodyRelativeLog(keys_[0], keys_[1]);
  for (std::size_t i = 0; i < n; ++i) {
    const LieBody step = lieBodyCompose(lieBodyInverse(keys_[i]), keys_[i + 1]);
    c_[i] = lieBodyLog(lieBodyCompose(lieBodyExp(-1.0 * b_[i]), step));
    if (i + 1 < n) b_[i + 1] = conjugate(b_[i], c_[i]) + 2.0 * c_[i];
  }
}

LieBody LieBodySpline::evaluate(double u) const {
  const int last = segmentCount() - 1;
  const int i = static_cast<int>(std::clamp(std::floor(u), 0.0, static_cast<double>(last)));
  const double t = u - i;
  return lieBodyCompose(keys_[i],
                        lieBodyCompose(lieBodyExp(t * b_[i]), lieBodyExp((t * t) * c_[i])));
}

TetCorners LieBodySpline::evaluateCorners(double u) const { return lieBodyCorners(evaluate(u)); }

}  // namespace tetblend
