// The separated copy of a self-intersecting surface: intersects nowhere
// (exact test), moves only vertices near the intersections, and gives up on
// overlaps that are not slight.

#include "tetblend/meshing/surface_separation.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "address_sanitizer.h"
#include "cgal_meshes.h"
#include "test_surfaces.h"
#include "tetblend/meshing/hole_filling.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

using testing_surfaces::cube;
using testing_surfaces::icosphere;
using testing_surfaces::join;

std::size_t intersectingPairs(const Vertices& vertices, const Triangles& triangles) {
  return findSelfIntersections(vertices, triangles, 1).pairCount;
}

double diagonal(const Vertices& v) {
  return (v.colwise().maxCoeff() - v.colwise().minCoeff()).norm();
}

// Two unit icospheres of 1280 faces (edges of about 0.1) side by side,
// `gap` apart between centres.
SurfaceMesh twoSpheres(double gap) {
  SurfaceMesh right = icosphere(3);
  right.vertices.col(0).array() += gap;
  return join(icosphere(3), right);
}

TEST(SurfaceSeparation, CleanSurfaceComesBackUnchanged) {
  const SurfaceMesh sphere = icosphere();
  const auto separated = separateSelfIntersections(sphere);
  ASSERT_TRUE(separated.has_value());
  EXPECT_EQ(separated->rounds, 0);
  EXPECT_EQ(separated->movedVertices, 0);
  EXPECT_TRUE(separated->vertices == sphere.vertices);
}

// The spheres overlap by 0.1 along the line of centres, so their surfaces
// cross on a circle of radius 0.31 around (0.95, 0, 0): the caps retreat
// inwards, and vertices more than 0.8 from that point (five edges beyond
// the circle) keep their bits.
TEST(SurfaceSeparation, SpheresThatOverlapSlightlyComeApart) {
  const SurfaceMesh touching = twoSpheres(1.9);
  ASSERT_GT(intersectingPairs(touching.vertices, touching.triangles), 0u);
  const auto separated = separateSelfIntersections(touching);
  ASSERT_TRUE(separated.has_value());
  EXPECT_EQ(intersectingPairs(separated->vertices, touching.triangles), 0u);
  EXPECT_LE(separated->largestDisplacement,
            SurfaceSeparationOptions{}.maxDisplacement * diagonal(touching.vertices));
  EXPECT_GT(separated->movedVertices, 0);
  for (Eigen::Index v = 0; v < touching.vertices.rows(); ++v) {
    if ((touching.vertices.row(v) - Eigen::RowVector3d(0.95, 0.0, 0.0)).norm() > 0.8) {
      EXPECT_TRUE(separated->vertices.row(v) == touching.vertices.row(v)) << "vertex " << v;
    }
  }
  EXPECT_TRUE(validateSurface({separated->vertices, touching.triangles}, "separated").ok());
}

// Low-poly meshes part by moving vertices up to an edge, more than 5 % of
// the diagonal: two cubes of 12 triangles touching at a corner.
TEST(SurfaceSeparation, LowPolyContactPartsWithinAnEdge) {
  const SurfaceMesh cubes = join(cube(), cube(Eigen::Vector3d(1.0, 1.0, 1.0)));
  ASSERT_GT(intersectingPairs(cubes.vertices, cubes.triangles), 0u);
  const auto separated = separateSelfIntersections(cubes);
  ASSERT_TRUE(separated.has_value());
  EXPECT_EQ(intersectingPairs(separated->vertices, cubes.triangles), 0u);
  EXPECT_GT(separated->largestDisplacement,
            SurfaceSeparationOptions{}.maxDisplacement * diagonal(cubes.vertices));
  // Every vertex has edges of length 1 and sqrt 2 (mean above 1).
  EXPECT_LE(separated->largestDisplacement, 1.0);
  EXPECT_TRUE(validateSurface({separated->vertices, cubes.triangles}, "separated").ok());
}

// Centres one radius apart: no slight move separates them.
TEST(SurfaceSeparation, DeepOverlapIsNotSeparated) {
  EXPECT_FALSE(separateSelfIntersections(twoSpheres(1.0)).has_value());
}

// Real meshes that intersect themselves, as CGAL ships them: folds of scans,
// crossed sides of thin parts (the bull's), parts that touch. Closed and
// oriented as prepare meshes them (open ones filled) before separating.
TEST(SurfaceSeparation, SelfIntersectingCgalDemoMeshesAreSeparated) {
  const std::string tarball = testing_cgal::cgalDataTarball();
  if (tarball.empty()) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  // Under AddressSanitizer (about 10 times slower) only the four that part
  // in one round; the release suite runs all nine.
  const std::vector<std::string> names =
      test::kAddressSanitizer
          ? std::vector<std::string>{"bull.off", "pig.off", "elk.off", "camel.off"}
          : std::vector<std::string>{"bull.off",       "pig.off",
                                     "elk.off",        "camel.off",
                                     "cow.off",        "ChineseDragon-10kv.off",
                                     "diplodocus.off", "man.off",
                                     "mannequin-devil.off"};
  const std::filesystem::path meshes = testing_cgal::extractCgalMeshes(tarball, names, "separate");
  ASSERT_FALSE(meshes.empty());
  for (const std::string& name : names) {
    SurfaceMesh surface = readSurface((meshes / name).string());
    orientConsistently(surface);
    const HoleFilling filling = fillHoles(surface, name);
    Triangles closed(surface.triangles.rows() + filling.triangles.rows(), 3);
    closed << surface.triangles, filling.triangles;
    surface.triangles = closed;
    orientConsistently(surface);
    const std::size_t before = intersectingPairs(surface.vertices, surface.triangles);
    ASSERT_GT(before, 0u) << name;
    const auto separated = separateSelfIntersections(surface);
    ASSERT_TRUE(separated.has_value()) << name;
    std::printf("%s: %zu intersecting pairs, separated in %d rounds, %d vertices of %d moved, "
                "by at most %.2g %% of the diagonal\n",
                name.c_str(), before, separated->rounds, separated->movedVertices,
                static_cast<int>(surface.vertices.rows()),
                100.0 * separated->largestDisplacement / diagonal(surface.vertices));
    EXPECT_EQ(intersectingPairs(separated->vertices, surface.triangles), 0u) << name;
    EXPECT_TRUE(validateSurface({separated->vertices, surface.triangles}, name).ok()) << name;
  }
  std::filesystem::remove_all(meshes.parent_path().parent_path());
}

}  // namespace
}  // namespace tetblend
