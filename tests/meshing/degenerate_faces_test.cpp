// Degenerate faces flipped away for meshing (degenerate_faces.h): caps on
// T-junctions (a vertex in the middle of an edge, closed by a face of zero
// area, or just off the edge) become two faces splitting the neighbour, runs
// of collinear points resolve one by one, and what no flip can fix (a face
// on the boundary, a needle) is left as it is.

#include "tetblend/meshing/degenerate_faces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_seed.h"
#include "test_surfaces.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

int zeroAreaFaces(const SurfaceMesh& mesh) {
  int count = 0;
  for (const SurfaceProblem& p : validateSurface(mesh, "mesh").problems) {
    count += p.kind == SurfaceProblemKind::kZeroAreaFace ? 1 : 0;
  }
  return count;
}

// A flip re-splits a face into two with the same plane and the same
// boundary: the enclosed volume (a sum of ~1000 signed tet volumes of unit
// size) changes by round-off only.
constexpr double kVolumeRelTol = 1e-12;

TEST(DegenerateFaces, CapsOnTJunctionsAreFlippedAwayKeepingTheShape) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(20261127u));
  SurfaceMesh mesh = testing_surfaces::icosphere(2);
  const double volume = enclosedVolume(mesh);
  // Ten caps, each on the middle child of one face of the level-1 sphere
  // (faces 4j + 3: its neighbours are that face's other children), on a
  // random edge: no two caps touch the same faces.
  std::uniform_int_distribution<int> corner(0, 2);
  for (int parent = 0; parent < 80; parent += 8)
    testing_surfaces::insertCap(mesh, 4 * parent + 3, corner(rng), 1);
  ASSERT_EQ(zeroAreaFaces(mesh), 10);
  const Eigen::Index faces = mesh.triangles.rows();
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 10);
  EXPECT_EQ(flips.left, 0);
  EXPECT_EQ(mesh.triangles.rows(), faces);
  const SurfaceValidation checked = validateSurface(mesh, "flipped");
  EXPECT_TRUE(checked.ok()) << checked.problems.front().message;
  // The new faces split the neighbours: the same solid, to round-off.
  EXPECT_NEAR(enclosedVolume(mesh), volume, kVolumeRelTol * volume);
}

TEST(DegenerateFaces, ARunOfCollinearPointsResolvesOneFlipAtATime) {
  SurfaceMesh mesh = testing_surfaces::icosphere(1);
  testing_surfaces::insertCap(mesh, 7, 0, 3);  // three points on one edge: three zero-area faces
  ASSERT_EQ(zeroAreaFaces(mesh), 3);
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 3);
  EXPECT_EQ(flips.left, 0);
  const SurfaceValidation checked = validateSurface(mesh, "flipped");
  EXPECT_TRUE(checked.ok()) << checked.problems.front().message;
}

TEST(DegenerateFaces, AFaceOnTheBoundaryIsLeftForTheValidation) {
  // Three points on a line, one face: no neighbour across its longest edge.
  SurfaceMesh mesh;
  mesh.vertices.resize(3, 3);
  mesh.vertices << 0, 0, 0, 2, 0, 0, 1, 0, 0;
  mesh.triangles.resize(1, 3);
  mesh.triangles << 0, 1, 2;
  const SurfaceMesh before = mesh;
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 0);
  EXPECT_EQ(flips.left, 1);
  EXPECT_EQ(mesh.triangles, before.triangles);
}

// Caps whose middle vertex an exporter's welding left just off the edge:
// the vertex moved by `height` times the edge's length, perpendicular to it
// in a random direction (outwards, inwards or along the surface), on the
// ten caps of the first test.
SurfaceMesh sphereWithNearCaps(double height, std::mt19937& rng) {
  SurfaceMesh mesh = testing_surfaces::icosphere(2);
  std::uniform_int_distribution<int> corner(0, 2);
  for (int parent = 0; parent < 80; parent += 8) {
    const int f = 4 * parent + 3;
    const int k = corner(rng);
    const Eigen::RowVector3d a = mesh.vertices.row(mesh.triangles(f, k));
    const Eigen::RowVector3d b = mesh.vertices.row(mesh.triangles(f, (k + 1) % 3));
    testing_surfaces::insertCap(mesh, f, k, 1);
    const Eigen::Vector3d along = (b - a).normalized().transpose();
    const Eigen::Vector3d u = along.unitOrthogonal();
    const double angle = test_seed::uniform(rng, 0.0, 2.0 * kPi);
    const Eigen::Vector3d across = std::cos(angle) * u + std::sin(angle) * along.cross(u);
    mesh.vertices.bottomRows(1) += height * (b - a).norm() * across.transpose();
  }
  return mesh;
}

TEST(DegenerateFaces, CapsJustOffTheirEdgeAreFlippedToo) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(20261128u));
  constexpr double kHeight = 1e-4;  // a tenth of kCapRelativeHeight
  SurfaceMesh mesh = sphereWithNearCaps(kHeight, rng);
  ASSERT_EQ(zeroAreaFaces(mesh), 0);  // not degenerate by the validation's absolute rule
  const double volume = enclosedVolume(mesh);
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 10);
  EXPECT_EQ(flips.left, 0);
  const SurfaceValidation checked = validateSurface(mesh, "flipped");
  EXPECT_TRUE(checked.ok()) << checked.problems.front().message;
  // Each flip adds or removes the tet (u, v, c, d): a third of the cap's
  // area, kHeight L² / 2, times d's distance, at most an edge L (<= 0.35 on
  // this sphere of radius 1).
  constexpr double kEdge = 0.35;
  EXPECT_NEAR(enclosedVolume(mesh), volume, 10 * kHeight * kEdge * kEdge * kEdge / 6.0);
}

TEST(DegenerateFaces, CapsHigherThanTheBoundAreLeftAsTheyAre) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(20261128u));
  SurfaceMesh mesh = sphereWithNearCaps(10 * kCapRelativeHeight, rng);
  const Triangles before = mesh.triangles;
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 0);
  EXPECT_EQ(flips.left, 0);
  EXPECT_EQ(mesh.triangles, before);
}

// A needle (a face with one short edge) is as thin as a cap, but a flip
// across its longest edge makes another needle: it stays.
TEST(DegenerateFaces, ANeedleIsNotFlipped) {
  SurfaceMesh mesh = testing_surfaces::icosphere(2);
  const int i = mesh.triangles(0, 0);
  const int j = mesh.triangles(0, 1);
  mesh.vertices.row(i) =
      mesh.vertices.row(j) + 1e-5 * (mesh.vertices.row(i) - mesh.vertices.row(j));
  const Triangles before = mesh.triangles;
  const DegenerateFaceFlips flips = flipDegenerateFaces(mesh, kDefaultZeroAreaRelTol);
  EXPECT_EQ(flips.flipped, 0);
  EXPECT_EQ(flips.left, 2);  // the two faces on the short edge
  EXPECT_EQ(mesh.triangles, before);
}

}  // namespace
}  // namespace tetblend
