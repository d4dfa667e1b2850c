// Seams zipped (seam_welding.h): vertices split along texture and normal
// seams are merged with their twins, and nothing else is.

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

#include "tetblend/core/error.h"
#include "tetblend/meshing/seam_welding.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

// The unit cube's 8 corners, corner i at ((i & 1), (i >> 1) & 1, (i >> 2) & 1).
Eigen::RowVector3d corner(int i) {
  return {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)};
}

// The cube's 6 sides as outward quads of corner numbers.
constexpr std::array<std::array<int, 4>, 6> kSides = {
    {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};

// A flat-shaded export of the cube: every side has its own 4 vertices (24 in
// all), split into 2 triangles, so the surface is 6 separate squares.
SurfaceMesh facetedCube() {
  SurfaceMesh mesh;
  mesh.vertices.resize(24, 3);
  mesh.triangles.resize(12, 3);
  for (int s = 0; s < 6; ++s) {
    for (int k = 0; k < 4; ++k) mesh.vertices.row(4 * s + k) = corner(kSides[s][k]);
    mesh.triangles.row(2 * s) << 4 * s, 4 * s + 1, 4 * s + 2;
    mesh.triangles.row(2 * s + 1) << 4 * s, 4 * s + 2, 4 * s + 3;
  }
  return mesh;
}

bool closedAndValid(const SurfaceMesh& mesh) { return validateSurface(mesh, "welded").ok(); }

TEST(SeamWelding, AFlatShadedCubeIsZippedIntoTheClosedCube) {
  const SurfaceMesh faceted = facetedCube();
  ASSERT_FALSE(closedAndValid(faceted));
  const SeamWelding welding = weldSeams(faceted);
  EXPECT_EQ(welding.surface.vertices.rows(), 8);
  EXPECT_EQ(welding.mergedVertices, 16);
  EXPECT_EQ(welding.seamEdges, 12);  // the cube's edges
  EXPECT_TRUE(closedAndValid(welding.surface));
  ASSERT_EQ(welding.rowOf.size(), 24u);
  for (int v = 0; v < 24; ++v) {
    // Each input vertex went to the row holding its own position...
    EXPECT_TRUE(welding.surface.vertices.row(welding.rowOf[v]) == faceted.vertices.row(v)) << v;
    // ...and the rows keep the order of the first vertex of each group.
    for (int u = 0; u < v; ++u) {
      if (faceted.vertices.row(u) == faceted.vertices.row(v)) {
        EXPECT_EQ(welding.rowOf[u], welding.rowOf[v]) << u << " " << v;
      }
    }
  }
  for (int r = 1; r < 8; ++r) {
    int firstOf = -1, firstOfPrevious = -1;
    for (int v = 23; v >= 0; --v) {
      if (welding.rowOf[v] == r) firstOf = v;
      if (welding.rowOf[v] == r - 1) firstOfPrevious = v;
    }
    EXPECT_LT(firstOfPrevious, firstOf) << r;
  }
  for (Eigen::Index f = 0; f < 12; ++f) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(welding.surface.triangles(f, c), welding.rowOf[faceted.triangles(f, c)]);
    }
  }
}

TEST(SeamWelding, ASurfaceWithoutSeamsIsLeftAsItIs) {
  SurfaceMesh cube;
  cube.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) cube.vertices.row(i) = corner(i);
  cube.triangles.resize(12, 3);
  for (int s = 0; s < 6; ++s) {
    cube.triangles.row(2 * s) << kSides[s][0], kSides[s][1], kSides[s][2];
    cube.triangles.row(2 * s + 1) << kSides[s][0], kSides[s][2], kSides[s][3];
  }
  const SeamWelding welding = weldSeams(cube);
  EXPECT_EQ(welding.mergedVertices, 0);
  EXPECT_TRUE(welding.surface.vertices == cube.vertices);
  EXPECT_TRUE(welding.surface.triangles == cube.triangles);
  EXPECT_EQ(welding.rowOf, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

// A flat-shaded export that oriented some facets inwards: their seam edges
// run the same way as their twins. They are zipped all the same, and the
// zipped cube can then be oriented consistently.
TEST(SeamWelding, FacetsOrientedEitherWayAreZipped) {
  SurfaceMesh faceted = facetedCube();
  for (const int side : {1, 4}) {
    for (int half = 0; half < 2; ++half) {
      const Eigen::Index f = 2 * side + half;
      std::swap(faceted.triangles(f, 1), faceted.triangles(f, 2));
    }
  }
  SeamWelding welding = weldSeams(faceted);
  EXPECT_EQ(welding.surface.vertices.rows(), 8);
  EXPECT_EQ(welding.seamEdges, 12);
  EXPECT_FALSE(closedAndValid(welding.surface));  // two sides face inwards
  orientConsistently(welding.surface);
  EXPECT_TRUE(closedAndValid(welding.surface));
}

// Three squares sharing one edge position (a fin on a seam): no edge has a
// single twin there, so that edge is left open; only true pairs are zipped.
TEST(SeamWelding, AnEdgePositionSharedByThreeBoundaryEdgesIsNotZipped) {
  SurfaceMesh fin;
  // Square A: (0,0,0) (1,0,0) (1,1,0) (0,1,0); square B its mirror copy across
  // the edge x = 0 running the other way; square C a third sheet on that edge.
  fin.vertices.resize(12, 3);
  fin.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,  //
      0, 1, 0, -1, 1, 0, -1, 0, 0, 0, 0, 0,            //
      0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0;
  fin.triangles.resize(6, 3);
  fin.triangles << 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11;
  const SeamWelding welding = weldSeams(fin);
  EXPECT_EQ(welding.mergedVertices, 0);
  // Without the third sheet, A's edge 3 -> 0 and B's edge 7 -> 4 are the two
  // sides of a seam.
  SurfaceMesh pair{fin.vertices.topRows(8), fin.triangles.topRows(4)};
  const SeamWelding zipped = weldSeams(pair);
  EXPECT_EQ(zipped.mergedVertices, 2);
  EXPECT_EQ(zipped.seamEdges, 1);
  EXPECT_EQ(zipped.rowOf[7], zipped.rowOf[0]);
  EXPECT_EQ(zipped.rowOf[4], zipped.rowOf[3]);
}

// Input the validation refuses later is left for it to name.
TEST(SeamWelding, BadInputIsLeftAsItIs) {
  SurfaceMesh outOfRange = facetedCube();
  outOfRange.triangles(3, 1) = 24;
  EXPECT_EQ(weldSeams(outOfRange).mergedVertices, 0);
  outOfRange.triangles(3, 1) = -1;
  EXPECT_EQ(weldSeams(outOfRange).mergedVertices, 0);
  SurfaceMesh notFinite = facetedCube();
  notFinite.vertices(5, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(weldSeams(notFinite).mergedVertices, 0);
  EXPECT_TRUE(weldSeams(notFinite).surface.triangles == notFinite.triangles);
}

TEST(SeamWelding, ExamplesAreMovedToTheMergedRowsAndAnOpenedSeamIsRefused) {
  const SurfaceMesh faceted = facetedCube();
  const SeamWelding welding = weldSeams(faceted);
  // An example: the cube sheared, every copy of a corner moved alike.
  Vertices example = faceted.vertices;
  example.col(0) += 0.5 * example.col(2);
  const Vertices merged = weldedPositions(welding, example, "example.off");
  ASSERT_EQ(merged.rows(), 8);
  for (int v = 0; v < 24; ++v) EXPECT_TRUE(merged.row(welding.rowOf[v]) == example.row(v)) << v;

  Vertices opened = example;
  opened(13, 1) += 0.25;  // one copy of a corner moves alone
  try {
    weldedPositions(welding, opened, "opened.off");
    FAIL() << "a seam that opens in an example was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("opened.off"), std::string::npos) << message;
    EXPECT_NE(message.find(" and 13 "), std::string::npos) << message;
    EXPECT_NE(message.find("0.25"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace tetblend
