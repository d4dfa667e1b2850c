// End to end: a rest and an example with faces of zero area (T-junctions
// closed by caps, as scanners and CAD exporters leave them) are prepared:
// the caps are re-split with a neighbour for meshing only, and blends keep
// the input's faces and reproduce the rest and the example at every vertex.

#include "apps_test_support.h"
#include "test_surfaces.h"

namespace tetblend::apps_test {
namespace {

// The bar with a cap on faces 0, 50 and 100 (three points on one edge of
// face 100): the same faces in the rest and in the example, the points at
// the same fractions of the edge in each.
SurfaceMesh withCaps(SurfaceMesh mesh) {
  testing_surfaces::insertCap(mesh, 0, 0, 1);
  testing_surfaces::insertCap(mesh, 50, 1, 1);
  testing_surfaces::insertCap(mesh, 100, 2, 3);
  return mesh;
}

// Writes rest.obj and twist.obj into `dir` and prepares them into m.tbm.
RunResult writeAndPrepare(const fs::path& dir, const SurfaceMesh& rest, const SurfaceMesh& twist) {
  writeSurface((dir / "rest.obj").string(), rest);
  writeSurface((dir / "twist.obj").string(), twist);
  return tetblend({"prepare", (dir / "rest.obj").string(), (dir / "twist.obj").string(), "-o",
                   (dir / "m.tbm").string()},
                  dir);
}

// Blends of dir/m.tbm at weights 0 and 1 give `rest` and `example` at every
// vertex, with every face.
void expectTheKeysBack(const fs::path& dir, const SurfaceMesh& rest, const SurfaceMesh& example) {
  for (const auto& [w, expected] : {std::pair{"0", &rest}, std::pair{"1", &example}}) {
    const fs::path out = dir / (std::string("w") + w + ".vtp");
    const RunResult r =
        tetblend({"blend", (dir / "m.tbm").string(), "-w", w, "-o", out.string(), "--quiet"}, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    const auto surface = readVtp(out);
    EXPECT_LT(maxDistance(pointsOf(surface), expected->vertices), kInterpolationTolerance) << w;
    EXPECT_EQ(surface->GetNumberOfCells(), expected->triangles.rows()) << w;
  }
}

TEST(DegenerateFaces, CappedRestAndExamplePrepareAndBlendExactly) {
  const fs::path dir = scratchDir();
  makeSamples(dir);
  const SurfaceMesh rest = withCaps(readSurface((dir / "bar_rest.obj").string()));
  const SurfaceMesh twist = withCaps(readSurface((dir / "bar_twist4pi.obj").string()));
  const RunResult prepared = writeAndPrepare(dir, rest, twist);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("5 faces of (almost) zero area are re-split with a neighbour"),
            std::string::npos)
      << prepared.err;
  expectTheKeysBack(dir, rest, twist);
}

// Vertices 10 and 40 of the bar each split in place (a zero-length edge and
// two faces of zero area each, as an exporter's collapsed edge leaves
// them), the same in the rest and the twisted example: the ends are merged
// for meshing, and every blended surface has all the input's vertices, the
// copies where their originals are.
TEST(DegenerateFaces, ZeroLengthEdgesAreMergedForMeshing) {
  const fs::path dir = scratchDir();
  makeSamples(dir);
  SurfaceMesh rest = readSurface((dir / "bar_rest.obj").string());
  SurfaceMesh twist = readSurface((dir / "bar_twist4pi.obj").string());
  for (SurfaceMesh* mesh : {&rest, &twist}) {
    testing_surfaces::splitVertexInPlace(*mesh, 10, 2);
    testing_surfaces::splitVertexInPlace(*mesh, 40, 3);
  }
  ASSERT_TRUE(rest.triangles == twist.triangles);
  const RunResult prepared = writeAndPrepare(dir, rest, twist);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("2 vertices are at the same position as a neighbour in the rest and "
                              "every example, joined by an edge of zero length (first: vertex " +
                              std::to_string(rest.vertices.rows() - 2) + " at vertex 10)"),
            std::string::npos)
      << prepared.err;
  EXPECT_NE(prepared.err.find("4 faces repeat a vertex"), std::string::npos) << prepared.err;
  expectTheKeysBack(dir, rest, twist);
  // Vertex 40's copy leaves it in the example: that edge has length there,
  // so it is not merged, and the rest's two faces of zero area on it keep
  // the bar from being meshed with an interior. --strict refuses it with
  // one line; without, every other face gets a tet of its own and the keys
  // still come back.
  twist.vertices.bottomRows(1).array() += 0.01;
  writeSurface((dir / "twist.obj").string(), twist);
  const std::vector<std::string> args = {"prepare", (dir / "rest.obj").string(),
                                         (dir / "twist.obj").string(), "-o",
                                         (dir / "m.tbm").string()};
  std::vector<std::string> strict = args;
  strict.push_back("--strict");
  strict.push_back("--quiet");
  const RunResult refused = tetblend(strict, dir);
  expectOneLineError(refused);
  EXPECT_NE(refused.err.find("has area 0"), std::string::npos) << refused.err;
  const RunResult parted = tetblend(args, dir);
  ASSERT_EQ(parted.code, 0) << parted.err;
  EXPECT_NE(parted.err.find("as with --tetrise (2 faces of zero area or repeating another get "
                            "none)"),
            std::string::npos)
      << parted.err;
  expectTheKeysBack(dir, rest, twist);
}

}  // namespace
}  // namespace tetblend::apps_test
