// End to end: an example that scales one part of the rest to a point, as
// game animations hide parts. No placement gives the tets on its faces a
// volume: prepare accepts the example with one warning that says so (not
// the advice of a finer mesh, which cannot help), and blends at the
// example's weights still reproduce it. Before, the blend at weight 1 was
// refused: a quality figure's polar decomposition of a nearly singular
// blended gradient threw.

#include "apps_test_support.h"
#include "test_surfaces.h"

namespace tetblend::apps_test {
namespace {

TEST(CollapsedPart, IsReportedAndBlendsStillReproduceTheExample) {
  const fs::path dir = scratchDir();
  makeSamples(dir);
  const SurfaceMesh bar = readSurface((dir / "bar_rest.obj").string());
  const SurfaceMesh twisted = readSurface((dir / "bar_twist4pi.obj").string());
  SurfaceMesh small = bar;
  small.vertices = small.vertices * 0.2;
  small.vertices.col(1).array() += 3.0;
  SurfaceMesh collapsed = small;
  collapsed.vertices.rowwise() = small.vertices.colwise().mean();
  const SurfaceMesh rest = testing_surfaces::join(bar, small);
  const SurfaceMesh example = testing_surfaces::join(twisted, collapsed);
  writeSurface((dir / "two_rest.obj").string(), rest);
  writeSurface((dir / "two_collapsed.obj").string(), example);

  const fs::path model = dir / "m.tbm";
  const RunResult prepared = tetblend({"prepare", (dir / "two_rest.obj").string(),
                                       (dir / "two_collapsed.obj").string(), "-o", model.string()},
                                      dir);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("two_collapsed.obj: "), std::string::npos) << prepared.err;
  EXPECT_NE(prepared.err.find("its surface collapses " + std::to_string(small.triangles.rows()) +
                              " faces to (almost) zero area"),
            std::string::npos)
      << prepared.err;
  EXPECT_EQ(prepared.err.find("--max-volume"), std::string::npos) << prepared.err;

  for (const char* weight : {"0", "1"}) {
    const fs::path out = dir / (std::string("w") + weight + ".vtu");
    const RunResult blended =
        tetblend({"blend", model.string(), "-w", weight, "-o", out.string()}, dir);
    ASSERT_EQ(blended.code, 0) << blended.err;
    const fs::path surface = fs::path(out).replace_extension(".vtp");
    const Vertices got = pointsOf(readVtp(surface).GetPointer());
    const Vertices& want = std::string(weight) == "0" ? rest.vertices : example.vertices;
    EXPECT_LT(maxDistance(got, want), kInterpolationTolerance) << "weight " << weight;
  }
}

}  // namespace
}  // namespace tetblend::apps_test
