// The untangler (meshing/src/untangle.h) on a Kuhn-subdivided cube grid whose
// interior is folded in several places: every tet valid afterwards, the
// fixed vertices bit for bit, and the same with the free region narrowed as
// the inverted tets become few (FreeRegionAround).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "kuhn_grid.h"
#include "test_seed.h"
#include "tet_elements.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/compatible_tets.h"
#include "untangle.h"

namespace tetblend {
namespace {

constexpr int kCells = 8;  // cells per side
const KuhnGrid kGrid{kCells};

int vertexIndex(int i, int j, int k) { return kGrid.index(i, j, k); }
bool onBoundary(int v) { return kGrid.onBoundary(v); }
TetMesh kuhnGrid() { return kGrid.mesh(); }

// The interior vertices of `tets` and of the tets sharing a vertex with them.
std::vector<int> interiorAround(const TetMesh& mesh, const std::vector<int>& tets) {
  std::set<int> near;
  for (int t : tets) {
    for (int a = 0; a < 4; ++a) near.insert(mesh.tets(t, a));
  }
  std::set<int> region;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    bool touches = false;
    for (int a = 0; a < 4; ++a) touches = touches || near.count(mesh.tets(t, a)) > 0;
    if (!touches) continue;
    for (int a = 0; a < 4; ++a) {
      if (!onBoundary(mesh.tets(t, a))) region.insert(mesh.tets(t, a));
    }
  }
  return {region.begin(), region.end()};
}

// The grid with interior vertices pushed through their neighbours: six by
// 1.2 cells (folds that untangle in a few rounds) and one by 3.5 cells, far
// from them (one that takes many more).
Vertices foldedGrid(const TetMesh& mesh) {
  Vertices positions = mesh.vertices;
  for (int i : {2, 4, 6}) {
    positions(vertexIndex(i, 2, 2), 0) += 1.2 / kCells;
    positions(vertexIndex(i, 2, 6), 1) += 1.2 / kCells;
  }
  positions(vertexIndex(4, 6, 4), 2) -= 3.5 / kCells;
  return positions;
}

std::vector<int> interiorVertices(const TetMesh& mesh) {
  std::vector<int> interior;
  for (int v = 0; v < static_cast<int>(mesh.vertices.rows()); ++v) {
    if (!onBoundary(v)) interior.push_back(v);
  }
  return interior;
}

TEST(Untangle, AFoldedGridComesBackValidWithItsBoundaryBitForBit) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  Vertices positions = foldedGrid(mesh);
  const Vertices start = positions;
  ASSERT_GE(invertedTets(positions, mesh.tets).size(), 4u);
  untangle(mesh.tets, elements, interiorVertices(mesh), UntangleEffort{}, positions);
  EXPECT_TRUE(invertedTets(positions, mesh.tets).empty());
  for (int v = 0; v < static_cast<int>(positions.rows()); ++v) {
    if (onBoundary(v)) {
      EXPECT_EQ(positions.row(v), start.row(v)) << "vertex " << v;
    }
  }
}

TEST(Untangle, NarrowingTheRegionToTheLastInvertedTetsStillUntanglesThem) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  Vertices positions = foldedGrid(mesh);
  const Vertices start = positions;
  const std::vector<int> inverted = invertedTets(positions, mesh.tets);
  const std::vector<int> first = interiorAround(mesh, inverted);
  std::vector<std::size_t> asked;  // tets asked about, per call
  std::set<int> everFree(first.begin(), first.end());
  const FreeRegionAround around = [&](const std::vector<int>& bad) {
    asked.push_back(bad.size());
    std::vector<int> region = interiorAround(mesh, bad);
    everFree.insert(region.begin(), region.end());
    return region;
  };
  // One Newton step a round, as for self-intersecting examples: with two
  // (the second on the first one's factor) this fold is untangled before
  // its count falls to a quarter, and the region is never narrowed.
  UntangleEffort effort;
  effort.iterationsPerRound = 1;
  untangle(mesh.tets, elements, first, effort, positions, around);
  EXPECT_TRUE(invertedTets(positions, mesh.tets).empty());
  // The region was narrowed, to a quarter of the inverted tets or fewer.
  ASSERT_FALSE(asked.empty()) << inverted.size() << " inverted tets at the start";
  EXPECT_LE(4 * asked.front(), inverted.size());
  for (int v = 0; v < static_cast<int>(positions.rows()); ++v) {
    if (everFree.count(v) == 0) {
      EXPECT_EQ(positions.row(v), start.row(v)) << "vertex " << v;
    }
  }
}

// A fold the untangler cannot repair: the centre of the grid's top face
// (3 × 3 fixed vertices) pushed down through the interior and out of the
// bottom face (the surface then intersects itself). Rounds that relax the
// region around it invert more tets (54 at the start, 384 after the 40th
// round when the last state was returned); the state returned must be the
// best one reached, no worse than the start.
// The grid with the centre of its top face pushed out through its bottom face.
Vertices hopelessFold(const TetMesh& mesh) {
  Vertices positions = mesh.vertices;
  for (int i = 3; i <= 5; ++i)
    for (int j = 3; j <= 5; ++j) positions(vertexIndex(i, j, kCells), 2) -= (kCells + 2.0) / kCells;
  return positions;
}

TEST(Untangle, AHopelessFoldComesBackNoWorseThanItStarted) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  Vertices positions = hopelessFold(mesh);
  const std::vector<int> before = invertedTets(positions, mesh.tets);
  ASSERT_FALSE(before.empty());
  double minDetBefore = INFINITY;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    minDetBefore = std::min(minDetBefore, deformationGradient(positions, mesh.tets.row(t),
                                                              elements[static_cast<size_t>(t)])
                                              .determinant());
  }
  UntangleEffort brief;  // ExampleAwareOptions::intersectingUntangle's, 8 stalled rounds
  brief.iterationsPerRound = 1;
  brief.maxRounds = 40;
  brief.minDetProgress = 1e-3;
  brief.stallRounds = brief.firstAttemptStallRounds = 8;
  const UntangleOutcome outcome =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  const std::vector<int> after = invertedTets(positions, mesh.tets);
  std::cout << "  " << before.size() << " inverted tets, min det F " << minDetBefore << " -> "
            << after.size() << ", " << outcome.minDet << " after " << outcome.rounds << " rounds\n";
  EXPECT_FALSE(after.empty());
  EXPECT_TRUE(after.size() < before.size() ||
              (after.size() == before.size() && outcome.minDet >= minDetBefore));
}

// One Newton step per round, at most maxRounds rounds, and no stall test
// (any rise of min det F is progress): only the limit under test stops.
UntangleEffort withoutStallTests(int maxRounds) {
  UntangleEffort effort;
  effort.iterationsPerRound = 1;
  effort.maxRounds = maxRounds;
  effort.minDetProgress = 0.0;
  effort.stallRounds = effort.firstAttemptStallRounds = 1000;
  return effort;
}

// UntangleEffort::roundsToFallBelowStart on the hopeless fold. Its first
// rounds all end with no fewer inverted tets than at the start: 4 rounds
// return the start bit for bit (the best state reached). With a limit of 4,
// the attempt then stops after those 4 rounds; without one, it goes on.
TEST(Untangle, AnAttemptThatNeverFallsBelowItsStartGivesUpAfterItsRounds) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const Vertices start = hopelessFold(mesh);
  UntangleEffort brief = withoutStallTests(4);
  Vertices positions = start;
  const UntangleOutcome four =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  ASSERT_EQ(four.rounds, 4);
  ASSERT_TRUE(positions == start) << "a round within the first 4 fell below the start";

  brief.maxRounds = 40;
  positions = start;
  const UntangleOutcome unlimited =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  EXPECT_GT(unlimited.rounds, 4);

  brief.roundsToFallBelowStart = 4;
  positions = start;
  const UntangleOutcome limited =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  EXPECT_EQ(limited.rounds, 4);
  EXPECT_TRUE(positions == start);
}

// UntangleEffort::risingRoundsToGiveUp on the hopeless fold. From 54
// inverted tets its rounds end with 106, 182, 148, 164, 148, 200, ... (a
// scratch trace, with the factor kept across rounds by kModelAgreement):
// with the limit at 2, rounds 1 and 2 rise in a row and the attempt stops
// after round 2, returning its best state, the start (no round fell below
// it); without the limit it runs its 8 rounds.
TEST(Untangle, AnAttemptWhoseCountKeepsRisingGivesUp) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const Vertices start = hopelessFold(mesh);
  UntangleEffort brief = withoutStallTests(8);
  Vertices positions = start;
  const UntangleOutcome unlimited =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  EXPECT_EQ(unlimited.rounds, 8);

  brief.risingRoundsToGiveUp = 2;
  positions = start;
  const UntangleOutcome limited =
      untangle(mesh.tets, elements, interiorVertices(mesh), brief, positions);
  EXPECT_EQ(limited.rounds, 2);
  EXPECT_TRUE(positions == start);
}

// UntangleEffort::largestStartEpsilon on the folded grid, one Newton step:
// the first ε is min(largestStartEpsilon, 2 |min det F|), so every cap at or
// above 2 |min det F| gives the same step bit for bit, and a cap below it
// (0.1, where the fold's |min det F| is above 1) a different one.
TEST(Untangle, TheFirstEpsilonIsCappedByLargestStartEpsilon) {
  const TetMesh mesh = kuhnGrid();
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const Vertices start = foldedGrid(mesh);
  double minDet = INFINITY;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    minDet = std::min(minDet,
                      deformationGradient(start, mesh.tets.row(t), elements[static_cast<size_t>(t)])
                          .determinant());
  }
  ASSERT_LT(minDet, -0.5) << "the fold no longer puts 2 |min det F| above 1";
  const auto oneStep = [&](double largestStartEpsilon) {
    UntangleEffort effort = withoutStallTests(1);
    effort.largestStartEpsilon = largestStartEpsilon;
    Vertices positions = start;
    untangle(mesh.tets, elements, interiorVertices(mesh), effort, positions);
    return positions;
  };
  const Vertices uncapped = oneStep(1e6);
  ASSERT_FALSE(uncapped == start) << "one step left the fold unchanged";
  EXPECT_TRUE(oneStep(2.0 * std::abs(minDet)) == uncapped);
  EXPECT_FALSE(oneStep(0.1) == uncapped);
}

// newtonModelAgrees on a quadratic energy f(x) = ½ xᵀHx (random H and x) with a stale factor B =
// cH: the step d = -B⁻¹g decreases f by (2 - 1/c) times the model's prediction -gᵀd / 2 (an
// identity of the quadratic, independent of the code), so the factor is kept exactly for c in [5/9,
// 5] (kModelAgreement = 0.2), here checked just inside and just outside both ends, at 1 and where
// the full step no longer decreases f.
TEST(Untangle, AStaleFactorIsKeptWhileItsModelPredictsTheDecrease) {
  std::mt19937 random(test_seed::seedOfCurrentTest(20261203u));
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(6, 6);
  for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = normal(random);
  const Eigen::MatrixXd h = a * a.transpose() + Eigen::MatrixXd::Identity(6, 6);
  Eigen::VectorXd x(6);
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = normal(random);
  const auto f = [&](const Eigen::VectorXd& y) { return 0.5 * y.dot(h * y); };
  const Eigen::VectorXd g = h * x;
  // A margin of 1e-6 in c moves the ratio 2 - 1/c by at least 4e-8, far
  // above the rounding of f's decrease (about 1e-15 of f here).
  constexpr double kMargin = 1e-6;
  const std::vector<std::pair<double, bool>> cases = {
      {0.5, false}, {5.0 / 9.0 - kMargin, false}, {5.0 / 9.0 + kMargin, true},
      {1.0, true},  {5.0 - kMargin, true},        {5.0 + kMargin, false},
  };
  for (const auto& [c, kept] : cases) {
    const Eigen::VectorXd d = -(c * h).ldlt().solve(g);
    EXPECT_EQ(newtonModelAgrees(g.dot(d), f(x), f(x + d)), kept) << "c = " << c;
  }
}

}  // namespace
}  // namespace tetblend
