// End to end: an open rest surface (a tube open at both ends) is prepared by
// closing its holes with triangles between its boundary vertices; blends keep
// the user's faces and reproduce the rest and every example at the surface.
// --no-fill-holes refuses it as before; a texture seam is zipped; holes
// that touch are filled around the vertex they share; a fill through the
// surface falls back to a tet per face; an example whose fill folds through
// the tube loses tets to the exclusion.

#include <Eigen/Geometry>

#include "apps_test_support.h"
#include "test_surfaces.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

// The promise: unit weights reproduce each example at the surface to
// 1e-9 of the bounding-box diagonal (the stitch is a least-squares solve of
// a compatible field; round-off is ~1e-13 of the size on this small mesh).
constexpr double kInterpolationRelTol = 1e-9;
constexpr int kSegments = 16;  // vertices per ring: two holes of 16 edges

class OpenRest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    std::vector<double> radii, heights;
    for (int k = 0; k <= 8; ++k) {
      radii.push_back(0.5);
      heights.push_back(0.5 * k);
    }
    tube_ = testing_surfaces::ringStack(kSegments, radii, heights);
    const SurfaceMesh& rest = tube_.mesh;
    const Eigen::Vector3d origin = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
    writeSurface(path("rest.obj"), rest);
    writeSurface(
        path("twist.obj"),
        SurfaceMesh{twistAboutAxis(rest.vertices, origin, axis, kPi, 4.0), rest.triangles});
    writeSurface(path("bend.obj"),
                 SurfaceMesh{bendAboutAxis(rest.vertices, origin, axis, Eigen::Vector3d::UnitX(),
                                           0.5 * kPi, 4.0),
                             rest.triangles});
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
  testing_surfaces::RingStack tube_;
};

TEST_F(OpenRest, HolesAreFilledAndBlendsKeepTheUsersFaces) {
  const fs::path model = dir_ / "tube.tbm";
  const RunResult r = tetblend(
      {"prepare", path("rest.obj"), path("twist.obj"), path("bend.obj"), "-o", model.string()},
      dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  // Two 16-gons take 2 × 14 triangles.
  EXPECT_NE(r.err.find("filled 2 holes with 28 triangles, no new vertices"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;

  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,0", "rest.obj"}, {"1,0", "twist.obj"}, {"0,1", "bend.obj"}};
  for (const std::string method : {"kaji", "linear"}) {
    for (const auto& [weights, expected] : cases) {
      SCOPED_TRACE(method + " at " + weights);
      const fs::path out = dir_ / (method + weights.substr(0, 1) + weights.substr(2) + ".vtu");
      const RunResult blend = tetblend(
          {"blend", model.string(), "-w", weights, "--method", method, "-o", out.string()}, dir_);
      ASSERT_EQ(blend.code, 0) << blend.err;
      const auto vtp = readVtp(fs::path(out).replace_extension(".vtp"));
      EXPECT_EQ(vtp->GetNumberOfPolys(), tube_.mesh.triangles.rows());
      const SurfaceMesh target = readSurface(path(expected));
      EXPECT_LT(maxDistance(pointsOf(vtp), target.vertices),
                kInterpolationRelTol * boundingBoxDiagonal(target.vertices));
    }
  }
}

TEST_F(OpenRest, NoFillHolesRefusesAsBefore) {
  const RunResult r = tetblend({"prepare", path("rest.obj"), path("twist.obj"), "--no-fill-holes",
                                "-o", (dir_ / "refused.tbm").string()},
                               dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("is a boundary edge (32 in total)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("let prepare fill the holes"), std::string::npos) << r.err;
}

TEST_F(OpenRest, TouchingHolesAreFilledAroundTheirSharedVertex) {
  // Drop the two triangles of quad 3 of band 0 and of quad 4 of band 1: the
  // bottom hole and the new one then touch at vertex v = (ring 1, 4), where
  // two fans of faces meet. Each hole's fill takes its own corner at v, so
  // the tube keeps its interior and the keys are exact, with --strict too
  // (nothing is inexact). Written twice: v shared, and v written as two
  // vertices at one position (one per fan, as a scan's touching rims are),
  // which are joined for meshing and share one row in the model.
  SurfaceMesh touching{tube_.mesh.vertices, Triangles(tube_.mesh.triangles.rows() - 4, 3)};
  int kept = 0;
  for (int f = 0; f < tube_.mesh.triangles.rows(); ++f) {
    const int quad = f / 2;
    if (quad == 3 || quad == kSegments + 4) continue;
    touching.triangles.row(kept++) = tube_.mesh.triangles.row(f);
  }
  const int v = tube_.vertex(1, 4);
  SurfaceMesh copied = touching;
  const auto copy = static_cast<int>(copied.vertices.rows());
  copied.vertices.conservativeResize(copy + 1, 3);
  copied.vertices.row(copy) = copied.vertices.row(v);
  for (Eigen::Index f = 0; f < copied.triangles.rows(); ++f) {
    const auto face = copied.triangles.row(f);
    const bool inQuad3OfBand1 =
        (face.array() == tube_.vertex(2, 3)).any() || (face.array() == tube_.vertex(2, 4)).any();
    for (int c = 0; c < 3; ++c) {
      if (face(c) == v && inQuad3OfBand1) {
        copied.triangles(f, c) = copy;
      }
    }
  }
  const Vertices twisted = readSurface(path("twist.obj")).vertices;
  for (const auto& [name, rest] : {std::pair{"shared", &touching}, std::pair{"copied", &copied}}) {
    SCOPED_TRACE(name);
    Vertices twist = twisted;
    twist.conservativeResize(rest->vertices.rows(), 3);
    if (rest == &copied) twist.row(copy) = twist.row(v);
    writeSurface(path(std::string(name) + ".obj"), *rest);
    writeSurface(path(std::string(name) + "_twist.obj"), SurfaceMesh{twist, rest->triangles});
    for (const bool strict : {false, true}) {
      const fs::path model = dir_ / (std::string(name) + (strict ? "_strict" : "") + ".tbm");
      std::vector<std::string> args{"prepare", path(std::string(name) + ".obj"),
                                    path(std::string(name) + "_twist.obj"), "-o", model.string()};
      if (strict) args.push_back("--strict");
      const RunResult r = tetblend(args, dir_);
      ASSERT_EQ(r.code, 0) << r.err;
      // The bottom hole with its notch at quad 3, quad 4 of band 1, the top.
      EXPECT_NE(r.err.find("filled 3 holes"), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find("a tet of its own"), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find("on its own"), std::string::npos) << r.err;
      const bool joined =
          r.err.find("1 vertices on the rims of its holes at the same position as another") !=
          std::string::npos;
      EXPECT_EQ(joined, rest == &copied) << r.err;
      const ModelData m = readModelFile(model.string());
      EXPECT_GT(m.rest.vertices.rows(), tube_.mesh.vertices.rows()) << "no interior vertex";
      EXPECT_TRUE(m.excludedTets.empty());
      if (rest == &copied) {
        ASSERT_EQ(m.inputVertexRows.size(), static_cast<std::size_t>(copy + 1));
        EXPECT_EQ(m.inputVertexRows[static_cast<std::size_t>(copy)],
                  m.inputVertexRows[static_cast<std::size_t>(v)]);
      }
      for (const auto& [w, expected] : {std::pair{"0", &rest->vertices}, std::pair{"1", &twist}}) {
        const fs::path out = dir_ / (std::string(name) + w + ".vtp");
        ASSERT_EQ(tetblend({"blend", model.string(), "-w", w, "-o", out.string()}, dir_).code, 0);
        EXPECT_LT(maxDistance(pointsOf(readVtp(out)), *expected),
                  kInterpolationRelTol * boundingBoxDiagonal(*expected));
      }
    }
  }
}

TEST_F(OpenRest, ARimTouchingAnotherPartsVertexIsMeshedWhole) {
  // A ball beside the tube, moved so that one of its vertices lies exactly
  // on a vertex of the tube's top rim (two vertices at one position, only
  // one of them on a rim, as where a scan's hole runs into a fold). That is
  // no pair of touching rims: the tube's holes are filled as usual, and the
  // two closed parts, which touch at that point, are meshed each on its
  // own within one model, not prepared part by part. The keys are exact.
  SurfaceMesh ball = testing_surfaces::icosphere(2);
  ball.vertices *= 0.4;
  Eigen::Index lowest = 0;
  ball.vertices.col(0).minCoeff(&lowest);
  const Eigen::RowVector3d rim = tube_.mesh.vertices.row(tube_.vertex(8, 0));  // (0.5, 0, 4)
  ball.vertices.rowwise() += rim - ball.vertices.row(lowest);
  const SurfaceMesh rest = testing_surfaces::join(tube_.mesh, ball);
  const SurfaceMesh bent{
      bendAboutAxis(rest.vertices, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                    Eigen::Vector3d::UnitX(), 0.5 * kPi, 8.0),
      rest.triangles};
  writeSurface(path("ball.obj"), rest);
  writeSurface(path("ball_bent.obj"), bent);
  const fs::path model = dir_ / "ball.tbm";
  const RunResult r =
      tetblend({"prepare", path("ball.obj"), path("ball_bent.obj"), "-o", model.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("filled 2 holes"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("rims of its holes"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("prepared on its own"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("a tet of its own"), std::string::npos) << r.err;
  for (const auto& [w, expected] : {std::pair{"0", &rest}, std::pair{"1", &bent}}) {
    const fs::path out = dir_ / (std::string("ball") + w + ".vtp");
    ASSERT_EQ(tetblend({"blend", model.string(), "-w", w, "-o", out.string()}, dir_).code, 0);
    EXPECT_LT(maxDistance(pointsOf(readVtp(out)), expected->vertices),
              kInterpolationRelTol * boundingBoxDiagonal(rest.vertices));
  }
}

TEST_F(OpenRest, TubesTouchingAtARimVertexArePreparedEachOnItsOwn) {
  // A second tube on top of the first, one diameter aside: its bottom ring
  // touches the first's top ring at one point, where the two share a vertex
  // (one index). The holes touch there, so the two cannot be filled
  // together, but each can.
  SurfaceMesh upper = tube_.mesh;
  upper.vertices.col(0).array() += 1.0;
  upper.vertices.col(2).array() += 4.0;
  SurfaceMesh pair = testing_surfaces::join(tube_.mesh, upper);
  const int shared = tube_.vertex(8, 0);
  const auto joinedAway =
      static_cast<int>(tube_.mesh.vertices.rows()) + tube_.vertex(0, kSegments / 2);
  for (Eigen::Index i = 0; i < pair.triangles.size(); ++i) {
    if (pair.triangles.data()[i] == joinedAway) pair.triangles.data()[i] = shared;
  }
  const SurfaceMesh rest = removeVertices(pair, {joinedAway});
  const SurfaceMesh bent{
      bendAboutAxis(rest.vertices, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                    Eigen::Vector3d::UnitX(), 0.5 * kPi, 8.0),
      rest.triangles};
  writeSurface(path("pair.obj"), rest);
  writeSurface(path("pair_bent.obj"), bent);
  const fs::path model = dir_ / "pair.tbm";
  const RunResult r =
      tetblend({"prepare", path("pair.obj"), path("pair_bent.obj"), "-o", model.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("instead, each of its 2 components is prepared on its own"),
            std::string::npos)
      << r.err;
  // Both tubes have interiors, and both use one row for the shared vertex.
  const ModelData m = readModelFile(model.string());
  EXPECT_GT(m.rest.vertices.rows(), rest.vertices.rows() + 1);
  std::vector<int> uses(static_cast<std::size_t>(m.rest.vertices.rows()), 0);
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) ++uses[static_cast<std::size_t>(m.rest.tets(t, c))];
  }
  EXPECT_EQ(std::count(uses.begin(), uses.end(), 0), 1);
  for (const auto& [w, expected] : {std::pair{"0", &rest}, std::pair{"1", &bent}}) {
    const fs::path out = dir_ / (std::string("pair") + w + ".vtp");
    ASSERT_EQ(tetblend({"blend", model.string(), "-w", w, "-o", out.string()}, dir_).code, 0);
    EXPECT_LT(maxDistance(pointsOf(readVtp(out)), expected->vertices),
              kInterpolationRelTol * boundingBoxDiagonal(rest.vertices));
  }
}

TEST_F(OpenRest, FillThroughTheSurfaceFallsBackToATetPerFace) {
  // The tube's last band but one climbs inwards above the plane of its top
  // ring (ring 7: radius 0.15 at height 4.5), the last comes back down to
  // it: the flat fill of the top hole must cut the band climbing through the
  // plane, at radius 0.27. No interior fits: each face gets a tet of its own
  // (one note line), and the blends stay exact; --strict refuses it.
  std::vector<double> radii(9, 0.5), heights;
  for (int k = 0; k <= 8; ++k) heights.push_back(0.5 * k);
  radii[7] = 0.15;
  heights[7] = 4.5;
  heights[8] = 4.0;
  const SurfaceMesh rest = testing_surfaces::ringStack(kSegments, radii, heights).mesh;
  writeSurface(path("folded.obj"), rest);
  writeSurface(path("folded_twist.obj"), SurfaceMesh{1.1 * rest.vertices, rest.triangles});
  const std::vector<std::string> args = {"prepare", path("folded.obj"), path("folded_twist.obj"),
                                         "-o", (dir_ / "folded.tbm").string()};
  const RunResult r = tetblend(args, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("folded.obj: a triangle filling one of its holes intersects face "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("instead, each of its 256 faces gets a tet of its own"), std::string::npos)
      << r.err;
  const ModelData m = readModelFile((dir_ / "folded.tbm").string());
  EXPECT_EQ(m.rest.tets.rows(), rest.triangles.rows());
  const fs::path out = dir_ / "folded_one.vtp";
  ASSERT_EQ(
      tetblend({"blend", (dir_ / "folded.tbm").string(), "-w", "1", "-o", out.string()}, dir_).code,
      0);
  EXPECT_LT(maxDistance(pointsOf(readVtp(out)), 1.1 * rest.vertices),
            kInterpolationRelTol * boundingBoxDiagonal(rest.vertices));

  std::vector<std::string> strict = args;
  strict.back() = (dir_ / "strict.tbm").string();
  strict.push_back("--strict");
  const std::vector<std::string> before = listDir(dir_);
  const RunResult refused = tetblend(strict, dir_);
  expectOneLineError(refused);
  EXPECT_NE(refused.err.find("folded.obj: a triangle filling one of its holes intersects face "),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("close them yourself"), std::string::npos) << refused.err;
  EXPECT_EQ(listDir(dir_), before);
}

TEST_F(OpenRest, FillThroughAnotherComponentIsMeshedOnItsOwn) {
  // A small closed cube inside the tube, straddling the plane of its top
  // ring: the flat fill of the top hole cuts the cube, another component, so
  // the closed tube and the cube are meshed each on its own.
  const SurfaceMesh cube = testing_surfaces::cube(Eigen::Vector3d(-0.1, -0.1, 3.9), 0.2);
  const SurfaceMesh rest = testing_surfaces::join(tube_.mesh, cube);
  writeSurface(path("plugged.obj"), rest);
  writeSurface(path("plugged_twist.obj"), SurfaceMesh{1.1 * rest.vertices, rest.triangles});
  const fs::path model = dir_ / "plugged.tbm";
  const RunResult r = tetblend(
      {"prepare", path("plugged.obj"), path("plugged_twist.obj"), "-o", model.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("plugged.obj: its 2 closed components intersect one another"),
            std::string::npos)
      << r.err;
  const fs::path out = dir_ / "plugged_one.vtu";
  ASSERT_EQ(tetblend({"blend", model.string(), "-w", "1", "-o", out.string()}, dir_).code, 0);
  EXPECT_LT(
      maxDistance(pointsOf(readVtp(fs::path(out).replace_extension(".vtp"))), 1.1 * rest.vertices),
      kInterpolationRelTol * boundingBoxDiagonal(rest.vertices));
}

// `sphere` cut open along its equator as a texture seam cuts it: the faces
// of the upper half use their own copies of the equator's vertices, which
// follow the originals.
SurfaceMesh cutAlongTheEquator(const SurfaceMesh& sphere) {
  SurfaceMesh seamed = sphere;
  std::vector<int> copy(static_cast<std::size_t>(sphere.vertices.rows()), -1);
  std::vector<int> original;
  for (Eigen::Index f = 0; f < sphere.triangles.rows(); ++f) {
    double z = 0.0;
    for (int c = 0; c < 3; ++c) z += sphere.vertices(sphere.triangles(f, c), 2);
    if (z <= 0.0) continue;
    for (int c = 0; c < 3; ++c) {
      const int v = sphere.triangles(f, c);
      if (std::abs(sphere.vertices(v, 2)) > 1e-12) continue;  // not on the equator
      if (copy[v] < 0) {
        copy[v] = static_cast<int>(sphere.vertices.rows() + original.size());
        original.push_back(v);
      }
      seamed.triangles(f, c) = copy[v];
    }
  }
  seamed.vertices.conservativeResize(
      sphere.vertices.rows() + static_cast<Eigen::Index>(original.size()), 3);
  for (std::size_t i = 0; i < original.size(); ++i) {
    seamed.vertices.row(sphere.vertices.rows() + static_cast<Eigen::Index>(i)) =
        sphere.vertices.row(original[i]);
  }
  return seamed;
}

// Both holes of the cut sphere would be filled by the same triangles; its
// seam is zipped instead, so it prepares, and the blends keep the copies.
TEST(OpenRestSeam, ASeamIsZippedAndTheBlendsKeepTheCopies) {
  const fs::path dir = scratchDir();
  const SurfaceMesh sphere = testing_surfaces::icosphere(2);
  const SurfaceMesh seamed = cutAlongTheEquator(sphere);
  ASSERT_GT(seamed.vertices.rows(), sphere.vertices.rows());
  // The example: the sphere sheared and squashed, copies moved alike.
  Eigen::Matrix3d map;
  map << 1.2, 0.4, 0.0, 0.0, 0.9, 0.3, 0.1, 0.0, 0.6;
  const SurfaceMesh sheared{seamed.vertices * map.transpose(), seamed.triangles};
  writeSurface((dir / "seamed.obj").string(), seamed);
  writeSurface((dir / "sheared.obj").string(), sheared);
  const RunResult r = tetblend({"prepare", (dir / "seamed.obj").string(),
                                (dir / "sheared.obj").string(), "-o", (dir / "s.tbm").string()},
                               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.err.find("seamed.obj: " + std::to_string(seamed.vertices.rows() - sphere.vertices.rows()) +
                 " vertices split along texture or normal seams are merged"),
      std::string::npos)
      << r.err;
  const std::vector<std::pair<std::string, const SurfaceMesh*>> cases = {{"0", &seamed},
                                                                         {"1", &sheared}};
  for (const auto& [weight, expected] : cases) {
    SCOPED_TRACE("weight " + weight);
    const fs::path out = dir / ("w" + weight + ".vtp");
    const RunResult blend =
        tetblend({"blend", (dir / "s.tbm").string(), "-w", weight, "-o", out.string()}, dir);
    ASSERT_EQ(blend.code, 0) << blend.err;
    const auto vtp = readVtp(out);
    ASSERT_EQ(vtp->GetNumberOfPoints(), expected->vertices.rows());
    EXPECT_LT(maxDistance(pointsOf(vtp), expected->vertices),
              kInterpolationRelTol * boundingBoxDiagonal(expected->vertices));
  }
}

// Two square sheets touching at a corner, each with its own copy of it
// (vertices 2 and 4), which part in the example: not a seam (no edge joins
// the copies' neighbours), and not rims to join (they part), so nothing is
// merged and no fill closes the sheets. Each face gets a tet of its own,
// and --strict refuses them with one line naming the vertices and the
// remedies that work.
TEST(OpenRestSeam, TouchingRimsThatPartAreNamed) {
  const fs::path dir = scratchDir();
  SurfaceMesh sheets;
  sheets.vertices.resize(8, 3);
  sheets.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,  //
      1, 1, 0, 2, 1, 0, 2, 2, 0, 1, 2, 0;
  sheets.triangles.resize(4, 3);
  sheets.triangles << 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7;
  SurfaceMesh apart = sheets;
  apart.vertices.bottomRows(4).col(0).array() += 0.5;
  writeSurface((dir / "sheets.obj").string(), sheets);
  writeSurface((dir / "apart.obj").string(), apart);
  const RunResult r = tetblend({"prepare", (dir / "sheets.obj").string(),
                                (dir / "apart.obj").string(), "-o", (dir / "s.tbm").string()},
                               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("instead, each of its 4 faces gets a tet of its own"), std::string::npos)
      << r.err;
  const std::vector<std::string> before = listDir(dir);
  const RunResult refused =
      tetblend({"prepare", (dir / "sheets.obj").string(), (dir / "apart.obj").string(), "-o",
                (dir / "strict.tbm").string(), "--strict"},
               dir);
  expectOneLineError(refused);
  EXPECT_NE(refused.err.find("sheets.obj: vertices 2 and 4 are at the same position where the "
                             "rims of its holes touch"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("--tetrise"), std::string::npos) << refused.err;
  EXPECT_EQ(listDir(dir), before);
}

TEST_F(OpenRest, ExampleThatFoldsTheRestsFillGetsAFillThatItDoesNotFold) {
  // Vertex 0 of the top ring pushed across the tube's axis: the rest's own
  // fill of the top hole folds over itself in this example (its tets were
  // excluded until the fill was chosen for the examples too). The fill of
  // the hole in this example's positions folds in neither, so every tet
  // embeds and no warning is printed.
  SurfaceMesh folded = readSurface(path("twist.obj"));
  const int v = tube_.vertex(8, 0);
  folded.vertices.row(v) << -0.8 * folded.vertices(v, 0), -0.8 * folded.vertices(v, 1),
      folded.vertices(v, 2);
  writeSurface(path("folded.obj"), folded);
  const fs::path model = dir_ / "folded.tbm";
  const RunResult r = tetblend(
      {"prepare", path("rest.obj"), path("folded.obj"), path("bend.obj"), "-o", model.string()},
      dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; 0 tets excluded)"), std::string::npos) << r.err;
  const fs::path out = dir_ / "folded_unit.vtu";
  ASSERT_EQ(tetblend({"blend", model.string(), "-w", "1,0", "-o", out.string()}, dir_).code, 0);
  EXPECT_LT(
      maxDistance(pointsOf(readVtp(fs::path(out).replace_extension(".vtp"))), folded.vertices),
      kInterpolationRelTol * boundingBoxDiagonal(folded.vertices));
}

}  // namespace
}  // namespace tetblend::apps_test
