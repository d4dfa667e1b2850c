// rotationLifts (rotation_consistency.h) on synthetic chains of rotations
// R_i = R_z(theta_i) R_x(alpha): the polar rotations along a twisted bar,
// whose twist shear tilts them by alpha about a horizontal axis. As theta_i
// passes 2 pi and 4 pi every logarithm of R_i lies near the tilt axis, yet
// the lift must keep following theta_i z, and exp(base) exp(correction) must
// still be R_i.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <random>

#include "blending_test_support.h"
#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

// exp(base) exp(correction) against R: products and Rodrigues' formula on
// vectors of length up to ~4.5 pi, each entry a few ulps of 1 per operation.
constexpr double kRoundTrip = 1e-14;
// Logarithms carried along a chain of ~20 relative turns (each log and
// closest-log a few ulps of angles ~2 rad), or Eigen's angle-axis oracle of
// the last one: ~1e-14 of accumulated round-off.
constexpr double kChainLogTolerance = 1e-12;

Eigen::Matrix3d tiltedTurn(double theta, double alpha) {
  return (Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// A chain of `count` tets, tet i adjacent to i - 1 and i + 1.
TetAdjacency chain(int count) {
  TetAdjacency adjacency;
  adjacency.neighbours.resize(count);
  for (int i = 0; i + 1 < count; ++i) {
    adjacency.neighbours[i].push_back(i + 1);
    adjacency.neighbours[i + 1].push_back(i);
  }
  return adjacency;
}

// Independent oracle of Kaji–Ochiai Alg. 1: the closest of the logarithms
// (phi + 2 pi k) a, k in [-4, 4], of R, from Eigen's angle-axis.
Eigen::Vector3d closestLogOracle(const Eigen::Matrix3d& r, const Eigen::Vector3d& reference) {
  const Eigen::AngleAxisd aa(r);
  Eigen::Vector3d best = aa.angle() * aa.axis();
  for (int k = -4; k <= 4; ++k) {
    const Eigen::Vector3d candidate = (aa.angle() + 2.0 * kPi * k) * aa.axis();
    if ((candidate - reference).norm() < (best - reference).norm()) best = candidate;
  }
  return best;
}

void expectLiftReproduces(const RotationLift& lift, const Eigen::Matrix3d& r) {
  EXPECT_LE((so3Exp(lift.base) * so3Exp(lift.correction) - r).cwiseAbs().maxCoeff(), kRoundTrip);
  EXPECT_LE(lift.correction.norm(), kPi);
}

// The base follows the twist: its axial part is within kAxialTolerance of
// theta_i (a wrong branch is 2 pi away). A snapped base is an exact log of
// R_i, whose axial part differs from theta_i through the tilt (second order,
// alpha^2 / 2 at worst for alpha <= 0.7: ~0.25 rad), and the prediction
// carried through the uncorrectable band adds the relative logs' axial parts,
// which the same bound covers.
constexpr double kAxialTolerance = 0.5;

// rotation_consistency.cpp's snap ratio (the specification of the threshold).
constexpr double kSnapRatio = 1.0;

TEST(RotationLift, FollowsTiltedTurnsThroughTwoPiAndFourPi) {
  std::mt19937 rng(testing::testSeed());
  SCOPED_TRACE("seed " + std::to_string(testing::testSeed()));
  std::uniform_real_distribution<double> tilt(0.05, 0.7);
  for (double alpha : {0.0, 1e-9, 0.3, 0.7, tilt(rng), tilt(rng), tilt(rng)}) {
    SCOPED_TRACE(alpha);
    constexpr double kStep = 0.05;  // radians of turn between neighbours
    std::vector<double> thetas;
    for (double theta = 0.0; theta <= 4.5 * kPi; theta += kStep) thetas.push_back(theta);
    thetas.push_back(2.0 * kPi);  // exactly on the singular turns, at the chain's end
    std::vector<Eigen::Matrix3d> rotations;
    for (double theta : thetas) rotations.push_back(tiltedTurn(theta, alpha));
    const int count = static_cast<int>(rotations.size());
    // Tet 0 must be the seed: the smallest principal angle, alpha, ties with
    // the tets at 2 pi and 4 pi and the lowest index wins.
    const TetAdjacency adjacency = chain(count);
    const std::vector<RotationLift> lifts =
        rotationLifts(rotations, adjacency, tetComponents(adjacency), true);
    int corrected = 0;
    for (int i = 0; i < count - 1; ++i) {
      SCOPED_TRACE(thetas[i]);
      expectLiftReproduces(lifts[i], rotations[i]);
      EXPECT_NEAR(lifts[i].base.z(), thetas[i], kAxialTolerance);
      if (!lifts[i].correction.isZero(0.0)) ++corrected;
    }
    // The last tet (2 pi, reached from 4.5 pi) is still lifted, on the 4.5 pi
    // side's branch: the chain is one path.
    expectLiftReproduces(lifts[count - 1], rotations[count - 1]);
    std::cout << "alpha " << alpha << ": " << corrected << " of " << count - 1
              << " tets corrected\n";
    if (alpha > 0.1) {
      EXPECT_GT(corrected, 0);  // the band around 2 pi needs the correction
    }
  }
}

TEST(RotationLift, PrincipalWhenNotConsistent) {
  std::vector<Eigen::Matrix3d> rotations = {tiltedTurn(0.0, 0.3), tiltedTurn(2.5, 0.3),
                                            tiltedTurn(5.0, 0.3)};
  const TetAdjacency adjacency = chain(3);
  const auto lifts = rotationLifts(rotations, adjacency, tetComponents(adjacency), false);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(lifts[i].correction.isZero(0.0));
    EXPECT_LE(lifts[i].base.norm(), kPi);
    expectLiftReproduces(lifts[i], rotations[i]);
  }
}

// Both sides of the snap threshold: a chain of pure turns up to theta = 1.8,
// then one tet R_n = R_z(theta) R_x(alpha). With delta = log(R_n
// R_{n-1}^T), its prediction is theta z + delta; it snaps to the closest
// logarithm while that is within kSnapRatio |delta| of the prediction. alpha is
// bisected (with the oracle) onto the threshold, then moved by 1e-6 either
// way.
TEST(RotationLift, SnapThresholdBothSides) {
  constexpr double kX = 2.0 * kPi - 1.8;  // a turn of 1.8 rad: |J_l^-1 - I| ~ 0.94
  constexpr double kStep = 0.1;
  constexpr double kTheta = 2.0 * kPi - kX;
  std::vector<Eigen::Matrix3d> turns;
  for (double theta = 0.0; theta < kTheta; theta += kStep) turns.push_back(tiltedTurn(theta, 0.0));
  turns.push_back(tiltedTurn(kTheta, 0.0));
  auto predictionFor = [&](double alpha) {
    const Eigen::AngleAxisd delta(tiltedTurn(kTheta, alpha) * tiltedTurn(kTheta, 0.0).transpose());
    return Eigen::Vector3d(kTheta * Eigen::Vector3d::UnitZ() + delta.angle() * delta.axis());
  };
  auto excess = [&](double alpha) {  // distance beyond the snap tolerance |delta|
    const Eigen::Vector3d prediction = predictionFor(alpha);
    return (closestLogOracle(tiltedTurn(kTheta, alpha), prediction) - prediction).norm() -
           kSnapRatio * std::abs(alpha);
  };
  double lo = 1e-3, hi = 2.5;
  ASSERT_LT(excess(lo), 0.0);
  ASSERT_GT(excess(hi), 0.0);
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) <= 0.0 ? lo : hi) = mid;
  }
  std::cout << "snap threshold at alpha = " << lo << " for a turn of " << kTheta << "\n";
  for (double alpha : {lo * (1.0 - 1e-6), hi * (1.0 + 1e-6)}) {
    SCOPED_TRACE(alpha);
    std::vector<Eigen::Matrix3d> rotations = turns;
    rotations.push_back(tiltedTurn(kTheta, alpha));
    const int count = static_cast<int>(rotations.size());
    const TetAdjacency adjacency = chain(count);
    const auto lifts = rotationLifts(rotations, adjacency, tetComponents(adjacency), true);
    const RotationLift& last = lifts[count - 1];
    expectLiftReproduces(last, rotations[count - 1]);
    ASSERT_LE((lifts[count - 2].base - kTheta * Eigen::Vector3d::UnitZ()).norm(),
              kChainLogTolerance);
    const Eigen::Vector3d prediction = predictionFor(alpha);
    if (alpha < lo) {
      EXPECT_TRUE(last.correction.isZero(0.0));
      EXPECT_LE((last.base - closestLogOracle(rotations[count - 1], prediction)).norm(),
                kChainLogTolerance);
    } else {
      EXPECT_FALSE(last.correction.isZero(0.0));
      EXPECT_LE((last.base - prediction).norm(), kChainLogTolerance);
    }
  }
}

}  // namespace
}  // namespace tetblend
