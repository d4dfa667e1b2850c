// The 4 pi twist of Kaji–Ochiai §4.3 / Fig. 2: with consistent rotation
// logarithms a bar twisted by 4 pi blends at weight 0.5 into a 2 pi twist;
// with principal logarithms every tet sees its rotation modulo 2 pi and the
// turns are lost.

#include <gtest/gtest.h>

#include <cmath>

#include "tetblend/blending/shape_blender.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

constexpr int kCells = 2;    // cross-section cells per side
constexpr int kLayers = 48;  // layers along the bar
constexpr double kLength = 8.0;
constexpr double kWidth = 0.2;

// Vertex (i, j, k) of boxTetMesh(kCells, kCells, kLayers).
int vertexIndex(int i, int j, int k) { return i + (kCells + 1) * (j + (kCells + 1) * k); }

// Twist of the top cross-section relative to the base (radians): the angle
// of the cross-section edge from corner (0,0) to corner (kCells,0), unwrapped
// layer by layer along the bar (no layer turns by more than pi).
double twistAngle(const Vertices& x) {
  double total = 0.0;
  double previous = 0.0;
  for (int k = 0; k <= kLayers; ++k) {
    const Eigen::RowVector3d edge = x.row(vertexIndex(kCells, 0, k)) - x.row(vertexIndex(0, 0, k));
    const double angle = std::atan2(edge.y(), edge.x());
    if (k > 0) total += std::remainder(angle - previous, 2.0 * M_PI);
    previous = angle;
  }
  return total;
}

// The example: the bar twisted by 4 pi, then turned rigidly by kTurn about
// its axis. Known limit of per-tet polar rotations: a tet whose in-plane
// rotation is a multiple of 2 pi has polar rotation I + (shear tilt), whose
// logarithms all lie along the tilt axis, so no logarithm continues the
// turns there and that tet blends as an outlier (a local kink). The rigid
// turn keeps those tets away from the bar's ends, where they would decide
// the measured end angle; the thin bar (tilt ~ width * twist rate) keeps
// them few.
constexpr double kTurn = 0.3;

struct TwistedBar {
  TetMesh rest = boxTetMesh(kCells, kCells, kLayers, Eigen::Vector3d(kWidth, kWidth, kLength));
  std::vector<Vertices> examples = {
      twistAboutAxis(rest.vertices, Eigen::Vector3d(0.0, 0.0, -kLength / 2),
                     Eigen::Vector3d::UnitZ(), 4.0 * M_PI, kLength) *
      Eigen::AngleAxisd(kTurn, Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose()};
};

// The blended twist is not exactly linear in the weight (the stretch of the
// sheared tets and the stitch couple in), but it is within a small fraction
// of a turn of 2 pi: 0.05 rad here (measured ~0.01); losing a turn would be
// off by 2 pi.
constexpr double kTwistTolerance = 0.05;

TEST(Twist, ExampleMeasuresFourPi) {
  const TwistedBar bar;
  EXPECT_NEAR(twistAngle(bar.rest.vertices), 0.0, 1e-12);
  EXPECT_NEAR(twistAngle(bar.examples[0]), 4.0 * M_PI, 1e-9);
}

TEST(Twist, FourPiBlendsIntoTwoPiWithConsistentLogarithms) {
  const TwistedBar bar;
  const ShapeBlender blender(bar.rest, bar.examples);  // kaji, consistency on
  EXPECT_NEAR(twistAngle(blender.blend({0.5}).vertices), 2.0 * M_PI, kTwistTolerance);
  EXPECT_NEAR(twistAngle(blender.blend({0.25}).vertices), M_PI, kTwistTolerance);
  EXPECT_NEAR(twistAngle(blender.blend({1.0}).vertices), 4.0 * M_PI, 1e-9);
}

TEST(Twist, PrincipalLogarithmsLoseTheTurns) {
  // Documented property of consistency off: each tet's rotation is taken
  // modulo 2 pi, so the half-way shape keeps less than half a turn.
  const TwistedBar bar;
  ShapeBlenderOptions options;
  options.rotationConsistency = false;
  const ShapeBlender blender(bar.rest, bar.examples, options);
  EXPECT_LT(std::abs(twistAngle(blender.blend({0.5}).vertices)), M_PI);
}

}  // namespace
}  // namespace tetblend
