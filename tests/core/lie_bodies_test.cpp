#include "tetblend/core/lie_bodies.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lie_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using lie_test::randomAffine;
using lie_test::randomTet;
using lie_test::testSeed;
using lie_test::uniform;

// Round trips and identities of unit-scale group elements: a few dozen
// roundings (e.g. Householder QR, 3x3 products and inverses).
constexpr double kRoundTripTol = 1e-13;
// Closed forms against Eigen's MatrixFunctions on unit-scale elements: both
// are accurate to a few hundred ulps (see shear_group_test.cpp).
constexpr double kOracleTol = 1e-12;
// Corner round trips, relative to the tet's size plus its distance from the
// origin. Householder QR is backward stable, but the shear parameters of a
// tet whose first face is nearly flat are ill-conditioned: a relative change
// of eps in A moves the corners by ~eps cond(A), cond(A) = |A|_F |A^-1|_F
// (~1/sin of the smallest angle of the first face). Measured: < 0.5 eps
// cond(A) over 3e4 random near-degenerate tets; 8 eps cond(A) leaves ~16x.
constexpr double kCornerTolPerCondition = 8 * std::numeric_limits<double>::epsilon();

double shearCondition(const TetCorners& c) {
  const Eigen::Matrix3d a = lieBodyFromCorners(c).shear;
  return a.norm() * a.inverse().norm();
}

double relErr(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
  return (got - want).norm() / std::max(1.0, want.norm());
}

Eigen::Matrix3d edgesOf(const TetCorners& c) {
  Eigen::Matrix3d e;
  for (int k = 0; k < 3; ++k) e.col(k) = c.col(k + 1) - c.col(0);
  return e;
}

// Size scale of a corner set for absolute corner errors: its extent plus its
// distance from the origin.
double cornerScale(const TetCorners& c) {
  return (c.rowwise().maxCoeff() - c.rowwise().minCoeff()).norm() + c.cwiseAbs().maxCoeff();
}

TetCorners transformed(const Eigen::Matrix4d& t, const TetCorners& c) {
  return (t * c.colwise().homogeneous()).topRows<3>();
}

struct NamedTet {
  std::string name;
  TetCorners corners;
};

std::vector<NamedTet> hardTets() {
  const TetCorners canonical = canonicalTetCorners();
  TetCorners regular;
  regular << 1, -1, -1, 1,  //
      1, -1, 1, -1,         //
      1, 1, -1, -1;
  if (edgesOf(regular).determinant() < 0) regular.col(1).swap(regular.col(2));
  TetCorners sliver = canonical;
  sliver.col(3) << 0.5, 0.5, 1e-9;  // fourth corner almost in the first face
  TetCorners needle = canonical;
  needle.col(1) << 1e-7, 0, 0;  // first edge 1e-7 long
  TetCorners flatFace = canonical;
  flatFace.col(2) << 1, 1e-9, 0;  // first two edges almost parallel
  TetCorners rotatedPi = transformed(
      (Eigen::Matrix4d() << -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1).finished(),
      regular);  // aligning rotation of angle pi
  Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
  far.topRightCorner<3, 1>() << 1e6, -2e6, 3e6;
  return {{"canonical", canonical},
          {"regular", regular},
          {"scaled 1e-6", 1e-6 * regular},
          {"scaled 1e6", 1e6 * regular},
          {"translated 1e6", transformed(far, regular)},
          {"rotated by pi", rotatedPi},
          {"sliver (height 1e-9)", sliver},
          {"needle (first edge 1e-7)", needle},
          {"first edges almost parallel", flatFace}};
}

// Paper Fig. 1 / App. A.1.2 built independently: Gram-Schmidt by cross
// products, s = 1/|e1|, A = C W^-1 by a general inverse.
LieBody paperDecomposition(const TetCorners& c) {
  const Eigen::Matrix3d e = edgesOf(c);
  const Eigen::Vector3d r1 = e.col(0).normalized();
  const Eigen::Vector3d r3 = e.col(0).cross(e.col(1)).normalized();
  Eigen::Matrix3d r;
  r.row(0) = r1.transpose();
  r.row(1) = r3.cross(r1).transpose();
  r.row(2) = r3.transpose();
  LieBody p;
  p.rigid.setIdentity();
  p.rigid.topLeftCorner<3, 3>() = r;
  p.rigid.topRightCorner<3, 1>() = -r * c.col(0);
  p.scale = 1.0 / e.col(0).norm();
  const Eigen::Matrix3d w = p.scale * r * e;
  Eigen::Matrix3d canonicalEdges;
  canonicalEdges << 1, 1, 0, 0, 1, 0, 0, 0, 1;
  p.shear = canonicalEdges * w.inverse();
  return p;
}

TEST(LieBodies, DecompositionMatchesThePaperConstruction) {
  std::mt19937 rng(testSeed("DecompositionMatchesThePaperConstruction"));
  for (int i = 0; i < 200; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const TetCorners c = randomTet(rng);
    const LieBody got = lieBodyFromCorners(c);
    const LieBody want = paperDecomposition(c);
    EXPECT_LE(relErr(got.rigid, want.rigid), kOracleTol);
    EXPECT_LE(relErr(got.shear, want.shear), kOracleTol * want.shear.norm());
    EXPECT_NEAR(got.scale, want.scale, kOracleTol * want.scale);
    // Theorem 1: A S E maps the tet onto the canonical tet.
    EXPECT_LE(relErr(transformed(lieBodyAffine(got), c), canonicalTetCorners()),
              kOracleTol * want.shear.norm());
  }
}

TEST(LieBodies, CornerRoundTripOnHardTets) {
  for (const NamedTet& t : hardTets()) {
    SCOPED_TRACE(t.name);
    const LieBody p = lieBodyFromCorners(t.corners);
    const Eigen::Matrix3d r = p.rigid.topLeftCorner<3, 3>();
    EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), kRoundTripTol);
    EXPECT_NEAR(r.determinant(), 1.0, kRoundTripTol);
    EXPECT_GT(p.shear(1, 1), 0.0);
    EXPECT_GT(p.shear(2, 2), 0.0);
    EXPECT_GT(p.scale, 0.0);
    const TetCorners back = lieBodyCorners(p);
    const double tol = kCornerTolPerCondition * shearCondition(t.corners);
    EXPECT_LE((back - t.corners).cwiseAbs().maxCoeff(), tol * cornerScale(t.corners));
    const Eigen::Matrix3d e = edgesOf(t.corners);
    EXPECT_LE((lieBodyEdges(p) - e).norm(), tol * e.norm());
  }
}

TEST(LieBodies, CornerRoundTripOnRandomAndNearDegenerateTets) {
  std::mt19937 rng(testSeed("CornerRoundTripOnRandomAndNearDegenerateTets"));
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    TetCorners c = randomTet(rng);
    // Two of three samples are near-degenerate: corner 2 squashed towards the
    // line u0 u1 (flat first face) or corner 3 towards the plane u0 u1 u2.
    const double squash = std::pow(10.0, -uniform(rng, 3.0, 9.0));
    const Eigen::Matrix3d e = edgesOf(c);
    const Eigen::Vector3d e1 = e.col(0).normalized();
    if (i % 3 == 1) {
      c.col(2) -= (1.0 - squash) * (e.col(1) - e1.dot(e.col(1)) * e1);
    } else if (i % 3 == 2) {
      const Eigen::Vector3d n = e.col(0).cross(e.col(1)).normalized();
      c.col(3) -= (1.0 - squash) * n.dot(e.col(2)) * n;
    }
    const TetCorners back = lieBodyCorners(lieBodyFromCorners(c));
    EXPECT_LE((back - c).cwiseAbs().maxCoeff(),
              kCornerTolPerCondition * shearCondition(c) * cornerScale(c));
  }
}

TEST(LieBodies, AffineMapRoundTripAndItsTet) {
  std::mt19937 rng(testSeed("AffineMapRoundTripAndItsTet"));
  for (int i = 0; i < 200; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const Eigen::Matrix4d t = randomAffine(rng);
    const LieBody p = lieBodyFromAffine(t);
    EXPECT_LE(relErr(lieBodyAffine(p), t), kOracleTol * t.inverse().norm());
    // The representation of T is that of the tet T^-1 Delta (§3.4).
    const TetCorners preimage = transformed(t.inverse(), canonicalTetCorners());
    EXPECT_LE(relErr(lieBodyCorners(p), preimage), kOracleTol * t.inverse().norm());
  }
}

TEST(LieBodies, RejectsInvalidInput) {
  TetCorners inverted = canonicalTetCorners();
  inverted.col(1).swap(inverted.col(2));
  EXPECT_THROW(lieBodyFromCorners(inverted), DomainError);
  TetCorners flat = canonicalTetCorners();
  flat.col(3).setZero();
  EXPECT_THROW(lieBodyFromCorners(flat), DomainError);
  TetCorners nan = canonicalTetCorners();
  nan(0, 3) = std::nan("");
  EXPECT_THROW(lieBodyFromCorners(nan), DomainError);
  Eigen::Matrix4d mirror = Eigen::Matrix4d::Identity();
  mirror(0, 0) = -1;
  EXPECT_THROW(lieBodyFromAffine(mirror), DomainError);
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
  projective(3, 0) = 0.1;
  EXPECT_THROW(lieBodyFromAffine(projective), DomainError);
  const LieBody p = LieBody::Identity();
  EXPECT_THROW(lieBodyBlend(p, {LieBodyTangent::Zero()}, Eigen::VectorXd::Ones(2)), InputError);
}

TEST(LieBodies, GroupOperationsExpAndLogMatchTheMatrixOracle) {
  std::mt19937 rng(testSeed("GroupOperationsExpAndLogMatchTheMatrixOracle"));
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const LieBody p = lieBodyFromCorners(randomTet(rng));
    const LieBody q = lieBodyFromCorners(randomTet(rng));
    const LieBody pq = lieBodyCompose(p, q);
    EXPECT_LE(relErr(lieBodyAffine(pq).topLeftCorner<3, 3>(),
                     pq.scale * pq.shear * pq.rigid.topLeftCorner<3, 3>()),
              kRoundTripTol * pq.shear.norm());
    const LieBody e = lieBodyCompose(p, lieBodyInverse(p));
    EXPECT_LE(relErr(e.rigid, Eigen::Matrix4d::Identity()),
              kRoundTripTol * cornerScale(lieBodyCorners(p)));
    EXPECT_LE(relErr(e.shear, Eigen::Matrix3d::Identity()),
              kRoundTripTol * p.shear.norm() * lieBodyInverse(p).shear.norm());
    EXPECT_NEAR(e.scale, 1.0, kRoundTripTol);
    const LieBodyTangent x = lieBodyLog(p);
    EXPECT_LE(relErr(se3Hat(x.rigid), logm(p.rigid)), kOracleTol);
    EXPECT_LE(relErr(x.shear, logm(p.shear)), kOracleTol * p.shear.norm());
    EXPECT_NEAR(x.scale, std::log(p.scale), kRoundTripTol);
    const LieBody back = lieBodyExp(x);
    EXPECT_LE(relErr(back.rigid, p.rigid), kOracleTol);
    EXPECT_LE(relErr(back.shear, p.shear), kOracleTol * p.shear.norm());
    EXPECT_NEAR(back.scale, p.scale, kRoundTripTol * p.scale);
  }
}

TEST(LieBodies, InterpolationAndExtrapolationAreThePerComponentGeodesic) {
  std::mt19937 rng(testSeed("InterpolationAndExtrapolationAreThePerComponentGeodesic"));
  for (int i = 0; i < 60; ++i) {
    const LieBody p = lieBodyFromCorners(randomTet(rng));
    const LieBody q = lieBodyFromCorners(randomTet(rng));
    const Eigen::Matrix4d logE = logm(p.rigid.inverse() * q.rigid);
    const Eigen::Matrix3d logA = logm(p.shear.inverse() * q.shear);
    for (double t : {-0.75, 0.0, 0.3, 0.5, 1.0, 1.75}) {
      SCOPED_TRACE("sample " + std::to_string(i) + ", t = " + std::to_string(t));
      const LieBody r = lieBodyInterpolate(p, q, t);
      const Eigen::Matrix4d wantE = p.rigid * expm(t * logE);
      const Eigen::Matrix3d wantA = p.shear * expm(t * logA);
      const double scale = wantA.norm() + wantE.norm();
      EXPECT_LE(relErr(r.rigid, wantE), kOracleTol * scale);
      EXPECT_LE(relErr(r.shear, wantA), kOracleTol * scale);
      EXPECT_NEAR(r.scale, p.scale * std::pow(q.scale / p.scale, t), kOracleTol * r.scale);
    }
  }
}

TEST(LieBodies, InterpolatedCornersHitTheEndpoints) {
  std::mt19937 rng(testSeed("InterpolatedCornersHitTheEndpoints"));
  for (int i = 0; i < 50; ++i) {
    const TetCorners a = randomTet(rng), b = randomTet(rng);
    EXPECT_LE((lieBodyInterpolateCorners(a, b, 0.0) - a).cwiseAbs().maxCoeff(),
              kOracleTol * cornerScale(a));
    EXPECT_LE((lieBodyInterpolateCorners(a, b, 1.0) - b).cwiseAbs().maxCoeff(),
              kOracleTol * cornerScale(b) * lieBodyFromCorners(b).shear.norm());
  }
}

}  // namespace
}  // namespace tetblend
