#include "tetblend/meshing/procedural_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "test_seed.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// Volumes and positions are sums of O(#T) unit-scale products: 1e-12 relative
// is ~1e4 ε, generous for meshes of a few thousand tets.
constexpr double kRelativeTolerance = 1e-12;
// Closed-form per-vertex maps (twist, bend, skinning: sin/cos of angles up to
// 4 pi and a few products) on coordinates of size <= 4, against the same
// formulas written out: a few ulps of ulp(4 pi) = 1.8e-15; absolute, and
// relative where isApprox compares whole points.
constexpr double kVertexMapTolerance = 1e-12;
// Grid vertices on a boundary plane, or cylinder vertices on the rim, are
// computed as i * h - size / 2 or r (cos, sin): within a few ulps of the
// boundary; the others are at least a cell (>= 0.1 here) away.
constexpr double kOnBoundary = 1e-12;
// Two-bone weights are 1 - w and w: their sum is 1 to within two roundings.
constexpr double kPartitionOfUnity = 1e-15;

unsigned testSeed() { return test_seed::seedOfCurrentTest(20240611u); }

double totalVolume(const TetMesh& mesh) {
  double volume = 0.0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    volume += tetSignedVolume(mesh.vertices, mesh.tets.row(t));
  }
  return volume;
}

double minVolume(const TetMesh& mesh) {
  double volume = INFINITY;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    volume = std::min(volume, tetSignedVolume(mesh.vertices, mesh.tets.row(t)));
  }
  return volume;
}

// Conformity checked independently of tet_boundary.cpp: every face (as a
// sorted triple) is used once (boundary) or twice (interior), and every
// interior face is used once in each orientation, i.e. its two tets lie on
// opposite sides. Boundary faces must lie on the domain's boundary, which
// `onBoundary` decides from coordinates.
template <typename OnBoundary>
void expectConforming(const TetMesh& mesh, OnBoundary onBoundary) {
  std::map<std::array<int, 3>, std::vector<double>> sides;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face;
      int n = 0;
      for (int k = 0; k < 4; ++k) {
        if (k != skip) face[n++] = mesh.tets(t, k);
      }
      std::sort(face.begin(), face.end());
      // Side of the opposite corner relative to the sorted face's plane.
      const Eigen::Vector3d a = mesh.vertices.row(face[0]);
      const Eigen::Vector3d normal = (Eigen::Vector3d(mesh.vertices.row(face[1])) - a)
                                         .cross(Eigen::Vector3d(mesh.vertices.row(face[2])) - a);
      sides[face].push_back(normal.dot(Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, skip))) - a));
    }
  }
  int boundaryFaces = 0;
  for (const auto& [face, side] : sides) {
    ASSERT_LE(side.size(), 2u);
    if (side.size() == 2) {
      EXPECT_LT(side[0] * side[1], 0.0) << "tets on the same side of a shared face";
    } else {
      ++boundaryFaces;
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(onBoundary(Eigen::Vector3d(mesh.vertices.row(face[k]))))
            << "an unshared face has a vertex inside the domain: a hole";
      }
    }
  }
  EXPECT_EQ(boundaryFaces, boundarySurface(mesh).triangles.rows());
}

TEST(ProceduralShapes, BoxIsConformingPositiveWithAnalyticVolume) {
  const Eigen::Vector3d size(2.0, 1.5, 0.75);
  const TetMesh mesh = boxTetMesh(4, 3, 5, size);
  EXPECT_EQ(mesh.vertices.rows(), 5 * 4 * 6);
  EXPECT_EQ(mesh.tets.rows(), 6 * 4 * 3 * 5);
  // Each Kuhn tet has volume cell/6.
  const double cellVolume = size.prod() / (4 * 3 * 5);
  EXPECT_NEAR(minVolume(mesh), cellVolume / 6.0, kRelativeTolerance * cellVolume);
  EXPECT_NEAR(totalVolume(mesh), size.prod(), kRelativeTolerance * size.prod());
  const Eigen::Vector3d half = size / 2.0;
  expectConforming(mesh, [&](const Eigen::Vector3d& p) {
    return ((p.cwiseAbs() - half).cwiseAbs().array() < kOnBoundary).any();
  });
  EXPECT_TRUE(mesh.vertices.colwise().maxCoeff().transpose().isApprox(half, kRelativeTolerance));
}

TEST(ProceduralShapes, CylinderIsConformingPositiveWithPolygonVolume) {
  const double radius = 0.5;
  const double length = 3.0;
  const int rings = 4;
  const TetMesh mesh = cylinderTetMesh(rings, 10, radius, length);
  EXPECT_GT(minVolume(mesh), 0.0);
  const double area = cylinderSectionArea(rings, radius);
  // Independent oracle: a regular 24-gon of circumradius r has area
  // 24 r² sin(7.5°) cos(7.5°) = 12 r² sin(15°) = 3 (√6 - √2) r².
  EXPECT_NEAR(area, 3.0 * (std::sqrt(6.0) - std::sqrt(2.0)) * radius * radius, kRelativeTolerance);
  EXPECT_NEAR(totalVolume(mesh), area * length, kRelativeTolerance * area * length);
  expectConforming(mesh, [&](const Eigen::Vector3d& p) {
    return std::abs(std::abs(p.x()) - length / 2) < kOnBoundary ||
           std::abs(std::hypot(p.y(), p.z()) - radius) < kOnBoundary;
  });
}

TEST(ProceduralShapes, RejectsBadSizes) {
  EXPECT_THROW(boxTetMesh(0, 1, 1, Eigen::Vector3d::Ones()), InputError);
  EXPECT_THROW(boxTetMesh(1, 1, 1, Eigen::Vector3d(1, -1, 1)), InputError);
  EXPECT_THROW(cylinderTetMesh(1, 1, 0.0, 1.0), InputError);
  EXPECT_THROW(
      twistAboutAxis(Vertices(1, 3), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0, 1.0),
      InputError);
}

TEST(ProceduralShapes, TwistRotatesEachSectionRigidlyByItsAngle) {
  const TetMesh bar = boxTetMesh(2, 2, 8, Eigen::Vector3d(0.5, 0.5, 4.0));
  for (const double total : {2.0 * kPi, 4.0 * kPi}) {
    const Vertices twisted = twistAboutAxis(bar.vertices, Eigen::Vector3d(0, 0, -2.0),
                                            Eigen::Vector3d::UnitZ(), total, 4.0);
    for (Eigen::Index v = 0; v < bar.vertices.rows(); ++v) {
      const Eigen::Vector3d p = bar.vertices.row(v);
      const Eigen::Vector3d q = twisted.row(v);
      EXPECT_NEAR(q.z(), p.z(), kRelativeTolerance);
      EXPECT_NEAR(std::hypot(q.x(), q.y()), std::hypot(p.x(), p.y()), kRelativeTolerance);
      // Oracle: the angle between the sections, via the rotation's matrix in
      // closed form (cos, sin) on the (x, y) plane.
      const double angle = total * (p.z() + 2.0) / 4.0;
      EXPECT_NEAR(q.x(), std::cos(angle) * p.x() - std::sin(angle) * p.y(), kVertexMapTolerance);
      EXPECT_NEAR(q.y(), std::sin(angle) * p.x() + std::cos(angle) * p.y(), kVertexMapTolerance);
    }
  }
}

TEST(ProceduralShapes, BendKeepsNeutralFibreLengthAndEndsUpReversed) {
  const double length = 4.0;
  const TetMesh bar = boxTetMesh(16, 2, 2, Eigen::Vector3d(length, 0.4, 0.4));
  const Eigen::Vector3d origin(-length / 2, 0, 0);
  const Vertices bent = bendAboutAxis(bar.vertices, origin, Eigen::Vector3d::UnitX(),
                                      Eigen::Vector3d::UnitY(), kPi, length);
  const double radius = length / kPi;
  for (Eigen::Index v = 0; v < bar.vertices.rows(); ++v) {
    const Eigen::Vector3d p = bar.vertices.row(v);
    const Eigen::Vector3d q = bent.row(v);
    // Distance to the bend axis (through origin + R ey along ez) is R - y.
    EXPECT_NEAR(std::hypot(q.x() - origin.x(), q.y() - radius), radius - p.y(),
                kVertexMapTolerance);
    EXPECT_NEAR(q.z(), p.z(), kVertexMapTolerance);
    if (std::abs(p.x() - length / 2) < kOnBoundary) {
      // The far end is turned by π: x maps back to origin's abscissa.
      EXPECT_NEAR(q.x(), origin.x(), kVertexMapTolerance);
      EXPECT_NEAR(q.y(), 2 * radius - p.y(), kVertexMapTolerance);
    }
  }
  EXPECT_GT(minVolume(TetMesh{bent, bar.tets}), 0.0);
}

TEST(ProceduralShapes, SkinningRigidCasesAndDqsPreservesLengthsWhereLbsCollapses) {
  const unsigned seed = testSeed();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vertices points(200, 3);
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    points.row(v) << 2.0 * uniform(rng), 0.3 * uniform(rng), 0.3 * uniform(rng);
  }
  const Eigen::Vector3d joint = Eigen::Vector3d::Zero();
  const Eigen::MatrixXd weights = twoBoneWeights(points, joint, Eigen::Vector3d::UnitX(), 0.4);
  EXPECT_TRUE(weights.rowwise().sum().isApproxToConstant(1.0, kPartitionOfUnity));
  const double angle = 170.0 * kPi / 180.0;
  // Twisting about the bone axis: DQS keeps every point's distance to the
  // axis; LBS shrinks points with weight 1/2 by cos(85°) (candy wrapper).
  const std::vector<Eigen::Isometry3d> bones = {
      Eigen::Isometry3d::Identity(), rotationAboutLine(joint, Eigen::Vector3d::UnitX(), angle)};
  const Vertices dqs = dualQuaternionSkinning(points, weights, bones);
  const Vertices lbs = linearBlendSkinning(points, weights, bones);
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const double r = std::hypot(points(v, 1), points(v, 2));
    EXPECT_NEAR(std::hypot(dqs(v, 1), dqs(v, 2)), r, kVertexMapTolerance);
    EXPECT_NEAR(dqs(v, 0), points(v, 0), kVertexMapTolerance);
    // Oracle for LBS: |(1-w) p + w R p| in the section, closed form.
    const double w = weights(v, 1);
    const double expected =
        r * std::sqrt((1 - w) * (1 - w) + w * w + 2 * w * (1 - w) * std::cos(angle));
    EXPECT_NEAR(std::hypot(lbs(v, 1), lbs(v, 2)), expected, kVertexMapTolerance);
    // Rigid parts: weight 0 keeps the point, weight 1 applies bone 1.
    if (w == 0.0 || w == 1.0) {
      const Eigen::Vector3d rigid = bones[w == 1.0 ? 1 : 0] * Eigen::Vector3d(points.row(v));
      EXPECT_TRUE(Eigen::Vector3d(dqs.row(v)).isApprox(rigid, kVertexMapTolerance));
      EXPECT_TRUE(Eigen::Vector3d(lbs.row(v)).isApprox(rigid, kVertexMapTolerance));
    }
  }
}

}  // namespace
}  // namespace tetblend
