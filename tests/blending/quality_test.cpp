#include "tetblend/blending/quality.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// Unit-scale 3x3 products and a converged polar decomposition: round-off.
constexpr double kTolerance = 1e-12;

TEST(Quality, SimilarityHasKnownRatiosAnglesAndNoDistortion) {
  const TetMesh rest = boxTetMesh(2, 2, 2, Eigen::Vector3d::Ones());
  const double scale = 1.5, angle = 2.0;
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(angle, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  const Vertices x = scale * rest.vertices * r.transpose();
  const std::vector<Eigen::Matrix3d> targets(rest.tets.rows(), scale * r);
  const TetQuality q = tetQuality(rest, restTetData(rest), x, targets);
  for (Eigen::Index j = 0; j < rest.tets.rows(); ++j) {
    EXPECT_EQ(q.inverted[j], 0);
    EXPECT_NEAR(q.volumeRatio[j], scale * scale * scale, kTolerance);
    EXPECT_NEAR(q.stitchResidual[j], 0.0, kTolerance);
    EXPECT_NEAR(q.conditionNumber[j], 1.0, kTolerance);
    EXPECT_NEAR(q.rotationAngle[j], angle, kTolerance);
  }
  const QualitySummary s = summarizeQuality(q);
  EXPECT_EQ(s.tetCount, rest.tets.rows());
  EXPECT_EQ(s.invertedCount, 0);
  EXPECT_NEAR(s.volumeRatio.mean, scale * scale * scale, kTolerance);
}

TEST(Quality, InvertedAndStretchedTetsAreReported) {
  const TetMesh rest = boxTetMesh(1, 1, 1, Eigen::Vector3d::Ones());
  Vertices x = rest.vertices;
  x.col(0) *= 3.0;  // stretch along x: condition number 3, volume ratio 3
  const TetQuality stretched = tetQuality(rest, restTetData(rest), x, {});
  for (size_t j = 0; j < stretched.inverted.size(); ++j) {
    EXPECT_NEAR(stretched.conditionNumber[j], 3.0, kTolerance);
    EXPECT_NEAR(stretched.volumeRatio[j], 3.0, kTolerance);
    EXPECT_TRUE(std::isnan(stretched.stitchResidual[j]));
    EXPECT_NEAR(stretched.rotationAngle[j], 0.0, kTolerance);
  }
  x = rest.vertices;
  x.row(7) = Eigen::RowVector3d(-1.0, -1.0, -1.0);  // through the main diagonal
  const TetQuality inverted = tetQuality(rest, restTetData(rest), x, {});
  const QualitySummary s = summarizeQuality(inverted);
  EXPECT_EQ(s.invertedCount, 6);
  EXPECT_LT(s.volumeRatio.max, 0.0);
  EXPECT_TRUE(std::isnan(s.rotationAngle.mean));
  EXPECT_TRUE(std::isnan(s.stitchResidual.min));
  EXPECT_THROW(tetQuality(rest, restTetData(rest), Vertices(2, 3), {}), InputError);
}

TEST(Quality, FiguresNotAskedForAreNotComputed) {
  const TetMesh rest = boxTetMesh(2, 1, 1, Eigen::Vector3d::Ones());
  Vertices x = rest.vertices;
  x.col(1) *= 2.0;
  const std::vector<Eigen::Matrix3d> targets(rest.tets.rows(), Eigen::Matrix3d::Identity());
  const TetQuality all = tetQuality(rest, restTetData(rest), x, targets);
  const TetQuality some = tetQuality(rest, restTetData(rest), x, targets, {false, true, false});
  EXPECT_TRUE(some.conditionNumber.empty());
  EXPECT_TRUE(some.stitchResidual.empty());
  EXPECT_EQ(some.rotationAngle, all.rotationAngle);
  EXPECT_EQ(some.volumeRatio, all.volumeRatio);
  EXPECT_EQ(some.inverted, all.inverted);
  const QualitySummary s = summarizeQuality(some);
  EXPECT_TRUE(std::isnan(s.conditionNumber.max));
  EXPECT_TRUE(std::isnan(s.stitchResidual.mean));
  EXPECT_NEAR(s.volumeRatio.min, 2.0, kTolerance);
}

}  // namespace
}  // namespace tetblend
