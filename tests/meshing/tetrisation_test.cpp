#include "tetblend/meshing/tetrisation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

#include "test_surfaces.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

using testing_surfaces::cube;

// Unit-scale positions built from a handful of operations: a few ulps.
constexpr double kPositionTol = 1e-14;
// Affine maps of unit-scale tets, compared entrywise: conditioning of the
// rest edge matrices (~10 for the star shapes) times round-off.
constexpr double kMapTol = 1e-11;

TEST(Tetrisation, CubeApexesSitOneUnitOutside) {
  const SurfaceMesh surface = cube();
  const TetMesh mesh = tetrise(surface);
  ASSERT_EQ(mesh.vertices.rows(), 8 + 12);
  ASSERT_EQ(mesh.tets.rows(), 12);
  EXPECT_EQ(mesh.vertices.topRows(8), surface.vertices);
  // Outward normals of the cube's face pairs, in cube()'s face order. Each
  // triangle has area 1/2, so the height sqrt(2 * area) is 1.
  const Eigen::Vector3d normals[6] = {-Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(),
                                      -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY(),
                                      -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX()};
  for (int f = 0; f < 12; ++f) {
    EXPECT_EQ(mesh.tets.row(f).head<3>(), surface.triangles.row(f));
    EXPECT_EQ(mesh.tets(f, 3), 8 + f);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centroid += surface.vertices.row(surface.triangles(f, k)) / 3.0;
    const Eigen::Vector3d apex = mesh.vertices.row(8 + f);
    EXPECT_LE((apex - (centroid + normals[f / 2])).norm(), kPositionTol) << "face " << f;
    EXPECT_NEAR(tetSignedVolume(mesh.vertices, mesh.tets.row(f)), 1.0 / 6.0, kPositionTol);
  }
}

TEST(Tetrisation, OpenSurfacesAreFine) {
  SurfaceMesh open = cube();
  open.triangles.conservativeResize(7, 3);
  const TetMesh mesh = tetrise(open);
  EXPECT_EQ(mesh.tets.rows(), 7);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    EXPECT_GT(tetSignedVolume(mesh.vertices, mesh.tets.row(t)), 0.0);
  }
}

// A similarity x -> s R x + t applied to the example surface must give the
// same similarity as every per-tet map (Kaji–Ochiai property V: the subgroup
// of similarities is preserved), because the apex height scales with s.
TEST(Tetrisation, SimilarExamplesGiveTheSimilarityOnEveryTet) {
  std::mt19937_64 rng(testing_surfaces::testSeed());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    SCOPED_TRACE(trial);
    const SurfaceMesh rest = testing_surfaces::randomStarShape(rng);
    const double scale = std::exp(2.0 * unit(rng));
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(3.0 * unit(rng),
                          Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized())
            .toRotationMatrix();
    const Eigen::Vector3d shift(unit(rng), unit(rng), unit(rng));
    SurfaceMesh example = rest;
    for (Eigen::Index v = 0; v < rest.vertices.rows(); ++v) {
      example.vertices.row(v) =
          (scale * rotation * rest.vertices.row(v).transpose() + shift).transpose();
    }
    const std::vector<TetMesh> meshes = tetriseCompatible(rest, {example}, {"example.off"});
    ASSERT_EQ(meshes.size(), 2u);
    EXPECT_EQ(meshes[0].tets, meshes[1].tets);
    Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
    expected.topLeftCorner<3, 3>() = scale * rotation;
    expected.topRightCorner<3, 1>() = shift;
    for (Eigen::Index t = 0; t < meshes[0].tets.rows(); ++t) {
      const Eigen::Matrix4d map =
          tetAffineMap(meshes[0].vertices, meshes[1].vertices, meshes[0].tets.row(t));
      ASSERT_LE((map - expected).cwiseAbs().maxCoeff(), kMapTol * scale) << "tet " << t;
    }
  }
}

TEST(Tetrisation, DegenerateFaceIsNamed) {
  SurfaceMesh m = cube();
  m.vertices.row(2) = m.vertices.row(1);  // faces 0 and 1 lose their area
  try {
    tetrise(m);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0"), std::string::npos) << e.what();
  }
}

TEST(Tetrisation, IncompatibleExampleIsRefused) {
  SurfaceMesh example = cube();
  example.triangles.row(4) << 0, 5, 1;
  EXPECT_THROW(tetriseCompatible(cube(), {example}, {"pose.off"}), InputError);
}

}  // namespace
}  // namespace tetblend
