#include "tetblend/blending/stitch_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "blending_test_support.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// A compatible target field has a zero-residual solution; the factorisation
// reproduces it to round-off amplified by the stitch matrix's condition
// number (~1e3 for these grids): 1e-10 of the bounding-box diagonal.
constexpr double kExactRelative = 1e-10;
// The stitch energy of that reproduction, sum of vol |G x - F|^2 (total
// volume 2.4): with gradients off by round-off (~cond * eps ~ 1e-13) it is
// ~1e-26; 1e-20 asks for gradient residuals below ~1e-10, which is tighter
// than kExactRelative's positions alone would imply.
constexpr double kExactEnergy = 1e-20;
// Random N(0, 1) targets are far from compatible: the minimum stitch energy
// is O(1) (total volume 1, 9 entries per target); 1e-3 tells it from a
// spuriously zero energy.
constexpr double kIncompatibleEnergy = 1e-3;
// E(x* + h d) - E(x*) against E(x* - h d) - E(x*): at the minimiser they
// differ only by the solve's residual gradient (2 h g.d, |g| ~ cond * eps
// relative) and the rounding of differences of O(1) energies: relative to
// up + down, plus an absolute floor of a few hundred ulps of those energies.
constexpr double kSymmetryRelative = 1e-9;
constexpr double kSymmetryAbsolute = 1e-13;
// The two backends factor the same Laplacian (supernodal vs simplicial LDLT):
// each solve is within ~cond * eps ~ 1e-13 of the exact positions (unit box).
constexpr double kBackendAgreement = 1e-12;

double maxRowDistance(const Vertices& a, const Vertices& b) {
  return (a - b).rowwise().norm().maxCoeff();
}

// Two boxes sharing no vertex, plus one vertex in no tet: three components.
TetMesh twoBoxesAndAPoint() {
  const TetMesh a = boxTetMesh(2, 2, 2, Eigen::Vector3d::Ones());
  TetMesh b = boxTetMesh(1, 2, 3, Eigen::Vector3d(0.5, 1.0, 1.5));
  TetMesh mesh;
  mesh.vertices.resize(a.vertices.rows() + b.vertices.rows() + 1, 3);
  mesh.vertices << a.vertices, b.vertices.rowwise() + Eigen::RowVector3d(3.0, 0.0, 0.0),
      Eigen::RowVector3d(-5.0, 1.0, 2.0);
  mesh.tets.resize(a.tets.rows() + b.tets.rows(), 4);
  mesh.tets << a.tets, b.tets.array() + static_cast<int>(a.vertices.rows());
  return mesh;
}

class StitchBackends : public ::testing::TestWithParam<StitchBackend> {};

TEST_P(StitchBackends, CompatibleTargetFieldIsReproducedExactly) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = boxTetMesh(3, 4, 5, Eigen::Vector3d(1.0, 1.2, 2.0));
  const Vertices target = testing::smoothWarp(rest.vertices, 0.1, rng);
  StitchOptions options;
  options.backend = GetParam();
  const StitchSolver solver(rest, options);
  const auto gradients = deformationGradients(rest, solver.restData(), target, 0);
  const Vertices solved = solver.solve(gradients, solver.componentCentroids(target));
  EXPECT_LT(maxRowDistance(solved, target), kExactRelative * boundingBoxDiagonal(target));
  EXPECT_LT(solver.energy(solved, gradients), kExactEnergy);
}

// A mesh 10^6 times its size from the origin (a scan in survey
// coordinates): the solve works on positions relative to each component's
// centroid, and the centroid is added back with one rounding, so a
// compatible target comes back to within kFarUlps ulps of its coordinates'
// size (the plain sums of coordinates that the centroids once were missed
// it by 10-20 ulps on a posed hand, above 1e-9 of its diagonal).
constexpr double kFarOffset = 1e6;
constexpr double kFarUlps = 2.0;

TEST_P(StitchBackends, AFarTranslatedTargetIsReproducedToItsCoordinatesUlps) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const Eigen::RowVector3d offset = kFarOffset * Eigen::RowVector3d(1.0, -3.0, 2.0);
  TetMesh rest = boxTetMesh(3, 4, 5, Eigen::Vector3d(1.0, 1.2, 2.0));
  const Vertices target = testing::smoothWarp(rest.vertices, 0.1, rng).rowwise() + offset;
  rest.vertices.rowwise() += offset;
  StitchOptions options;
  options.backend = GetParam();
  const StitchSolver solver(rest, options);
  const auto gradients = deformationGradients(rest, solver.restData(), target, 0);
  const Vertices solved = solver.solve(gradients, solver.componentCentroids(target));
  const double ulp =
      std::nextafter(target.cwiseAbs().maxCoeff(), INFINITY) - target.cwiseAbs().maxCoeff();
  EXPECT_LT(maxRowDistance(solved, target),
            kFarUlps * ulp + kExactRelative * boundingBoxDiagonal(target));
}

TEST_P(StitchBackends, EveryComponentIsAnchoredAtItsCentroid) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = twoBoxesAndAPoint();
  StitchOptions options;
  options.backend = GetParam();
  const StitchSolver solver(rest, options);
  ASSERT_EQ(solver.componentCount(), 3);
  // Each component moved by its own rigid motion plus a warp: the solve must
  // put every component (and the lone point) back where the target has it.
  Vertices target = testing::smoothWarp(rest.vertices, 0.05, rng);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (Eigen::Index v = 0; v < target.rows(); ++v) {
    const int c = solver.vertexComponent()[v];
    if (c == 1) target.row(v) = (turn * target.row(v).transpose()).transpose();
    target.row(v) += Eigen::RowVector3d(c, -2.0 * c, 0.5);
  }
  const auto gradients = deformationGradients(rest, solver.restData(), target, 0);
  const Vertices solved = solver.solve(gradients, solver.componentCentroids(target));
  EXPECT_LT(maxRowDistance(solved, target), kExactRelative * boundingBoxDiagonal(target));
}

TEST_P(StitchBackends, SolutionIsTheLeastSquaresMinimiser) {
  // Incompatible targets (random matrices): the energy must not decrease
  // under any vertex perturbation (first-order optimality, checked with a
  // finite step both ways), and the residual must be non-zero.
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  const TetMesh rest = boxTetMesh(2, 3, 2, Eigen::Vector3d::Ones());
  StitchOptions options;
  options.backend = GetParam();
  const StitchSolver solver(rest, options);
  std::vector<Eigen::Matrix3d> targets(rest.tets.rows());
  for (auto& t : targets) t = Eigen::Matrix3d::NullaryExpr([&] { return normal(rng); });
  const Vertices solved = solver.solve(targets, solver.componentCentroids(rest.vertices));
  const double best = solver.energy(solved, targets);
  EXPECT_GT(best, kIncompatibleEnergy);
  // E is quadratic: E(x + h d) - E(x) = h^2 d^T A d >= 0 at the minimiser,
  // and a first-order term would show as an asymmetry between +h and -h.
  constexpr double kStep = 1e-3;
  for (int trial = 0; trial < 10; ++trial) {
    const Vertices direction =
        Vertices::NullaryExpr(rest.vertices.rows(), 3, [&] { return normal(rng); });
    const double up = solver.energy(solved + kStep * direction, targets) - best;
    const double down = solver.energy(solved - kStep * direction, targets) - best;
    EXPECT_GE(up, 0.0);
    EXPECT_GE(down, 0.0);
    EXPECT_NEAR(up, down, kSymmetryRelative * (up + down) + kSymmetryAbsolute);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, StitchBackends,
                         ::testing::Values(StitchBackend::kCholmodSupernodal,
                                           StitchBackend::kEigenSimplicialLdlt));

TEST(StitchSolver, BackendsAgree) {
  const TetMesh rest = boxTetMesh(3, 3, 3, Eigen::Vector3d::Ones());
  StitchOptions simplicial;
  simplicial.backend = StitchBackend::kEigenSimplicialLdlt;
  const StitchSolver a(rest);
  const StitchSolver b(rest, simplicial);
  EXPECT_EQ(b.backend(), StitchBackend::kEigenSimplicialLdlt);
  std::vector<Eigen::Matrix3d> targets(rest.tets.rows());
  for (size_t j = 0; j < targets.size(); ++j) {
    targets[j] = Eigen::AngleAxisd(0.01 * j, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  const Centroids c = a.componentCentroids(rest.vertices);
  EXPECT_LT(maxRowDistance(a.solve(targets, c), b.solve(targets, c)), kBackendAgreement);
}

// The supernodal solve splits dense triangles of at least 512 columns into
// panels on two threads; on this 14 x 14 x 36 bar (8325 vertices) METIS's
// root separator is a 566-column supernode (measured), so the panel path,
// the two-thread split of the elimination tree and the split off-diagonal
// blocks all run (with CHOLMOD, the default build; the property below holds
// for every backend, so a build without CHOLMOD checks Eigen's factor here).
TEST(StitchSolver, LargeSupernodesGiveTheLeastSquaresSolution) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = boxTetMesh(14, 14, 36, Eigen::Vector3d(1.0, 1.0, 2.6));
  const StitchSolver solver(rest);
  // A compatible field is reproduced (same tolerance as the small grids: the
  // condition number of this Laplacian is still far below 1e6).
  const Vertices target = testing::smoothWarp(rest.vertices, 0.03, rng);
  const auto gradients = deformationGradients(rest, solver.restData(), target, 0);
  EXPECT_LT(maxRowDistance(solver.solve(gradients, solver.componentCentroids(target)), target),
            kExactRelative * boundingBoxDiagonal(target));
  // Incompatible targets (each tet's map turned about its own random axis):
  // the gradient of E, sum_j vol_j (grad_j(x) - B_j) g_c at every vertex
  // (the definition of E, not the solver's assembly), vanishes at the
  // minimiser up to round-off times the condition number, relative to the
  // size of the terms.
  constexpr double kStationaryRelative = 1e-9;
  std::vector<Eigen::Matrix3d> targets = gradients;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (auto& t : targets) {
    const Eigen::Vector3d axis(unit(rng), unit(rng), unit(rng));
    t = Eigen::AngleAxisd(0.3 * unit(rng), axis.normalized()) * t;
  }
  const Vertices x = solver.solve(targets, solver.componentCentroids(target));
  const RestTetData& data = solver.restData();
  Vertices gradient = Vertices::Zero(x.rows(), 3);
  double scale = 0.0;
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
    const Eigen::Matrix3d difference =
        data.volumes[j] * (solver.gradient(x, static_cast<int>(j)) - targets[j]);
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d g = c == 0 ? Eigen::Vector3d(-data.inverseEdges[j].colwise().sum())
                                       : Eigen::Vector3d(data.inverseEdges[j].row(c - 1));
      gradient.row(rest.tets(j, c)) += (difference * g).transpose();
      scale = std::max(scale, (data.volumes[j] * targets[j] * g).norm());
    }
  }
  EXPECT_GT(solver.energy(x, targets), 0.0);
  EXPECT_LT(gradient.rowwise().norm().maxCoeff(), kStationaryRelative * scale);
}

TEST(StitchSolver, SizeMismatchesAreInputErrors) {
  const TetMesh rest = boxTetMesh(1, 1, 1, Eigen::Vector3d::Ones());
  const StitchSolver solver(rest);
  const Centroids c = solver.componentCentroids(rest.vertices);
  EXPECT_THROW(solver.solve(std::vector<Eigen::Matrix3d>(2), c), InputError);
  EXPECT_THROW(solver.solve(std::vector<Eigen::Matrix3d>(rest.tets.rows()), Centroids(2, 3)),
               InputError);
  EXPECT_THROW(solver.componentCentroids(Vertices(3, 3)), InputError);
}

}  // namespace
}  // namespace tetblend
