// End to end: a rest and an example written with quads (as an animation
// exported from Blender without "Triangulate Faces") are prepared; every
// reader splits each quad into the same two triangles, so the example stays
// compatible, and blends reproduce the rest and the example at the surface.
// An example triangulated by its own shape (other quad diagonals) is the same
// surface and prepares with a warning.

#include <array>
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
// all facing outwards, as 1-based corner lists.
std::vector<std::array<int, 4>> quadBarFaces() {
  auto at = [](int ring, int corner) { return 4 * ring + corner % 4 + 1; };
  std::vector<std::array<int, 4>> quads;
  for (int ring = 0; ring < kLayers; ++ring) {
    for (int i = 0; i < 4; ++i) {
      quads.push_back({at(ring, i), at(ring, i + 1), at(ring + 1, i + 1), at(ring + 1, i)});
    }
  }
  quads.push_back({at(0, 3), at(0, 2), at(0, 1), at(0, 0)});
  quads.push_back({at(kLayers, 0), at(kLayers, 1), at(kLayers, 2), at(kLayers, 3)});
  return quads;
}

std::string objVertices(const Vertices& positions) {
  std::ostringstream out;
  out.precision(17);
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    out << "v " << positions(v, 0) << ' ' << positions(v, 1) << ' ' << positions(v, 2) << '\n';
  }
  return out.str();
}

// The bar as OBJ with "f a b c d" lines.
std::string quadBarObj(const Vertices& positions) {
  std::string out = objVertices(positions);
  for (const auto& q : quadBarFaces()) {
    out += "f " + std::to_string(q[0]) + ' ' + std::to_string(q[1]) + ' ' + std::to_string(q[2]) +
           ' ' + std::to_string(q[3]) + '\n';
  }
  return out;
}

// The bar as OBJ with each quad split along its shorter diagonal in
// `positions`, as an exporter that triangulates by shape writes it; counts
// in `otherDiagonal` the quads not split along c0-c2 (the readers' fan).
std::string shapeTriangulatedBarObj(const Vertices& positions, int& otherDiagonal) {
  std::string out = objVertices(positions);
  otherDiagonal = 0;
  auto distance = [&](int a, int b) {
    return (positions.row(a - 1) - positions.row(b - 1)).norm();
  };
  auto triangle = [&](int a, int b, int c) {
    out += "f " + std::to_string(a) + ' ' + std::to_string(b) + ' ' + std::to_string(c) + '\n';
  };
  for (const auto& q : quadBarFaces()) {
    if (distance(q[0], q[2]) <= distance(q[1], q[3])) {
      triangle(q[0], q[1], q[2]);
      triangle(q[0], q[2], q[3]);
    } else {
      ++otherDiagonal;
      triangle(q[0], q[1], q[3]);
      triangle(q[1], q[2], q[3]);
    }
  }
  return out;
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

// The rest written with quads, the example triangulated by its own shape:
// some quads are split along the other diagonal. The example is the same
// surface, so it prepares with one warning line naming the count, and the
// blends reproduce it.
TEST(PolygonInput, ExampleTriangulatedByItsShapeIsAcceptedWithAWarning) {
  const fs::path dir = scratchDir();
  const Vertices rest = quadBarPositions();
  const Vertices twisted =
      twistAboutAxis(rest, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 1.5 * kPi, 4.0);
  int otherDiagonal = 0;
  std::ofstream(dir / "rest.obj") << quadBarObj(rest);
  std::ofstream(dir / "twist.obj") << shapeTriangulatedBarObj(twisted, otherDiagonal);
  ASSERT_GT(otherDiagonal, 0);
  const fs::path model = dir / "bar.tbm";
  const RunResult r = tetblend(
      {"prepare", (dir / "rest.obj").string(), (dir / "twist.obj").string(), "-o", model.string()},
      dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("twist.obj: " + std::to_string(otherDiagonal) +
                       " quads are split along the other diagonal than in the rest"),
            std::string::npos)
      << r.err;
  const fs::path out = dir / "w1.vtp";
  const RunResult blend = tetblend({"blend", model.string(), "-w", "1", "-o", out.string()}, dir);
  ASSERT_EQ(blend.code, 0) << blend.err;
  EXPECT_LT(maxDistance(pointsOf(readVtp(out)), twisted),
            kInterpolationRelTol * boundingBoxDiagonal(twisted));
}

}  // namespace
}  // namespace tetblend::apps_test
