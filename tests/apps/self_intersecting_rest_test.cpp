// End to end: a rest whose own surface intersects itself slightly (CGAL's
// cow, a scan whose folds cross at 101 face pairs), or whose faces point
// inwards, is prepared: the tets are made on a separated, outward copy and
// the user's rest is embedded in them like a pose. Blends still give the
// user's rest at zero weights and each example at unit weights; --strict
// and overlaps too deep to be slight are refused with one line.

#include <filesystem>

#include "apps_test_support.h"
#include "cgal_meshes.h"
#include "test_surfaces.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

// The promise: the rest and every example to 1e-9 of the
// bounding-box diagonal (measured: 3e-12 on this 13 k-tet mesh).
constexpr double kInterpolationRelTol = 1e-9;

std::size_t countOf(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + 1)) {
    ++count;
  }
  return count;
}

class SelfIntersectingRest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string tarball = testing_cgal::cgalDataTarball();
    if (tarball.empty()) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
    dir_ = scratchDir();
    const fs::path meshes = testing_cgal::extractCgalMeshes(tarball, {"cow.off"}, "cowrest");
    ASSERT_FALSE(meshes.empty());
    rest_ = readSurface((meshes / "cow.off").string());
    fs::remove_all(meshes.parent_path().parent_path());
    ASSERT_GT(findSelfIntersections(rest_.vertices, rest_.triangles, 1).pairCount, 0u);
    // Two poses: a 60° twist and a 40° bend along the body (x).
    const Eigen::Vector3d lo = rest_.vertices.colwise().minCoeff().transpose();
    const double length = rest_.vertices.col(0).maxCoeff() - lo.x();
    const Eigen::Vector3d origin(lo.x(), rest_.vertices.col(1).mean(),
                                 rest_.vertices.col(2).mean());
    SurfaceMesh twist = rest_, bend = rest_;
    twist.vertices = twistAboutAxis(rest_.vertices, origin, Eigen::Vector3d::UnitX(),
                                    60.0 * kPi / 180.0, length);
    bend.vertices = bendAboutAxis(rest_.vertices, origin, Eigen::Vector3d::UnitX(),
                                  Eigen::Vector3d::UnitY(), 40.0 * kPi / 180.0, length);
    writeSurface((dir_ / "cow_rest.obj").string(), rest_);
    writeSurface((dir_ / "cow_twist.obj").string(), twist);
    writeSurface((dir_ / "cow_bend.obj").string(), bend);
  }
  std::vector<std::string> prepareArgs(const std::string& rest, const fs::path& model) const {
    return {"prepare",
            (dir_ / rest).string(),
            (dir_ / "cow_twist.obj").string(),
            (dir_ / "cow_bend.obj").string(),
            "-o",
            model.string()};
  }
  fs::path dir_;
  SurfaceMesh rest_;
};

TEST_F(SelfIntersectingRest, PreparesWithOneWarningForTheRest) {
  const fs::path model = dir_ / "cow.tbm";
  const RunResult r = tetblend(prepareArgs("cow_rest.obj", model), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string restLine = "tetblend: warning: " + (dir_ / "cow_rest.obj").string() + ": ";
  EXPECT_EQ(countOf(r.err, restLine), 1u) << r.err;
  EXPECT_NE(r.err.find(restLine + "its surface intersects itself at 101 face pairs"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("the rest is embedded in them"), std::string::npos) << r.err;

  // The model holds the user's rest surface bit for bit; every tet it
  // stitches is positively oriented in it, and the tets the rest inverts are
  // among the excluded.
  const ModelData m = readModelFile(model.string());
  EXPECT_TRUE(m.rest.vertices.topRows(rest_.vertices.rows()) == rest_.vertices);
  EXPECT_TRUE(m.surfaceTriangles == rest_.triangles);
  std::vector<char> excluded(static_cast<std::size_t>(m.rest.tets.rows()), 0);
  for (int t : m.excludedTets) excluded[static_cast<std::size_t>(t)] = 1;
  int invertedInRest = 0;
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    if (tetSignedVolume(m.rest.vertices, m.rest.tets.row(t)) > 0.0) continue;
    ++invertedInRest;
    EXPECT_TRUE(excluded[static_cast<std::size_t>(t)]) << "tet " << t;
  }
  EXPECT_GT(invertedInRest, 0);
  const RunResult inspect = tetblend({"inspect", model.string()}, dir_);
  ASSERT_EQ(inspect.code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find("excluded from the stitch: "), std::string::npos) << inspect.out;
}

TEST_F(SelfIntersectingRest, BlendsGiveTheUsersRestAndEveryExample) {
  const fs::path model = dir_ / "cow.tbm";
  ASSERT_EQ(tetblend(prepareArgs("cow_rest.obj", model), dir_).code, 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,0", "cow_rest.obj"}, {"1,0", "cow_twist.obj"}, {"0,1", "cow_bend.obj"}};
  for (const std::string method : {"kaji", "liebodies", "dq", "linear", "vertex-linear"}) {
    for (const auto& [weights, expected] : cases) {
      SCOPED_TRACE(method + " at " + weights);
      const fs::path out =
          dir_ / (method + "_" + weights.substr(0, 1) + weights.substr(2) + ".vtu");
      const RunResult r = tetblend(
          {"blend", model.string(), "-w", weights, "--method", method, "-o", out.string()}, dir_);
      ASSERT_EQ(r.code, 0) << r.err;
      const SurfaceMesh target = readSurface((dir_ / expected).string());
      const Vertices surface = pointsOf(readVtp(fs::path(out).replace_extension(".vtp")));
      EXPECT_LT(maxDistance(surface, target.vertices),
                kInterpolationRelTol * boundingBoxDiagonal(target.vertices));
    }
  }
}

TEST_F(SelfIntersectingRest, StrictRefusesItWithOneLineAndNoFile) {
  std::vector<std::string> args = prepareArgs("cow_rest.obj", dir_ / "strict.tbm");
  args.push_back("--strict");
  const std::vector<std::string> before = listDir(dir_);
  const RunResult r = tetblend(args, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("cow_rest.obj: faces "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("intersect"), std::string::npos) << r.err;
  EXPECT_EQ(listDir(dir_), before);
}

// The user's faces all reversed: meshed outward with a warning; the model
// and the blended surfaces keep the user's faces.
TEST_F(SelfIntersectingRest, InwardFacesAreMeshedReversedAndKept) {
  SurfaceMesh inward = testing_surfaces::reversed(rest_);
  writeSurface((dir_ / "inward.obj").string(), inward);
  for (const char* pose : {"cow_twist.obj", "cow_bend.obj"}) {
    SurfaceMesh posed = readSurface((dir_ / pose).string());
    posed.triangles = inward.triangles;
    writeSurface((dir_ / (std::string("inward_") + pose)).string(), posed);
  }
  const fs::path model = dir_ / "inward.tbm";
  const RunResult r =
      tetblend({"prepare", (dir_ / "inward.obj").string(), (dir_ / "inward_cow_twist.obj").string(),
                (dir_ / "inward_cow_bend.obj").string(), "-o", model.string()},
               dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("inward.obj: 5804 faces point inwards or against their neighbours"),
            std::string::npos)
      << r.err;
  const fs::path out = dir_ / "inward_zero.vtu";
  ASSERT_EQ(tetblend({"blend", model.string(), "-w", "0,0", "-o", out.string()}, dir_).code, 0);
  const auto surface = readVtp(fs::path(out).replace_extension(".vtp"));
  EXPECT_LT(maxDistance(pointsOf(surface), rest_.vertices),
            kInterpolationRelTol * boundingBoxDiagonal(rest_.vertices));
  ASSERT_EQ(surface->GetNumberOfPolys(), inward.triangles.rows());
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  surface->GetPolys()->InitTraversal();
  for (Eigen::Index f = 0; surface->GetPolys()->GetNextCell(n, ids); ++f) {
    ASSERT_EQ(n, 3);
    EXPECT_EQ(ids[1], inward.triangles(f, 1)) << "face " << f;
  }
}

// A sphere whose cap beyond x = 0.2 is pushed 1.6 radii along -x, through
// its own far side: an overlap far beyond a slight contact. No interior
// fits, so each face gets a tet of its own, with one note line saying why;
// --strict refuses it with one line, quickly, and no file. (Two overlapping
// spheres are two components, meshed each on its own:
// overlapping_components_test.cpp.)
TEST(SelfIntersectingRestRefused, DeepOverlapFallsBackToATetPerFace) {
  const fs::path dir = scratchDir();
  SurfaceMesh pushed = testing_surfaces::icosphere(3);
  for (Eigen::Index v = 0; v < pushed.vertices.rows(); ++v) {
    if (pushed.vertices(v, 0) > 0.2) pushed.vertices(v, 0) -= 1.6;
  }
  ASSERT_GT(findSelfIntersections(pushed.vertices, pushed.triangles, 1).pairCount, 0u);
  writeSurface((dir / "pushed.obj").string(), pushed);
  const RunResult r = tetblend({"prepare", (dir / "pushed.obj").string(),
                                (dir / "pushed.obj").string(), "-o", (dir / "s.tbm").string()},
                               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("too deeply to separate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("instead, each of its " + std::to_string(pushed.triangles.rows()) +
                       " faces gets a tet of its own"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(readModelFile((dir / "s.tbm").string()).rest.tets.rows(), pushed.triangles.rows());

  const std::vector<std::string> before = listDir(dir);
  const RunResult refused =
      tetblend({"prepare", (dir / "pushed.obj").string(), (dir / "pushed.obj").string(), "-o",
                (dir / "strict.tbm").string(), "--strict"},
               dir);
  expectOneLineError(refused);
  EXPECT_NE(refused.err.find("pushed.obj: faces "), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("intersect"), std::string::npos) << refused.err;
  EXPECT_EQ(listDir(dir), before);
}

// The same pushed sphere as the rest of two examples: itself stretched (it
// intersects itself too) and the round sphere twisted by 90°. The tets are
// made on the one that bounds a solid and the rest is embedded in them:
// an interior, not a tet per face, and still the rest and each example at
// the keys; the rest's inverted tets are excluded.
TEST(SelfIntersectingRestRefused, DeepOverlapIsMeshedOnACleanExample) {
  const fs::path dir = scratchDir();
  const SurfaceMesh round = testing_surfaces::icosphere(3);
  SurfaceMesh pushedCap = round;
  for (Eigen::Index v = 0; v < pushedCap.vertices.rows(); ++v) {
    if (pushedCap.vertices(v, 0) > 0.2) pushedCap.vertices(v, 0) -= 1.6;
  }
  const SurfaceMesh& pushed = pushedCap;
  const SurfaceMesh stretched{pushed.vertices * Eigen::Vector3d(1.0, 1.0, 1.5).asDiagonal(),
                              pushed.triangles};
  const SurfaceMesh twisted{twistAboutAxis(round.vertices, Eigen::Vector3d(0, 0, -1),
                                           Eigen::Vector3d::UnitZ(), 0.5 * kPi, 2.0),
                            round.triangles};
  for (const auto& [name, mesh] :
       {std::pair{"pushed.obj", &pushed}, std::pair{"stretched.obj", &stretched},
        std::pair{"twisted.obj", &twisted}}) {
    writeSurface((dir / name).string(), *mesh);
  }
  const std::string model = (dir / "m.tbm").string();
  const RunResult r =
      tetblend({"prepare", (dir / "pushed.obj").string(), (dir / "stretched.obj").string(),
                (dir / "twisted.obj").string(), "-o", model},
               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("too deeply to separate; the tets were made on the surface of " +
                       (dir / "twisted.obj").string()),
            std::string::npos)
      << r.err;
  const ModelData m = readModelFile(model);
  EXPECT_GT(m.rest.vertices.rows(), pushed.vertices.rows());  // an interior
  EXPECT_FALSE(m.excludedTets.empty());
  for (const auto& [w, expected] :
       {std::pair{"0,0", &pushed}, std::pair{"1,0", &stretched}, std::pair{"0,1", &twisted}}) {
    const std::string out = (dir / "key.vtp").string();
    ASSERT_EQ(tetblend({"blend", model, "-w", w, "-o", out, "--quiet"}, dir).code, 0) << w;
    EXPECT_LT(maxDistance(pointsOf(readVtp(out)), expected->vertices),
              kInterpolationRelTol * boundingBoxDiagonal(pushed.vertices))
        << w;
  }
}

}  // namespace
}  // namespace tetblend::apps_test
