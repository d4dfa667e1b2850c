// End to end: an example that scales one part of the rest to a point, as
// game animations hide parts. No placement gives the tets on its faces a
// volume: prepare accepts the example with one warning that says so (not
// the advice of a finer mesh, which cannot help), and blends at the
// example's weights still reproduce it. Before, the blend at weight 1 was
// refused: a quality figure's polar decomposition of a nearly singular
// blended gradient threw. A rest that hides a part is refused, naming a
// frame that can be the rest.

#include <algorithm>

#include "apps_test_support.h"
#include "test_surfaces.h"

namespace tetblend::apps_test {
namespace {

// The samples' bar beside a small copy of it (two_rest.obj), and the bar
// twisted by 4π beside the copy scaled to its centre (two_collapsed.obj),
// written into `dir`.
struct TwoParts {
  SurfaceMesh rest;
  SurfaceMesh collapsed;
  Eigen::Index smallFaces = 0;
};

TwoParts writeTwoParts(const fs::path& dir) {
  makeSamples(dir);
  const SurfaceMesh bar = readSurface((dir / "bar_rest.obj").string());
  const SurfaceMesh twisted = readSurface((dir / "bar_twist4pi.obj").string());
  SurfaceMesh small = bar;
  small.vertices = small.vertices * 0.2;
  small.vertices.col(1).array() += 3.0;
  SurfaceMesh collapsed = small;
  collapsed.vertices.rowwise() = small.vertices.colwise().mean();
  TwoParts parts{testing_surfaces::join(bar, small), testing_surfaces::join(twisted, collapsed),
                 small.triangles.rows()};
  writeSurface((dir / "two_rest.obj").string(), parts.rest);
  writeSurface((dir / "two_collapsed.obj").string(), parts.collapsed);
  return parts;
}

TEST(CollapsedPart, IsReportedAndBlendsStillReproduceTheExample) {
  const fs::path dir = scratchDir();
  const TwoParts parts = writeTwoParts(dir);
  const SurfaceMesh& rest = parts.rest;
  const SurfaceMesh& example = parts.collapsed;

  const fs::path model = dir / "m.tbm";
  const RunResult prepared = tetblend({"prepare", (dir / "two_rest.obj").string(),
                                       (dir / "two_collapsed.obj").string(), "-o", model.string()},
                                      dir);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("two_collapsed.obj: "), std::string::npos) << prepared.err;
  EXPECT_NE(prepared.err.find("its surface collapses " + std::to_string(parts.smallFaces) +
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

// The same pair the other way round: a rest that hides a part (an
// animation's first frame may). No tet can fill the collapsed faces, and
// removing them (as the degenerate-face advice says for a single face)
// would break the examples' correspondence: prepare refuses with one line
// that names a frame to use as the rest instead, and writes no model.
TEST(CollapsedPart, InTheRestIsRefusedNamingAFrameThatCanBeTheRest) {
  const fs::path dir = scratchDir();
  const TwoParts parts = writeTwoParts(dir);
  const fs::path model = dir / "m.tbm";
  const std::string example = (dir / "two_rest.obj").string();
  const RunResult prepared = tetblend(
      {"prepare", (dir / "two_collapsed.obj").string(), example, "-o", model.string()}, dir);
  EXPECT_NE(prepared.code, 0);
  EXPECT_EQ(std::count(prepared.err.begin(), prepared.err.end(), '\n'), 1) << prepared.err;
  EXPECT_NE(prepared.err.find(std::to_string(parts.smallFaces) +
                              " faces have (almost) zero area in the rest but not in " + example),
            std::string::npos)
      << prepared.err;
  EXPECT_NE(prepared.err.find(
                "prepare with a frame where the part has its size as the rest, e.g. " + example),
            std::string::npos)
      << prepared.err;
  EXPECT_EQ(prepared.err.find("MeshLab"), std::string::npos) << prepared.err;
  EXPECT_FALSE(fs::exists(model));
}

}  // namespace
}  // namespace tetblend::apps_test
