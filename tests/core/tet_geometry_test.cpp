#include "tetblend/core/tet_geometry.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace tetblend {
namespace {

// Round trips of unit-scale values: a few ulps of accumulated round-off.
constexpr double kRoundTripTol = 1e-13;

Vertices unitTet() {
  Vertices v(4, 3);
  v << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return v;
}

TEST(TetGeometry, UnitTetVolumeIsOneSixth) {
  const Eigen::RowVector4i t(0, 1, 2, 3);
  EXPECT_NEAR(tetSignedVolume(unitTet(), t), 1.0 / 6.0, kRoundTripTol);
  const Eigen::RowVector4i flipped(0, 2, 1, 3);
  EXPECT_NEAR(tetSignedVolume(unitTet(), flipped), -1.0 / 6.0, kRoundTripTol);
}

TEST(TetGeometry, AffineMapReproducesAKnownMap) {
  Eigen::Matrix4d known = Eigen::Matrix4d::Identity();
  known.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
      Eigen::Vector3d(2.0, 0.5, 1.5).asDiagonal();
  known.topRightCorner<3, 1>() = Eigen::Vector3d(-1, 4, 0.25);
  const Vertices from = unitTet();
  Vertices to(4, 3);
  for (int i = 0; i < 4; ++i) {
    to.row(i) = (known * from.row(i).transpose().homogeneous()).head<3>().transpose();
  }
  const Eigen::Matrix4d map = tetAffineMap(from, to, Eigen::RowVector4i(0, 1, 2, 3));
  EXPECT_LE((map - known).norm(), kRoundTripTol * known.norm());
}

TEST(TetGeometry, BoundingBoxDiagonal) {
  EXPECT_NEAR(boundingBoxDiagonal(unitTet()), std::sqrt(3.0), kRoundTripTol);
  EXPECT_EQ(boundingBoxDiagonal(Vertices(0, 3)), 0.0);
}

}  // namespace
}  // namespace tetblend
