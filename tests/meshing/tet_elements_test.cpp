// The untangler's thickened reference shapes (thickenedTetElements,
// meshing/src/tet_elements.h) against an oracle built by hand: a tet whose
// edge matrix is D = Q diag(σ) Rᵀ for random rotations Q, R and chosen σ,
// so the thickened matrix is known in closed form, Q diag(max(σ, κ σ_0)) Rᵀ.
// Covered: a sliver thickened, a well-shaped tet copied bit for bit, the
// bound itself (a singular value exactly at κ σ_0 stays), and the property
// the untangler relies on, the same sign of det F as with the rest's shape
// for random example corners.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <random>
#include <vector>

#include "../test_seed.h"
#include "tet_elements.h"

namespace tetblend {
namespace {

unsigned testSeed() { return test_seed::seedOfCurrentTest(20261128u); }

// The bound used in the tests (the pipeline's is compatible_tets.cpp's).
constexpr double kRatio = 0.05;
// Agreement of matrices built by different products of rotations: a few
// hundred ulps of their unit-sized entries.
constexpr double kMatrixTolerance = 1e-12;

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  Eigen::Quaterniond q(test_seed::uniform(rng, -1, 1), test_seed::uniform(rng, -1, 1),
                       test_seed::uniform(rng, -1, 1), test_seed::uniform(rng, -1, 1));
  return q.normalized().toRotationMatrix();
}

// One tet with corner 0 at the origin and edge matrix `edges`.
TetMesh tetWithEdges(const Eigen::Matrix3d& edges) {
  TetMesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices.row(0).setZero();
  for (int i = 0; i < 3; ++i) mesh.vertices.row(i + 1) = edges.col(i).transpose();
  mesh.tets.resize(1, 4);
  mesh.tets << 0, 1, 2, 3;
  return mesh;
}

// The edge matrix an element stands for: its gradients of λ1..λ3 are the
// rows of D⁻¹.
Eigen::Matrix3d edgesOf(const TetElement& element) {
  return element.gradients.rightCols<3>().transpose().inverse();
}

TEST(ThickenedTetElements, SliverGetsTheBoundedSingularValues) {
  std::mt19937 rng(testSeed());
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d q = randomRotation(rng);
    const Eigen::Matrix3d r = randomRotation(rng);
    const Eigen::Vector3d sigma(2.0, 0.7, 1e-6);  // a sliver of relative height 5e-7
    const TetMesh mesh = tetWithEdges(q * sigma.asDiagonal() * r.transpose());
    const std::vector<TetElement> thickened =
        thickenedTetElements(mesh, buildTetElements(mesh), kRatio);
    const Eigen::Vector3d bounded(2.0, 0.7, kRatio * 2.0);
    const Eigen::Matrix3d expected = q * bounded.asDiagonal() * r.transpose();
    EXPECT_LT((edgesOf(thickened[0]) - expected).cwiseAbs().maxCoeff(), kMatrixTolerance)
        << "trial " << trial;
    EXPECT_NEAR(thickened[0].volume, bounded.prod() / 6.0, kMatrixTolerance) << "trial " << trial;
    const Eigen::Vector3d gradientSum = thickened[0].gradients.rowwise().sum();
    EXPECT_LT(gradientSum.norm(), kMatrixTolerance) << "the barycentric gradients sum to 0";
  }
}

TEST(ThickenedTetElements, WellShapedTetAndTheBoundItselfStayAsTheyAre) {
  std::mt19937 rng(testSeed());
  for (const Eigen::Vector3d& sigma :
       {Eigen::Vector3d(1.4, 0.7, 0.7), Eigen::Vector3d(1.0, 0.5, kRatio)}) {
    const Eigen::Matrix3d edges =
        randomRotation(rng) * sigma.asDiagonal() * randomRotation(rng).transpose();
    const TetMesh mesh = tetWithEdges(edges);
    const std::vector<TetElement> elements = buildTetElements(mesh);
    // The bound case only stays when rounding leaves σ_2 >= κ σ_0; compare
    // with what the SVD sees rather than with the nominal values.
    const Eigen::Vector3d seen = Eigen::JacobiSVD<Eigen::Matrix3d>(edges).singularValues();
    if (seen(2) < kRatio * seen(0)) continue;
    const std::vector<TetElement> thickened = thickenedTetElements(mesh, elements, kRatio);
    EXPECT_TRUE(thickened[0].gradients == elements[0].gradients) << sigma.transpose();
    EXPECT_EQ(thickened[0].volume, elements[0].volume) << sigma.transpose();
  }
}

TEST(ThickenedTetElements, DetFKeepsItsSignForAnyExample) {
  std::mt19937 rng(testSeed());
  const Eigen::Matrix3d edges = randomRotation(rng) * Eigen::Vector3d(1.0, 0.3, 1e-5).asDiagonal() *
                                randomRotation(rng).transpose();
  const TetMesh mesh = tetWithEdges(edges);
  const std::vector<TetElement> elements = buildTetElements(mesh);
  const std::vector<TetElement> thickened = thickenedTetElements(mesh, elements, kRatio);
  for (int trial = 0; trial < 1000; ++trial) {
    Eigen::Matrix<double, 3, 4> corners;
    for (int i = 0; i < 12; ++i) corners(i) = test_seed::uniform(rng, -1, 1);
    const Eigen::Matrix3d exampleEdges = corners.rightCols<3>().colwise() - corners.col(0);
    const double exampleVolume = exampleEdges.determinant() / 6.0;
    const double restDet = (corners * elements[0].gradients.transpose()).determinant();
    const double thickDet = (corners * thickened[0].gradients.transpose()).determinant();
    EXPECT_EQ(exampleVolume > 0.0, thickDet > 0.0) << "trial " << trial;
    EXPECT_EQ(restDet > 0.0, thickDet > 0.0) << "trial " << trial;
    // det F = example volume / reference volume, with either reference: the
    // thickened one is 5000 times larger here, its det F that much smaller.
    // The corners lie in [-1, 1]³, so rounding is absolute, relative to 1:
    // a few ulps times the thickened D⁻¹'s condition number (20); the
    // rest's D⁻¹ has condition number 1e5, and its det F carries about
    // ulp × 1e5² = 1e-6 (2e-8 seen): one reason the thickened reference
    // serves the untangler better.
    EXPECT_NEAR(thickDet * thickened[0].volume, exampleVolume, 1e-13) << "trial " << trial;
    EXPECT_NEAR(restDet * elements[0].volume, exampleVolume, 1e-5) << "trial " << trial;
  }
}

}  // namespace
}  // namespace tetblend
