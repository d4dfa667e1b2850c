#include "tetblend/core/kaji_ochiai.h"

#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

namespace tetblend {
namespace {

void checkSizes(const char* function, std::size_t weights, std::size_t items) {
  if (weights != items) {
    std::ostringstream msg;
    msg << function << ": " << weights << " weights for " << items
        << " transforms; give one weight per transform";
    throw InputError(msg.str());
  }
}

Eigen::Matrix3d symmetrised(const Eigen::Matrix3d& m) { return 0.5 * (m + m.transpose()); }

}  // namespace

Eigen::Matrix4d phi(const AffineParams& params) {
  Eigen::Matrix4d m;
  m.topLeftCorner<3, 3>() = so3Exp(params.rotationLog) * symExp(params.stretchLog);
  m.topRightCorner<3, 1>() = params.translation;
  m.row(3) << 0.0, 0.0, 0.0, 1.0;
  return m;
}

AffineParams psi(const Eigen::Matrix4d& a) {
  const PolarLogDecomposition polar = polarDecomposeLog(a.topLeftCorner<3, 3>());
  return {a.topRightCorner<3, 1>(), so3Log(polar.rotation), polar.stretchLog};
}

AffineParams psi(const Eigen::Matrix4d& a, const Eigen::Vector3d& rotationReference) {
  if (!rotationReference.allFinite()) {
    std::ostringstream msg;
    msg << "psi: the rotation reference (" << rotationReference.transpose()
        << ") is not finite; pass the rotation log of a neighbouring element or the"
           " previous frame, or use psi without a reference";
    throw InputError(msg.str());
  }
  const PolarLogDecomposition polar = polarDecomposeLog(a.topLeftCorner<3, 3>());
  return {a.topRightCorner<3, 1>(), so3LogClosest(polar.rotation, rotationReference),
          polar.stretchLog};
}

AffineParams weightedSum(const std::vector<double>& weights,
                         const std::vector<AffineParams>& params) {
  checkSizes("weightedSum", weights.size(), params.size());
  AffineParams sum = AffineParams::Zero();
  for (std::size_t i = 0; i < weights.size(); ++i) {
    sum.translation += weights[i] * params[i].translation;
    sum.rotationLog += weights[i] * params[i].rotationLog;
    sum.stretchLog += weights[i] * params[i].stretchLog;
  }
  return sum;
}

Eigen::Matrix4d kajiBlend(const std::vector<double>& weights,
                          const std::vector<AffineParams>& params) {
  return phi(weightedSum(weights, params));
}

FrechetBlendResult kajiFrechetBlend(const std::vector<double>& weights,
                                    const std::vector<Eigen::Matrix4d>& transforms,
                                    const FrechetBlendOptions& options) {
  checkSizes("kajiFrechetBlend", weights.size(), transforms.size());
  const std::size_t n = transforms.size();
  std::vector<Eigen::Matrix3d> rotations(n), stretches(n);
  std::vector<AffineParams> params(n);
  double identityWeight = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const PolarDecomposition polar = polarDecompose(transforms[i].topLeftCorner<3, 3>());
    rotations[i] = polar.rotation;
    stretches[i] = polar.stretch;
    params[i] = {transforms[i].topRightCorner<3, 1>(), so3Log(polar.rotation),
                 symLog(polar.stretch)};
    identityWeight -= weights[i];
  }
  const AffineParams start = weightedSum(weights, params);
  FrechetBlendResult result;
  bool rotationConverged = false;
  // Start at the input of largest weight (Alg. 2 starts at R_1): the Blend
  // rotation can sit near the cut locus of the inputs when their angles
  // approach pi, and the iteration would then settle on another critical point.
  Eigen::Matrix3d zr = Eigen::Matrix3d::Identity();
  double largest = identityWeight;
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] > largest) {
      largest = weights[i];
      zr = rotations[i];
    }
  }
  for (int it = 0; it < options.maxIterations; ++it) {
    Eigen::Vector3d w = identityWeight * so3Log(zr.transpose());
    for (std::size_t i = 0; i < n; ++i) w += weights[i] * so3Log(zr.transpose() * rotations[i]);
    if (w.norm() <= options.tolerance) {
      rotationConverged = true;
      break;
    }
    zr = zr * so3Exp(w);
    ++result.iterations;
  }
  bool stretchConverged = false;
  Eigen::Matrix3d zs = symExp(start.stretchLog);
  for (int it = 0; it < options.maxIterations; ++it) {
    const Eigen::Matrix3d logZ = symLog(zs);
    const Eigen::Matrix3d half = symExp(0.5 * logZ);
    const Eigen::Matrix3d invHalf = symExp(-0.5 * logZ);
    Eigen::Matrix3d w = -identityWeight * logZ;
    for (std::size_t i = 0; i < n; ++i) {
      w += weights[i] * symLog(symmetrised(invHalf * stretches[i] * invHalf));
    }
    if (w.norm() <= options.tolerance) {
      stretchConverged = true;
      break;
    }
    zs = symmetrised(half * symExp(w) * half);
    ++result.iterations;
  }
  result.converged = rotationConverged && stretchConverged;
  result.matrix.setIdentity();
  result.matrix.topLeftCorner<3, 3>() = zr * zs;
  result.matrix.topRightCorner<3, 1>() = start.translation;
  return result;
}

AffineParams projectToSubgroup(const AffineParams& params, AffineSubgroup subgroup) {
  AffineParams p = params;
  switch (subgroup) {
    case AffineSubgroup::Translation:
      p.rotationLog.setZero();
      p.stretchLog.setZero();
      break;
    case AffineSubgroup::Rotation:
      p.translation.setZero();
      p.stretchLog.setZero();
      break;
    case AffineSubgroup::Stretch:
      p.translation.setZero();
      p.rotationLog.setZero();
      break;
    case AffineSubgroup::Rigid:
      p.stretchLog.setZero();
      break;
    case AffineSubgroup::Similarity:
      p.stretchLog = Eigen::Matrix3d::Identity() * (params.stretchLog.trace() / 3.0);
      break;
    case AffineSubgroup::General:
      break;
  }
  return p;
}

bool inSubgroup(const AffineParams& params, AffineSubgroup subgroup, double tolerance) {
  const AffineParams d = params - projectToSubgroup(params, subgroup);
  return d.translation.cwiseAbs().maxCoeff() <= tolerance &&
         d.rotationLog.cwiseAbs().maxCoeff() <= tolerance &&
         d.stretchLog.cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace tetblend
