#include "tetblend/core/dual_quaternion_blend.h"

#include <cmath>
#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/se3.h"

namespace tetblend {
namespace {

Eigen::Quaterniond fromCoeffs(const Eigen::Vector4d& c) {
  Eigen::Quaterniond q;
  q.coeffs() = c;
  return q;
}

double updateNorm(const DualQuaternion& x) {
  return std::sqrt(x.real().vec().squaredNorm() + x.dual().vec().squaredNorm());
}

void checkSizes(const char* where, std::size_t dqs, std::size_t weights) {
  if (dqs != weights || dqs == 0) {
    std::ostringstream msg;
    msg << where << ": " << dqs << " dual quaternions and " << weights
        << " weights; give one weight per dual quaternion, at least one";
    throw InputError(msg.str());
  }
}

}  // namespace

DualQuaternion scLerp(double t, const DualQuaternion& p, const DualQuaternion& q) {
  const DualQuaternion relative = (p.conjugate() * q).canonicalSign();
  return p * relative.power(t);
}

DualQuaternion dlb(const DualQuaternion* dqs, const double* weights, int count) {
  if (count < 1) throw InputError("dlb: no dual quaternion to blend (count < 1)");
  int pivot = 0;
  for (int i = 1; i < count; ++i) {
    if (std::abs(weights[i]) > std::abs(weights[pivot])) pivot = i;
  }
  const Eigen::Vector4d pivotReal = dqs[pivot].real().coeffs();
  Eigen::Vector4d real = Eigen::Vector4d::Zero();
  Eigen::Vector4d dual = Eigen::Vector4d::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector4d qi = dqs[i].real().coeffs();
    const double w = qi.dot(pivotReal) < 0.0 ? -weights[i] : weights[i];
    real += w * qi;
    dual += w * dqs[i].dual().coeffs();
  }
  return DualQuaternion(fromCoeffs(real), fromCoeffs(dual)).normalized();
}

DualQuaternion dlb(const std::vector<DualQuaternion>& dqs, const std::vector<double>& weights) {
  checkSizes("dlb", dqs.size(), weights.size());
  return dlb(dqs.data(), weights.data(), static_cast<int>(dqs.size()));
}

DibResult dib(const std::vector<DualQuaternion>& dqs, const std::vector<double>& weights,
              const DibOptions& options) {
  checkSizes("dib", dqs.size(), weights.size());
  double sum = 0.0;
  for (double w : weights) sum += w;
  if (!(std::abs(sum - 1.0) <= 1e-9)) {
    std::ostringstream msg;
    msg << "dib: the weights sum to " << sum << ", not 1; normalise them (DIB's fixed point "
        << "is the weighted mean only for weights summing to 1)";
    throw InputError(msg.str());
  }
  DibResult result;
  DualQuaternion b = dlb(dqs, weights);
  for (int it = 0;; ++it) {
    const DualQuaternion bConj = b.conjugate();
    DualQuaternion x = DualQuaternion::pure(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < dqs.size(); ++i) {
      x = x + (bConj * dqs[i]).canonicalSign().log() * weights[i];
    }
    result.residual = updateNorm(x);
    result.iterations = it;
    if (result.residual < options.precision) {
      result.converged = true;
      break;
    }
    if (it >= options.maxIterations) break;
    b = (b * DualQuaternion::exp(x)).normalized();
  }
  result.blend = b.canonicalSign();
  return result;
}

DualQuaternion eberlyGeodesic(double t, const Eigen::Matrix4d& H0, const Eigen::Matrix4d& H1) {
  const Eigen::Matrix3d r0 = H0.topLeftCorner<3, 3>();
  const Eigen::Vector3d t0 = H0.topRightCorner<3, 1>();
  // (S, U) = log(H1 H0^{-1}) (eq. 22).
  const Vector6d xi = se3Log(H1 * rigidInverse(H0));
  const Eigen::Vector3d omega = xi.head<3>();
  const Eigen::Vector3d u = xi.tail<3>();
  // q(t): the quaternion of G(t) = exp(t S) R0, the slerp of q0 and q1 along
  // the shortest arc (the rotation angle of S is in [0, pi]).
  const Eigen::Quaterniond q0(r0);
  const double angle = omega.norm();
  const Eigen::Quaterniond step =
      angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(t * angle, omega / angle))
                  : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond qt = step * q0;
  // b(t) = t V(t) U (eq. 25) = V(t omega) (t U); a = R0^T T0.
  const Eigen::Vector3d bt = se3LeftJacobian(t * omega) * (t * u);
  const Eigen::Vector3d av = r0.transpose() * t0;
  const Eigen::Quaterniond a(0.0, av.x(), av.y(), av.z());
  const Eigen::Quaterniond b(0.0, bt.x(), bt.y(), bt.z());
  // eq. 33: d(t) = q(t) + eps (q(t) a + b(t) q(t)) / 2.
  const Eigen::Vector4d dual = 0.5 * ((qt * a).coeffs() + (b * qt).coeffs());
  return DualQuaternion(qt, fromCoeffs(dual)).canonicalSign();
}

}  // namespace tetblend
