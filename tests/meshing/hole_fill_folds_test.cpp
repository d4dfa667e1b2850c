// sharpestFold (meshing/src/hole_fill_folds.h) on fills whose folds are
// known in closed form: a square hole in the top of an open unit cube,
// closed by two triangles along one diagonal, the far corner lifted so the
// two triangles meet at a chosen angle; the rim faces are the cube's walls.

#include "hole_fill_folds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tetblend/core/constants.h"

namespace tetblend {
namespace {

// Folds computed from unit normals of exact small-integer coordinates: a
// few ulps of acos near its well-conditioned middle; near 0 and π acos
// loses half the digits, so 1e-7 rad there.
constexpr double kAngleTol = 1e-7;

// The open cube's vertices 0..7 (bottom square 0-3, top square 4-7, counter-
// clockwise seen from above) and its five walls, faces outward; the top
// square 4-5-6-7 is the hole.
struct OpenCube {
  Vertices positions;
  Triangles walls;
  std::vector<Border> rim;
};

OpenCube openCube() {
  OpenCube cube;
  cube.positions.resize(8, 3);
  cube.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  cube.walls.resize(10, 3);
  cube.walls << 0, 2, 1, 0, 3, 2,  // bottom, facing −z
      0, 1, 5, 0, 5, 4,            // y = 0
      1, 2, 6, 1, 6, 5,            // x = 1
      2, 3, 7, 2, 7, 6,            // y = 1
      3, 0, 4, 3, 4, 7;            // x = 0
  // The fill runs 4 -> 5 -> 6 -> 7 (facing +z); across each rim edge, the
  // wall face that runs it the other way.
  cube.rim = {{4, 5, 3}, {5, 6, 5}, {6, 7, 7}, {7, 4, 9}};
  return cube;
}

TEST(HoleFillFolds, AFlatLidFoldsByRightAnglesAtTheRimOnly) {
  const OpenCube cube = openCube();
  const FillTriangles lid = {{4, 5, 6}, {4, 6, 7}};
  EXPECT_NEAR(sharpestFold(lid, cube.rim, cube.walls, cube.positions), kPi / 2, kAngleTol);
}

// Corner 5 at (x, y, 1 + h), the lid's edges only (no rim): triangle
// (4, 5, 6) has the normal (−h, h, x − y)/‖·‖ and (4, 6, 7) the normal
// (0, 0, 1), so the fold along the diagonal 4-6 is atan(√2 h) with 5 above
// its own corner (x − y = 1) and π − atan(√2 h) with 5 carried across the
// diagonal above corner 7 (x − y = −1): both sides of a right angle.
TEST(HoleFillFolds, ALiftedCornerFoldsTheLidAlongItsDiagonal) {
  const FillTriangles lid = {{4, 5, 6}, {4, 6, 7}};
  for (const double h : {0.0, 0.25, 1.0, 20.0}) {
    SCOPED_TRACE(h);
    OpenCube cube = openCube();
    cube.positions.row(5) << 1.0, 0.0, 1.0 + h;
    EXPECT_NEAR(sharpestFold(lid, {}, cube.walls, cube.positions), std::atan(std::sqrt(2.0) * h),
                kAngleTol);
    cube.positions.row(5) << 0.0, 1.0, 1.0 + h;
    EXPECT_NEAR(sharpestFold(lid, {}, cube.walls, cube.positions),
                kPi - std::atan(std::sqrt(2.0) * h), kAngleTol);
  }
}

TEST(HoleFillFolds, ATentFoldedFlatIsAFoldOfPi) {
  // Corners 5 and 7 both moved onto the point above the diagonal's middle:
  // the triangles (4, 5, 6) and (4, 6, 7) lie on top of each other.
  OpenCube cube = openCube();
  cube.positions.row(5) << 0.5, 0.5, 2.0;
  cube.positions.row(7) << 0.5, 0.5, 2.0;
  const FillTriangles lid = {{4, 5, 6}, {4, 6, 7}};
  EXPECT_NEAR(sharpestFold(lid, cube.rim, cube.walls, cube.positions), kPi, kAngleTol);
}

TEST(HoleFillFolds, ATriangleOfZeroAreaCountsAsAFoldOfPi) {
  OpenCube cube = openCube();
  cube.positions.row(5) = 0.5 * (cube.positions.row(4) + cube.positions.row(6));
  const FillTriangles lid = {{4, 5, 6}, {4, 6, 7}};
  EXPECT_EQ(sharpestFold(lid, cube.rim, cube.walls, cube.positions), kPi);
}

}  // namespace
}  // namespace tetblend
