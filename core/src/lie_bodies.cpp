#include "tetblend/core/lie_bodies.h"

#include <Eigen/LU>
#include <Eigen/QR>

#include <cmath>
#include <sstream>

#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/shear_group.h"
#include "tetblend/core/so3.h"

namespace tetblend {

namespace {

// Edge matrix [e1, e1 + e2, e3] of the canonical tet.
Eigen::Matrix3d canonicalEdges() {
  Eigen::Matrix3d c;
  c << 1, 1, 0, 0, 1, 0, 0, 0, 1;
  return c;
}

// The last row of a homogeneous affine map may differ from (0 0 0 1) by this
// much (absolute: the row is unitless).
constexpr double kAffineRowTol = 1e-12;

Eigen::Matrix3d rotationOf(const LieBody& p) { return p.rigid.topLeftCorner<3, 3>(); }

// Twist of E whose rotation vector is `omega` (a logarithm of E's rotation).
Vector6d twistWithRotation(const Eigen::Matrix4d& e, const Eigen::Vector3d& omega) {
  const double theta = omega.norm();
  const Eigen::Vector3d t = e.topRightCorner<3, 1>();
  Vector6d xi;
  xi.head<3>() = omega;
  if (theta <= kPi) {
    xi.tail<3>() = se3LeftJacobianInverse(omega) * t;
    return xi;
  }
  // V = I + a S + b S^2 has eigenvalue 1 along omega and modulus
  // 2 |sin(theta/2)| / theta across it.
  const double sigma = 2.0 * std::abs(std::sin(0.5 * theta)) / theta;
  if (sigma >= kScrewSingularValueFloor) {
    xi.tail<3>() = se3LeftJacobian(omega).partialPivLu().solve(t);
  } else {
    // Truncated pseudo-inverse: keep the axial part, drop the part across the
    // axis that no screw with this rotation vector can produce.
    const Eigen::Vector3d axis = omega / theta;
    xi.tail<3>() = axis.dot(t) * axis;
  }
  return xi;
}

LieBodyTangent logWithRigid(const LieBody& p, const Vector6d& rigidLog) {
  if (!(p.scale > 0.0) || !std::isfinite(p.scale)) {
    std::ostringstream msg;
    msg << "lieBodyLog: the scale component must be finite and > 0, got " << p.scale << ".";
    throw DomainError(msg.str());
  }
  return {rigidLog, shearLog(p.shear), std::log(p.scale)};
}

}  // namespace

LieBody LieBody::Identity() {
  return {Eigen::Matrix4d::Identity(), Eigen::Matrix3d::Identity(), 1.0};
}

LieBodyTangent LieBodyTangent::Zero() { return {Vector6d::Zero(), Eigen::Matrix3d::Zero(), 0.0}; }

LieBodyTangent operator+(const LieBodyTangent& a, const LieBodyTangent& b) {
  return {a.rigid + b.rigid, a.shear + b.shear, a.scale + b.scale};
}

LieBodyTangent operator-(const LieBodyTangent& a, const LieBodyTangent& b) {
  return {a.rigid - b.rigid, a.shear - b.shear, a.scale - b.scale};
}

LieBodyTangent operator*(double w, const LieBodyTangent& x) {
  return {w * x.rigid, w * x.shear, w * x.scale};
}

TetCorners canonicalTetCorners() {
  TetCorners c;
  c << 0, 1, 1, 0,  //
      0, 0, 1, 0,   //
      0, 0, 0, 1;
  return c;
}

LieBody lieBodyFromCorners(const TetCorners& corners) {
  Eigen::Matrix3d edges;
  for (int k = 0; k < 3; ++k) edges.col(k) = corners.col(k + 1) - corners.col(0);
  // edges = Q V with V upper triangular, diag(V) > 0, Q in SO(3): then
  // R = Q^T aligns the tet (Fig. 1 step 1) and V = [v1 v2 v3] (aligned edges).
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr(edges);
  Eigen::Matrix3d q = qr.householderQ();
  Eigen::Matrix3d v = qr.matrixQR().triangularView<Eigen::Upper>();
  for (int i = 0; i < 2; ++i) {
    if (v(i, i) < 0.0) {
      v.row(i) *= -1.0;
      q.col(i) *= -1.0;
    }
  }
  if (q.determinant() < 0.0) {
    v.row(2) *= -1.0;
    q.col(2) *= -1.0;
  }
  if (!corners.allFinite() || !(v(0, 0) > 0.0) || !(v(1, 1) > 0.0) || !(v(2, 2) > 0.0)) {
    std::ostringstream msg;
    msg << "lieBodyFromCorners: the tet must be finite, non-degenerate and positively oriented "
           "(det[u1-u0, u2-u0, u3-u0] > 0); its signed volume is "
        << edges.determinant() / 6.0 << ". Reorder two corners of an inverted tet.";
    throw DomainError(msg.str());
  }
  LieBody p;
  p.rigid.setIdentity();
  p.rigid.topLeftCorner<3, 3>() = q.transpose();
  p.rigid.topRightCorner<3, 1>() = -q.transpose() * corners.col(0);
  p.scale = 1.0 / v(0, 0);
  // Scaled aligned corners w2 = s v2, w3 = s v3 and the shear of eq. (8)-(9).
  const double w2x = p.scale * v(0, 1), w2y = p.scale * v(1, 1);
  const double w3x = p.scale * v(0, 2), w3y = p.scale * v(1, 2), w3z = p.scale * v(2, 2);
  p.shear.setIdentity();
  p.shear(0, 1) = (1.0 - w2x) / w2y;
  p.shear(1, 1) = 1.0 / w2y;
  p.shear(0, 2) = -((1.0 - w2x) * w3y + w3x * w2y) / (w2y * w3z);
  p.shear(1, 2) = -w3y / (w2y * w3z);
  p.shear(2, 2) = 1.0 / w3z;
  return p;
}

Eigen::Matrix3d lieBodyEdges(const LieBody& body) {
  return rotationOf(body).transpose() * (shearInverse(body.shear) * canonicalEdges()) / body.scale;
}

TetCorners lieBodyCorners(const LieBody& body) {
  const Eigen::Vector3d u0 = -rotationOf(body).transpose() * body.rigid.topRightCorner<3, 1>();
  const Eigen::Matrix3d edges = lieBodyEdges(body);
  TetCorners c;
  c.col(0) = u0;
  for (int k = 0; k < 3; ++k) c.col(k + 1) = u0 + edges.col(k);
  return c;
}

Eigen::Matrix4d lieBodyAffine(const LieBody& body) {
  Eigen::Matrix4d sa = Eigen::Matrix4d::Identity();
  sa.topLeftCorner<3, 3>() = body.scale * body.shear;
  return sa * body.rigid;
}

LieBody lieBodyFromAffine(const Eigen::Matrix4d& map) {
  const Eigen::Matrix3d linear = map.topLeftCorner<3, 3>();
  const double det = linear.determinant();
  if (!map.allFinite() || !(det > 0.0) ||
      (map.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > kAffineRowTol) {
    std::ostringstream msg;
    msg << "lieBodyFromAffine: needs a finite homogeneous affine map (last row 0 0 0 1) with "
           "det of the linear part > 0; got det "
        << det << " and last row " << map.row(3) << ".";
    throw DomainError(msg.str());
  }
  // Corners of T^-1 Delta: u0 = -L^-1 t, edges L^-1 [e1, e1 + e2, e3].
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(linear);
  const Eigen::Vector3d u0 = -lu.solve(Eigen::Vector3d(map.topRightCorner<3, 1>()));
  const Eigen::Matrix3d edges = lu.solve(canonicalEdges());
  TetCorners c;
  c.col(0) = u0;
  for (int k = 0; k < 3; ++k) c.col(k + 1) = u0 + edges.col(k);
  return lieBodyFromCorners(c);
}

LieBody lieBodyFromCorners(const TetCorners& corners, const TetCorners& canonical) {
  const LieBody p = lieBodyFromCorners(corners);
  const LieBody c = lieBodyFromCorners(canonical);
  return {p.rigid, shearInverse(c.shear) * p.shear, p.scale / c.scale};
}

TetCorners lieBodyCorners(const LieBody& body, const TetCorners& canonical) {
  const LieBody c = lieBodyFromCorners(canonical);
  return lieBodyCorners(LieBody{body.rigid, c.shear * body.shear, c.scale * body.scale});
}

LieBody lieBodyCompose(const LieBody& a, const LieBody& b) {
  return {a.rigid * b.rigid, a.shear * b.shear, a.scale * b.scale};
}

LieBody lieBodyInverse(const LieBody& p) {
  return {rigidInverse(p.rigid), shearInverse(p.shear), 1.0 / p.scale};
}

LieBody lieBodyExp(const LieBodyTangent& x) {
  return {se3Exp(x.rigid), shearExp(x.shear), std::exp(x.scale)};
}

LieBodyTangent lieBodyLog(const LieBody& p) { return logWithRigid(p, se3Log(p.rigid)); }

LieBodyTangent lieBodyLog(const LieBody& p, const Eigen::Vector3d& rotationReference) {
  const Eigen::Vector3d omega = so3LogClosest(rotationOf(p), rotationReference);
  return logWithRigid(p, twistWithRotation(p.rigid, omega));
}

LieBody lieBodyInterpolate(const LieBody& p, const LieBody& q, double t) {
  return lieBodyCompose(p, lieBodyExp(t * lieBodyLog(lieBodyCompose(lieBodyInverse(p), q))));
}

TetCorners lieBodyInterpolateCorners(const TetCorners& p, const TetCorners& q, double t) {
  return lieBodyCorners(lieBodyInterpolate(lieBodyFromCorners(p), lieBodyFromCorners(q), t));
}

Eigen::Matrix3d lieBodyWorldRotation(const LieBody& rest, const LieBody& example) {
  return rotationOf(example).transpose() * rotationOf(rest);
}

LieBodyTangent lieBodyRelativeLog(const LieBody& rest, const LieBody& example) {
  return lieBodyLog(lieBodyCompose(lieBodyInverse(rest), example));
}

LieBodyTangent lieBodyRelativeLog(const LieBody& rest, const LieBody& example,
                                  const Eigen::Vector3d& worldRotationReference) {
  // The rotation of p0^-1 p_k is R_0^T R_k = W^T, whose logarithms are -log W.
  return lieBodyLog(lieBodyCompose(lieBodyInverse(rest), example), -worldRotationReference);
}

LieBody lieBodyBlend(const LieBody& rest, const std::vector<LieBodyTangent>& relativeLogs,
                     const Eigen::VectorXd& weights) {
  if (weights.size() != static_cast<Eigen::Index>(relativeLogs.size())) {
    std::ostringstream msg;
    msg << "lieBodyBlend: " << weights.size() << " weights for " << relativeLogs.size()
        << " examples; give one weight per example.";
    throw InputError(msg.str());
  }
  LieBodyTangent sum = LieBodyTangent::Zero();
  for (std::size_t k = 0; k < relativeLogs.size(); ++k) {
    sum = sum + weights(static_cast<Eigen::Index>(k)) * relativeLogs[k];
  }
  return lieBodyCompose(rest, lieBodyExp(sum));
}

TetCorners lieBodyBlendCorners(const LieBody& rest, const std::vector<LieBodyTangent>& relativeLogs,
                               const Eigen::VectorXd& weights) {
  return lieBodyCorners(lieBodyBlend(rest, relativeLogs, weights));
}

}  // namespace tetblend
