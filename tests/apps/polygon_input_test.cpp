// End to end: a rest and an example written with quads (as an animation
// exported from Blender without "Triangulate Faces") are prepared; every
// reader splits each quad into the same two triangles, so the example stays
// compatible, and blends reproduce the rest and the example at the surface.

#include <cmath>
#include <fstream>
#include <string>

#include "apps_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend::apps_test {
namespace {

// Unit weights reproduce the example at the surface to 1e-9 of the
// bounding-box diagonal (issue 10's promise; the stitch's round-off on this
// small bar is ~1e-13 of its size).
constexpr double kInterpolationRelTol = 1e-9;
constexpr int kLayers = 12;  // square rings along the bar: 4 × 12 side quads

// A square bar (section 1 × 1, length 4 along z) made of quads: kLayers + 1
// square rings, four quads between neighbouring rings and one quad per end,
// all facing outwards. Written as OBJ with 1-based "f a b c d" lines.
std::string quadBarObj(const Vertices& positions) {
  std::ostringstream out;
  out.precision(17);
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    out << "v " << positions(v, 0) << ' ' << positions(v, 1) << ' ' << positions(v, 2) << '\n';
  }
  auto at = [](int ring, int corner) { return 4 * ring + corner % 4 + 1; };
  for (int ring = 0; ring < kLayers; ++ring) {
    for (int i = 0; i < 4; ++i) {
      out << "f " << at(ring, i) << ' ' << at(ring, i + 1) << ' ' << at(ring + 1, i + 1) << ' '
          << at(ring + 1, i) << '\n';
    }
  }
  out << "f " << at(0, 3) << ' ' << at(0, 2) << ' ' << at(0, 1) << ' ' << at(0, 0) << '\n';
  out << "f " << at(kLayers, 0) << ' ' << at(kLayers, 1) << ' ' << at(kLayers, 2) << ' '
      << at(kLayers, 3) << '\n';
  return out.str();
}

Vertices quadBarPositions() {
  Vertices positions(4 * (kLayers + 1), 3);
  for (int ring = 0; ring <= kLayers; ++ring) {
    for (int i = 0; i < 4; ++i) {
      const double angle = 0.25 * kPi + 0.5 * kPi * i;  // counter-clockwise seen from +z
      positions.row(4 * ring + i) << std::sqrt(0.5) * std::cos(angle),
          std::sqrt(0.5) * std::sin(angle), 4.0 * ring / kLayers;
    }
  }
  return positions;
}

TEST(PolygonInput, QuadRestAndQuadExamplePrepareAndBlendsReproduceThem) {
  const fs::path dir = scratchDir();
  const Vertices rest = quadBarPositions();
  const Vertices twisted =
      twistAboutAxis(rest, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 1.5 * kPi, 4.0);
  std::ofstream(dir / "rest.obj") << quadBarObj(rest);
  std::ofstream(dir / "twist.obj") << quadBarObj(twisted);
  const fs::path model = dir / "bar.tbm";
  const RunResult r = tetblend(
      {"prepare", (dir / "rest.obj").string(), (dir / "twist.obj").string(), "-o", model.string()},
      dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const std::vector<std::pair<std::string, const Vertices*>> cases = {{"0", &rest},
                                                                      {"1", &twisted}};
  for (const auto& [weight, expected] : cases) {
    SCOPED_TRACE("weight " + weight);
    const fs::path out = dir / ("w" + weight + ".vtp");
    const RunResult blend =
        tetblend({"blend", model.string(), "-w", weight, "-o", out.string()}, dir);
    ASSERT_EQ(blend.code, 0) << blend.err;
    const auto vtp = readVtp(out);
    EXPECT_EQ(vtp->GetNumberOfPolys(), 2 * (4 * kLayers + 2));  // two triangles per quad
    EXPECT_LT(maxDistance(pointsOf(vtp), *expected),
              kInterpolationRelTol * boundingBoxDiagonal(*expected));
  }
}

}  // namespace
}  // namespace tetblend::apps_test
