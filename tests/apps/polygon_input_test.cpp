// End to end: a rest and an example written with quads (as an animation
// exported from Blender without "Triangulate Faces") are prepared; every
// reader splits each quad into the same two triangles, so the example stays
// compatible, and blends reproduce the rest and the example at the surface.
// An example triangulated by its own shape (other quad diagonals) is the same
// surface and prepares with a warning. A flat-shaded export (every quad with
// vertices of its own, so the surface is cut along every edge) prepares with
// its seams zipped, and the blends keep its vertices.

#include <array>
#include <cmath>
#include <fstream>
#include <string>

#include "apps_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_io.h"

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

// The flat-shaded bar's vertices, in its file's order.
Vertices flatShadedPositions(const Vertices& positions) {
  const auto quads = quadBarFaces();
  Vertices result(4 * static_cast<Eigen::Index>(quads.size()), 3);
  for (std::size_t i = 0; i < quads.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      result.row(4 * static_cast<Eigen::Index>(i) + c) = positions.row(quads[i][c] - 1);
    }
  }
  return result;
}

// The bar flat-shaded, as exporters write a mesh with per-face normals:
// quad q has vertices 4q..4q+3 of its own (copies of the shared corners),
// written with one "f" line each.
std::string flatShadedBarObj(const Vertices& positions) {
  std::string out = objVertices(flatShadedPositions(positions));
  for (int first = 1; first <= 4 * static_cast<int>(quadBarFaces().size()); first += 4) {
    out += "f " + std::to_string(first) + ' ' + std::to_string(first + 1) + ' ' +
           std::to_string(first + 2) + ' ' + std::to_string(first + 3) + '\n';
  }
  return out;
}

TEST(PolygonInput, FlatShadedRestAndExamplePrepareWithTheirSeamsZipped) {
  const fs::path dir = scratchDir();
  const Vertices rest = quadBarPositions();
  const Vertices twisted =
      twistAboutAxis(rest, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 1.5 * kPi, 4.0);
  std::ofstream(dir / "rest.obj") << flatShadedBarObj(rest);
  std::ofstream(dir / "twist.obj") << flatShadedBarObj(twisted);
  const fs::path model = dir / "bar.tbm";
  const RunResult r = tetblend(
      {"prepare", (dir / "rest.obj").string(), (dir / "twist.obj").string(), "-o", model.string()},
      dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const Eigen::Index inputVertices = 4 * (4 * kLayers + 2);
  const Eigen::Index corners = rest.rows();
  EXPECT_NE(r.err.find("rest.obj: " + std::to_string(inputVertices - corners) +
                       " vertices split along texture or normal seams are merged"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const std::vector<std::pair<std::string, Vertices>> cases = {{"0", flatShadedPositions(rest)},
                                                               {"1", flatShadedPositions(twisted)}};
  for (const auto& [weight, expected] : cases) {
    SCOPED_TRACE("weight " + weight);
    const fs::path out = dir / ("w" + weight + ".vtu");
    const RunResult blend = tetblend(
        {"blend", model.string(), "-w", weight, "-o", out.string(), "--surface-format", "obj"},
        dir);
    ASSERT_EQ(blend.code, 0) << blend.err;
    // The tets share the zipped corners; the surfaces keep the input's copies.
    const auto vtp = readVtp(fs::path(out).replace_extension(".vtp"));
    EXPECT_EQ(vtp->GetNumberOfPolys(), 2 * (4 * kLayers + 2));
    ASSERT_EQ(vtp->GetNumberOfPoints(), inputVertices);
    EXPECT_LT(maxDistance(pointsOf(vtp), expected),
              kInterpolationRelTol * boundingBoxDiagonal(expected));
    const SurfaceMesh obj = readSurface(fs::path(out).replace_extension(".obj").string());
    ASSERT_EQ(obj.vertices.rows(), inputVertices);
    EXPECT_LT(maxDistance(obj.vertices, expected),
              kInterpolationRelTol * boundingBoxDiagonal(expected));
  }
  const RunResult inspect = tetblend({"inspect", model.string()}, dir);
  ASSERT_EQ(inspect.code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find("input surface: " + std::to_string(inputVertices) + " vertices"),
            std::string::npos)
      << inspect.out;
}

// An example in which one copy of a seam vertex moves away from the others:
// its surface is cut open there, so it cannot share the rest's tets.
TEST(PolygonInput, ExampleWhoseSeamOpensIsRefusedInOneLine) {
  const fs::path dir = scratchDir();
  const Vertices rest = quadBarPositions();
  std::ofstream(dir / "rest.obj") << flatShadedBarObj(rest);
  std::string opened = flatShadedBarObj(rest);
  opened.replace(0, opened.find('\n'), "v 5 5 5");  // input vertex 0 alone
  std::ofstream(dir / "opened.obj") << opened;
  const RunResult r = tetblend({"prepare", (dir / "rest.obj").string(),
                                (dir / "opened.obj").string(), "-o", (dir / "m.tbm").string()},
                               dir);
  EXPECT_NE(r.code, 0);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("opened.obj: vertices 0 and "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a seam must stay closed in every example"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "m.tbm"));
}

}  // namespace
}  // namespace tetblend::apps_test
