// Degenerate faces flipped away for meshing (degenerate_faces.h): caps on
// T-junctions (a vertex in the middle of an edge, closed by a face of zero
// area) become two faces splitting the neighbour, runs of collinear points
// resolve one by one, and what no flip can fix is left for the validation.

#include "tetblend/meshing/degenerate_faces.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "test_seed.h"
#include "test_surfaces.h"
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

}  // namespace
}  // namespace tetblend
