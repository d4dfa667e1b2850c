#include "tetblend/blending/tet_maps.h"

#include <gtest/gtest.h>

#include <cmath>

#include "blending_test_support.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// F_j is computed from one inverse; the oracle solves the 4x4 homogeneous
// system independently. Both are O(cond * eps) on unit-scale tets.
constexpr double kMapTolerance = 1e-12;
// Rest volumes against tetSignedVolume on the same vertices: a determinant of
// edges < 1 over 6, a few ulps of volumes ~0.02 (~1e-17 each).
constexpr double kVolumeTolerance = 1e-15;

TEST(TetMaps, GradientsMatchTheHomogeneousAffineMap) {
  const unsigned seed = testing::testSeed();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const TetMesh rest = boxTetMesh(2, 2, 3, Eigen::Vector3d(1.0, 1.0, 1.5));
  const Vertices example = testing::smoothWarp(rest.vertices, 0.05, rng);
  const RestTetData data = restTetData(rest);
  const auto gradients = deformationGradients(rest, data, example, 0);
  ASSERT_EQ(gradients.size(), static_cast<size_t>(rest.tets.rows()));
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
    const Eigen::Matrix4d map = tetAffineMap(rest.vertices, example, rest.tets.row(j));
    EXPECT_LT((gradients[j] - map.topLeftCorner<3, 3>()).norm(), kMapTolerance) << "tet " << j;
    EXPECT_NEAR(data.volumes[j], tetSignedVolume(rest.vertices, rest.tets.row(j)),
                kVolumeTolerance);
  }
}

TEST(TetMaps, InvertedExampleTetIsReportedWithExampleTetAndVolume) {
  const TetMesh rest = boxTetMesh(1, 1, 1, Eigen::Vector3d::Ones());
  Vertices example = rest.vertices;
  // Moving vertex 7 (the far corner) through the opposite diagonal plane
  // inverts the tets that contain it.
  example.row(7) = Eigen::RowVector3d(-1.0, -1.0, -1.0);
  const RestTetData data = restTetData(rest);
  try {
    deformationGradients(rest, data, example, 3);
    FAIL() << "inverted example accepted";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("example 4"), std::string::npos) << what;  // index 3, counted from 1
    EXPECT_NE(what.find("tet "), std::string::npos) << what;
    EXPECT_NE(what.find("signed volume -"), std::string::npos) << what;
  }
}

TEST(TetMaps, FlatExampleTetIsRejectedAndPositiveOneAccepted) {
  // Both sides of the det > 0 threshold: a zero-volume tet is refused, a tiny
  // positive one is accepted.
  TetMesh rest;
  rest.vertices.resize(4, 3);
  rest.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  rest.tets.resize(1, 4);
  rest.tets << 0, 1, 2, 3;
  const RestTetData data = restTetData(rest);
  Vertices flat = rest.vertices;
  flat(3, 2) = 0.0;
  EXPECT_THROW(deformationGradients(rest, data, flat, 0), InputError);
  Vertices thin = rest.vertices;
  thin(3, 2) = 1e-12;
  EXPECT_NO_THROW(deformationGradients(rest, data, thin, 0));
}

TEST(TetMaps, BadRestMeshIsRejected) {
  TetMesh rest;
  rest.vertices.resize(4, 3);
  rest.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  rest.tets.resize(1, 4);
  rest.tets << 0, 2, 1, 3;  // negatively oriented
  EXPECT_THROW(restTetData(rest), InputError);
  rest.tets << 0, 1, 2, 4;  // index out of range
  EXPECT_THROW(restTetData(rest), InputError);
}

// A tet listed in mayBeFlat (a model's excluded tets) is not refused when
// inverted: it gets NaN, and the other tets keep their data.
TEST(TetMaps, InvertedTetListedAsMayBeFlatGetsNaN) {
  TetMesh rest;
  rest.vertices.resize(5, 3);
  rest.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  rest.tets.resize(2, 4);
  rest.tets << 0, 1, 2, 3,  // positive, volume 1/6
      1, 3, 2, 4;           // negatively oriented
  EXPECT_THROW(restTetData(rest), InputError);
  EXPECT_THROW(restTetData(rest, {0}), InputError);
  const RestTetData data = restTetData(rest, {1});
  EXPECT_EQ(data.volumes[0], 1.0 / 6.0);
  EXPECT_TRUE(std::isnan(data.volumes[1]));
  EXPECT_TRUE(data.inverseEdges[1].array().isNaN().all());
}

}  // namespace
}  // namespace tetblend
