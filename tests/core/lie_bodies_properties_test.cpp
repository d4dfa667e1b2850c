// The properties Bansal & Tatu prove for Lie-Bodies interpolation (§4,
// Lemmas 1-5, App. A.1.3-A.1.7; §5.1 Theorem 2, App. A.1.8; §5.2.1), checked
// numerically on fixed and seeded random maps and tets.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "lie_test_support.h"
#include "matrix_function_oracle.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/lie_bodies.h"

namespace tetblend {
namespace {

using core_test::expm;
using core_test::logm;
using lie_test::randomAffine;
using lie_test::randomRotation;
using lie_test::randomShear;
using lie_test::randomTet;
using lie_test::testSeed;
using lie_test::uniform;

// Closed forms against MatrixFunctions, relative to the norms involved.
constexpr double kOracleTol = 1e-12;
// Identities that hold exactly in the paper (det, orthonormality, equal
// corners under re-labelling): a few hundred roundings of unit-scale values.
constexpr double kIdentityTol = 1e-12;
// A generic map with rotation and shear is not steady (§4): its T_t differs
// from T^t by at least this (measured ~0.05 for the map below).
constexpr double kNotSteadyGap = 1e-3;
// Re-ordering changes the path when the tets differ by a shear (§5.2.2) or
// by a scaling with a change of first corner: lower bound on the maximal
// corner deviation for the maps used below.
constexpr double kReorderGap = 1e-3;

double relErr(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
  return (got - want).norm() / std::max(1.0, want.norm());
}

// T_t of eq. (2): the interpolation of the affine map T from the identity.
Eigen::Matrix4d interpolatedMap(const Eigen::Matrix4d& map, double t) {
  return lieBodyAffine(lieBodyExp(t * lieBodyLog(lieBodyFromAffine(map))));
}

Eigen::Matrix4d rigidMap(const Eigen::Matrix3d& r, const Eigen::Vector3d& d) {
  Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
  e.topLeftCorner<3, 3>() = r;
  e.topRightCorner<3, 1>() = d;
  return e;
}

Eigen::Matrix4d embed(const Eigen::Matrix3d& a) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = a;
  return m;
}

double tetVolume(const TetCorners& c) {
  Eigen::Matrix3d e;
  for (int k = 0; k < 3; ++k) e.col(k) = c.col(k + 1) - c.col(0);
  return e.determinant() / 6.0;
}

TetCorners transformed(const Eigen::Matrix4d& t, const TetCorners& c) {
  return (t * c.colwise().homogeneous()).topRows<3>();
}

const std::vector<double> kTimes = {-0.5, 0.0, 0.25, 0.5, 0.8, 1.0, 1.5};

TEST(LieBodiesPaper, Lemma1SteadyForOneComponentAndForShearWithScale) {
  std::mt19937 rng(testSeed("Lemma1SteadyForOneComponentAndForShearWithScale"));
  for (int i = 0; i < 40; ++i) {
    const Eigen::Matrix4d e =
        rigidMap(randomRotation(rng, 0.95 * kPi),
                 Eigen::Vector3d(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2)));
    const Eigen::Matrix4d a = embed(randomShear(rng, 1.0, 2.0));
    const Eigen::Matrix4d s =
        embed(std::exp(uniform(rng, -1.5, 1.5)) * Eigen::Matrix3d::Identity());
    const std::array<std::pair<const char*, Eigen::Matrix4d>, 4> maps = {
        {{"E", e}, {"A", a}, {"S", s}, {"AS", a * s}}};
    for (const auto& [name, map] : maps) {
      const Eigen::Matrix4d logMap = logm(map);
      for (double t : kTimes) {
        SCOPED_TRACE(std::string(name) + ", sample " + std::to_string(i) + ", t " +
                     std::to_string(t));
        // Steady: T_t = T^t (App. A.1.3), hence constant relative velocity.
        const Eigen::Matrix4d want = expm(t * logMap);
        EXPECT_LE(relErr(interpolatedMap(map, t), want), kOracleTol * want.norm());
      }
      // One-parameter group: T_{t+h} = T_h T_t.
      EXPECT_LE(relErr(interpolatedMap(map, 0.3) * interpolatedMap(map, 0.45),
                       interpolatedMap(map, 0.75)),
                kIdentityTol * map.norm());
    }
  }
}

TEST(LieBodiesPaper, Lemma1DoesNotClaimSteadinessWithRotationAndShear) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(0, 1) = 1.0;
  const Eigen::Matrix4d map =
      embed(a) * rigidMap(Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                          Eigen::Vector3d(0.5, 0, 0));
  const Eigen::Matrix4d power = expm(0.5 * logm(map));
  EXPECT_GT((interpolatedMap(map, 0.5) - power).norm(), kNotSteadyGap);
}

TEST(LieBodiesPaper, Lemma2And3VolumeIsGeometricHenceMonotoneOrPreserved) {
  std::mt19937 rng(testSeed("Lemma2And3VolumeIsGeometricHenceMonotoneOrPreserved"));
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    Eigen::Matrix4d map = randomAffine(rng);
    const double det = map.topLeftCorner<3, 3>().determinant();
    Eigen::Matrix4d unimodular = map;
    unimodular.topLeftCorner<3, 3>() /= std::cbrt(det);
    double previous = 0.0;
    for (int k = 0; k <= 10; ++k) {
      const double t = k / 10.0;
      // Lemma 2: det T = 1 gives det T_t = 1.
      const double unimodularDet =
          interpolatedMap(unimodular, t).topLeftCorner<3, 3>().determinant();
      EXPECT_NEAR(unimodularDet, 1.0, kIdentityTol);
      // Lemma 3 (App. A.1.5): det T_t = (det T)^t, monotone in t.
      const double dt = interpolatedMap(map, t).topLeftCorner<3, 3>().determinant();
      EXPECT_NEAR(dt, std::pow(det, t), kIdentityTol * std::max(1.0, std::pow(det, t)));
      if (k > 0) {
        EXPECT_TRUE(det > 1.0 ? dt > previous : dt < previous);
      }
      previous = dt;
    }
  }
}

TEST(LieBodiesPaper, Lemma3TetVolumeAlongInterpolationIsGeometric) {
  std::mt19937 rng(testSeed("Lemma3TetVolumeAlongInterpolationIsGeometric"));
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const TetCorners p = randomTet(rng), q = 1.7 * randomTet(rng);
    const double vp = tetVolume(p), vq = tetVolume(q);
    double previous = vp;
    for (int k = 1; k <= 10; ++k) {
      const double t = k / 10.0;
      const double v = tetVolume(lieBodyInterpolateCorners(p, q, t));
      EXPECT_NEAR(v, std::pow(vp, 1 - t) * std::pow(vq, t), kIdentityTol * std::max(vp, vq));
      EXPECT_TRUE(vq > vp ? v > previous : v < previous) << "t " << t;
      previous = v;
    }
  }
}

TEST(LieBodiesPaper, Lemma4IsometriesStayIsometries) {
  std::mt19937 rng(testSeed("Lemma4IsometriesStayIsometries"));
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const Eigen::Matrix4d e =
        rigidMap(randomRotation(rng, 0.95 * kPi),
                 Eigen::Vector3d(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)));
    const TetCorners p = randomTet(rng);
    const TetCorners q = transformed(e, p);
    for (double t : kTimes) {
      const Eigen::Matrix3d l = interpolatedMap(e, t).topLeftCorner<3, 3>();
      EXPECT_LE((l.transpose() * l - Eigen::Matrix3d::Identity()).norm(), kIdentityTol);
      const TetCorners r = lieBodyInterpolateCorners(p, q, t);
      for (int a = 0; a < 4; ++a) {
        for (int b = a + 1; b < 4; ++b) {
          EXPECT_NEAR((r.col(a) - r.col(b)).norm(), (p.col(a) - p.col(b)).norm(), kIdentityTol);
        }
      }
    }
  }
}

TEST(LieBodiesPaper, Lemma5InterpolationIsReversible) {
  std::mt19937 rng(testSeed("Lemma5InterpolationIsReversible"));
  for (int i = 0; i < 100; ++i) {
    const TetCorners p = randomTet(rng), q = randomTet(rng);
    for (double t : {-0.4, 0.1, 0.37, 0.5, 0.9, 1.3}) {
      SCOPED_TRACE("sample " + std::to_string(i) + ", t " + std::to_string(t));
      const TetCorners forward = lieBodyInterpolateCorners(p, q, t);
      const TetCorners backward = lieBodyInterpolateCorners(q, p, 1.0 - t);
      EXPECT_LE((forward - backward).cwiseAbs().maxCoeff(),
                kOracleTol * (1.0 + forward.cwiseAbs().maxCoeff()) *
                    lieBodyFromCorners(forward).shear.norm());
    }
  }
}

// Theorem 2 (App. A.1.8), exactly as proved: the representation against a
// canonical tet Delta_i keeps the rigid component E_p of the standard
// representation and takes (A, s) so that E_{Delta_i}^-1 A S E_p maps the tet
// onto Delta_i (eq. 7). Then (a) the tangent log(p_i^-1 q_i) is the same for
// every Delta_i and (b) the interpolated tets coincide for all t.
TEST(LieBodiesPaper, Theorem2InvariantToTheCanonicalTet) {
  std::mt19937 rng(testSeed("Theorem2InvariantToTheCanonicalTet"));
  for (int i = 0; i < 60; ++i) {
    const TetCorners p = randomTet(rng), q = randomTet(rng);
    const std::array<TetCorners, 3> canonicals = {canonicalTetCorners(), randomTet(rng),
                                                  2.5 * randomTet(rng)};
    std::vector<LieBodyTangent> tangents;
    std::vector<TetCorners> paths;
    for (const TetCorners& delta : canonicals) {
      const LieBody pi = lieBodyFromCorners(p, delta), qi = lieBodyFromCorners(q, delta);
      // Eq. 7: E_Delta^-1 A S E_p maps p onto Delta.
      const Eigen::Matrix4d map =
          lieBodyFromCorners(delta).rigid.inverse() *
          lieBodyAffine(LieBody{Eigen::Matrix4d::Identity(), pi.shear, pi.scale}) * pi.rigid;
      EXPECT_LE((transformed(map, p) - delta).cwiseAbs().maxCoeff(),
                kOracleTol * map.norm() * delta.cwiseAbs().maxCoeff());
      tangents.push_back(lieBodyLog(lieBodyCompose(lieBodyInverse(pi), qi)));
      for (double t : {-0.3, 0.4, 0.8, 1.2}) {
        paths.push_back(lieBodyCorners(lieBodyInterpolate(pi, qi, t), delta));
      }
    }
    const std::size_t perCanonical = paths.size() / canonicals.size();
    for (std::size_t c = 1; c < canonicals.size(); ++c) {
      SCOPED_TRACE("sample " + std::to_string(i) + ", canonical " + std::to_string(c));
      EXPECT_LE((tangents[c].rigid - tangents[0].rigid).norm(), kOracleTol);
      EXPECT_LE((tangents[c].shear - tangents[0].shear).norm(),
                kOracleTol * tangents[0].shear.norm());
      EXPECT_NEAR(tangents[c].scale, tangents[0].scale, kOracleTol);
      for (std::size_t k = 0; k < perCanonical; ++k) {
        const TetCorners& want = paths[k];
        EXPECT_LE((paths[c * perCanonical + k] - want).cwiseAbs().maxCoeff(),
                  kOracleTol * (1.0 + want.cwiseAbs().maxCoeff()) *
                      lieBodyFromCorners(want).shear.norm());
      }
    }
  }
}

// The 12 orientation-preserving (even) re-orderings of a tet's corners; with
// `keepFirst`, only the 3 that keep corner 0 first.
std::vector<std::array<int, 4>> evenOrderings(bool keepFirst) {
  std::vector<std::array<int, 4>> out;
  std::array<int, 4> perm = {0, 1, 2, 3};
  do {
    int inversions = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) inversions += perm[a] > perm[b];
    if (inversions % 2 == 0 && (!keepFirst || perm[0] == 0)) out.push_back(perm);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

TetCorners reordered(const TetCorners& c, const std::array<int, 4>& perm) {
  TetCorners out;
  for (int k = 0; k < 4; ++k) out.col(k) = c.col(perm[k]);
  return out;
}

// Largest corner deviation, over re-orderings and a few t, between the path
// of the re-ordered tets and the re-ordered path (§5.2).
double reorderDeviation(const TetCorners& p, const TetCorners& q, bool keepFirst) {
  double worst = 0.0;
  for (const auto& perm : evenOrderings(keepFirst)) {
    for (double t : {0.25, 0.5, 0.75}) {
      const TetCorners path = reordered(lieBodyInterpolateCorners(p, q, t), perm);
      const TetCorners other = lieBodyInterpolateCorners(reordered(p, perm), reordered(q, perm), t);
      worst = std::max(worst, (path - other).cwiseAbs().maxCoeff());
    }
  }
  return worst;
}

Eigen::Vector3d randomShift(std::mt19937& rng) {
  return Eigen::Vector3d(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
}

// §5.2.1 claims invariance to re-ordering when q = S E p. What holds: p^-1 q
// = (E_p^-1 E_q, I, 1/s) with E_p^-1 E_q = [R^T, (1 - s) u0 - s R^T d], which
// is E^-1 for every ordering when s = 1 (isometries) and depends on the first
// corner u0 otherwise. So: isometries are invariant under all 12 even
// orderings, similarities under the 3 that keep the first corner, and a
// similarity with s != 1 is not invariant under the others (nor is a shear,
// §5.2.2).
TEST(LieBodiesPaper, Section52ReorderingInvarianceForIsometriesAndSimilarities) {
  std::mt19937 rng(testSeed("Section52ReorderingInvarianceForIsometriesAndSimilarities"));
  for (int i = 0; i < 30; ++i) {
    SCOPED_TRACE("sample " + std::to_string(i));
    const TetCorners p = randomTet(rng);
    const Eigen::Matrix4d isometry = rigidMap(randomRotation(rng, 0.9 * kPi), randomShift(rng));
    EXPECT_LE(reorderDeviation(p, transformed(isometry, p), false), kIdentityTol);
    const Eigen::Matrix4d similarity =
        rigidMap(std::exp(uniform(rng, -1, 1)) * randomRotation(rng, 0.9 * kPi), randomShift(rng));
    EXPECT_LE(reorderDeviation(p, transformed(similarity, p), true), kIdentityTol);
  }
  Eigen::Matrix4d scaling = Eigen::Matrix4d::Identity();
  scaling.topLeftCorner<3, 3>() *= 2.0;
  EXPECT_GT(
      reorderDeviation(canonicalTetCorners(), transformed(scaling, canonicalTetCorners()), false),
      kReorderGap);
  Eigen::Matrix4d shear = Eigen::Matrix4d::Identity();
  shear(0, 1) = 0.8;
  shear(1, 2) = -0.5;
  EXPECT_GT(
      reorderDeviation(canonicalTetCorners(), transformed(shear, canonicalTetCorners()), true),
      kReorderGap);
}

}  // namespace
}  // namespace tetblend
