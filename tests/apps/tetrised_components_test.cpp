// End to end: a rest with a closed body and an open flat sheet beside it (a
// cape, a hair card, a leaf): no fill closes the sheet, so its faces get a
// tet each, as with --tetrise, while the body is meshed with an interior;
// the two are joined into one model. Blends give the rest at zero weights
// and each example at unit weights, over every input vertex in the input's
// order. --strict refuses the sheet instead.

#include "posed_rest_fixture.h"
#include "test_surfaces.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

constexpr int kSheetCells = 6;  // the sheet: 6 × 6 squares, 72 faces

// A flat grid of kSheetCells² squares at height z, x in [-1.5, 1.5] and y
// in [-0.4, 0.4], faces up.
SurfaceMesh flatSheet(double z) {
  const int n = kSheetCells + 1;
  SurfaceMesh sheet{Vertices(n * n, 3), Triangles(2 * kSheetCells * kSheetCells, 3)};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      sheet.vertices.row(j * n + i) << -1.5 + 3.0 * i / kSheetCells, -0.4 + 0.8 * j / kSheetCells,
          z;
    }
  }
  int f = 0;
  for (int j = 0; j < kSheetCells; ++j) {
    for (int i = 0; i < kSheetCells; ++i) {
      const int a = j * n + i;
      sheet.triangles.row(f++) << a, a + 1, a + n + 1;
      sheet.triangles.row(f++) << a, a + n + 1, a + n;
    }
  }
  return sheet;
}

// A body (an ellipsoid 4 by 1 by 1) and a flat sheet above it, the sheet
// first: the model's rows (body surface first) then differ from the
// input's order.
class TetrisedComponents : public PosedRest {
 protected:
  void SetUp() override {
    PosedRest::SetUp();
    SurfaceMesh body = testing_surfaces::icosphere(3);
    body.vertices.col(0) *= 2.0;
    body.vertices.rightCols(2) *= 0.5;
    writePoses(testing_surfaces::join(flatSheet(0.8), body));
  }
};

TEST_F(TetrisedComponents, TheSheetGetsATetPerFaceAndTheBodyAnInterior) {
  const RunResult r = tetblend(prepareArgs("cape.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("rest.obj: 1 of its components (first: the one of face 0) cannot be filled "
                       "with tets on their own"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("each of their 72 faces gets a tet of its own"), std::string::npos) << r.err;
  const ModelData m = readModelFile(path("cape.tbm"));
  EXPECT_EQ(m.surfaceVertexCount, rest_.vertices.rows());
  EXPECT_EQ(m.inputVertexCount(), rest_.vertices.rows());
  EXPECT_TRUE(m.inputVertices(m.rest.vertices) == rest_.vertices);
  // The body's interior vertices and the sheet's 72 apexes come after the
  // surface: more than 72 rows means the body has an interior.
  EXPECT_GT(m.rest.vertices.rows(), rest_.vertices.rows() + 72);
  // Every tet positive in the rest and in each example.
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    EXPECT_GT(tetSignedVolume(m.rest.vertices, m.rest.tets.row(t)), 0.0) << "tet " << t;
    for (const Vertices& example : m.examples) {
      EXPECT_GT(tetSignedVolume(example, m.rest.tets.row(t)), 0.0) << "tet " << t;
    }
  }
  EXPECT_TRUE(m.excludedTets.empty());
}

TEST_F(TetrisedComponents, BlendsGiveTheRestAndEveryExample) {
  ASSERT_EQ(tetblend(prepareArgs("cape.tbm"), dir_).code, 0);
  expectTheKeysBack("cape.tbm");
}

// An example equal to the rest is warned about once, not once per part
// prepared on its own: the body stays still in it, but blending it moves
// nothing anywhere.
TEST_F(TetrisedComponents, AnExampleEqualToTheRestIsWarnedAboutOnce) {
  const RunResult r = tetblend(
      {"prepare", path("rest.obj"), path("twist.obj"), path("rest.obj"), "-o", path("same.tbm")},
      dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string warning = "every vertex equals the rest's";
  const std::size_t first = r.err.find(warning);
  ASSERT_NE(first, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(warning, first + 1), std::string::npos) << r.err;
}

// The sheet's corner is one of the body's vertices: the sheet's tets use the
// body's row there (the two stay one tet component), and the sheet's own
// copy of it is the one row in no tet.
TEST(TetrisedComponentsAttached, ASheetSharingAVertexUsesTheBodysRow) {
  const fs::path dir = scratchDir();
  SurfaceMesh body = testing_surfaces::icosphere(2);
  Eigen::Index top = 0;
  body.vertices.col(2).maxCoeff(&top);
  SurfaceMesh sheet = flatSheet(0.0);
  sheet.vertices.rowwise() += body.vertices.row(top) - sheet.vertices.row(0);
  // The body, then the sheet without its corner 0, which becomes `top`.
  const auto nb = static_cast<int>(body.vertices.rows());
  SurfaceMesh rest{Vertices(nb + sheet.vertices.rows() - 1, 3),
                   Triangles(body.triangles.rows() + sheet.triangles.rows(), 3)};
  rest.vertices << body.vertices, sheet.vertices.bottomRows(sheet.vertices.rows() - 1);
  for (Eigen::Index f = 0; f < sheet.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = sheet.triangles(f, c);
      sheet.triangles(f, c) = v == 0 ? static_cast<int>(top) : nb + v - 1;
    }
  }
  rest.triangles << body.triangles, sheet.triangles;
  writeSurface((dir / "rest.obj").string(), rest);
  const Eigen::Vector3d origin(-1.0, 0.0, 0.0), axis = Eigen::Vector3d::UnitX();
  const SurfaceMesh twist{twistAboutAxis(rest.vertices, origin, axis, 0.5 * kPi, 3.0),
                          rest.triangles};
  writeSurface((dir / "twist.obj").string(), twist);
  const std::string model = (dir / "attached.tbm").string();
  const RunResult r = tetblend(
      {"prepare", (dir / "rest.obj").string(), (dir / "twist.obj").string(), "-o", model}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const ModelData m = readModelFile(model);
  std::vector<char> used(static_cast<std::size_t>(m.rest.vertices.rows()), 0);
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) used[static_cast<std::size_t>(m.rest.tets(t, c))] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 1);
  EXPECT_TRUE(used[static_cast<std::size_t>(
      m.inputVertexRows.empty() ? top : m.inputVertexRows[static_cast<std::size_t>(top)])]);
  const std::string out = (dir / "one.vtp").string();
  ASSERT_EQ(tetblend({"blend", model, "-w", "1", "-o", out}, dir).code, 0);
  EXPECT_LT(maxDistance(pointsOf(readVtp(out)), twist.vertices),
            kPosedRestInterpolationRelTol * boundingBoxDiagonal(twist.vertices));
}

// The sheet alone with a face of zero area on its boundary: the corners of
// one boundary edge and a new vertex at its midpoint, which no other face
// uses. That face gets no tet, its vertex follows the examples linearly,
// and every input vertex comes back at the keys.
TEST_F(TetrisedComponents, AFaceOfZeroAreaGetsNoTet) {
  SurfaceMesh sheet = flatSheet(0.0);
  const Eigen::Index m = sheet.vertices.rows();
  sheet.vertices.conservativeResize(m + 1, 3);
  sheet.vertices.row(m) = 0.5 * (sheet.vertices.row(0) + sheet.vertices.row(1));
  sheet.triangles.conservativeResize(sheet.triangles.rows() + 1, 3);
  sheet.triangles.bottomRows(1) << 1, 0, static_cast<int>(m);
  writePoses(sheet);
  const RunResult r = tetblend(prepareArgs("flat.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("each of its 73 faces gets a tet of its own, as with --tetrise (1 face of "
                       "zero area or repeating another gets none)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(readModelFile(path("flat.tbm")).rest.tets.rows(), 72);
  expectTheKeysBack("flat.tbm");
}

TEST_F(TetrisedComponents, StrictRefusesTheSheet) {
  std::vector<std::string> args = prepareArgs("strict.tbm");
  args.push_back("--strict");
  const std::vector<std::string> before = listDir(dir_);
  const RunResult r = tetblend(args, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("rest.obj: a triangle filling one of its holes intersects face "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(listDir(dir_), before);
}

}  // namespace
}  // namespace tetblend::apps_test
