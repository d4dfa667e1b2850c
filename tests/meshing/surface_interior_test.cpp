// SurfaceInterior (meshing/src/surface_interior.h): whether a segment or a
// triangle between surface vertices lies inside the solid a clean closed
// surface bounds, against an independent oracle: the generalised winding
// number (the solid angles of the faces, Van Oosterom & Strackee 1983) at
// sample points of the segment or triangle.

#include "surface_interior.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "tetblend/core/constants.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/tet_boundary.h"
#include "test_surfaces.h"

namespace tetblend {
namespace {

// Winding numbers of closed surfaces are integers away from the surface; a
// sample counts as inside above 0.9 and outside below 0.1. Between the two
// it lies within round-off of a face, and the pair is not judged.
constexpr double kInsideWinding = 0.9;
constexpr double kOutsideWinding = 0.1;
// Samples per segment (and per triangle edge direction): fine against the
// shapes' edges of 1/20 to 1/10 of their size.
constexpr int kSamples = 64;
// Barycentric distances of the triangles' edge rows (triangleSamples).
constexpr double kEdgeOffsets[] = {1e-2, 1e-4, 1e-6};
// Vertices of the cylinder's sections at x = -1.5, 1.5 and on the rim's z = 0
// line come out of sin/cos and grid arithmetic within a few ulps of those
// values (sin(pi) = 1.2e-16); the next sections are 1/6 away in x and the
// next rim vertices 0.3 sin(30 deg) = 0.15 in z.
constexpr double kVertexSelection = 1e-9;
// The chord between two bent rim vertices against its closed form: the bend
// is sin/cos of angles <= pi on coordinates <= 2, a few ulps each.
constexpr double kChordTolerance = 1e-9;

// Winding number of the closed surface about p: Σ solid angles / 4π.
double windingNumber(const SurfaceMesh& surface, const Eigen::Vector3d& p) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = Eigen::Vector3d(surface.vertices.row(surface.triangles(f, 0))) - p;
    const Eigen::Vector3d b = Eigen::Vector3d(surface.vertices.row(surface.triangles(f, 1))) - p;
    const Eigen::Vector3d c = Eigen::Vector3d(surface.vertices.row(surface.triangles(f, 2))) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * kPi);
}

enum class Verdict { kInside, kOutside, kOnSurface };

// The oracle's verdict on the points Σ w_i corners_i over the sample weights.
Verdict judge(const SurfaceMesh& surface, const std::vector<Eigen::Vector3d>& points) {
  bool outside = false;
  for (const Eigen::Vector3d& p : points) {
    const double w = windingNumber(surface, p);
    if (w > kOutsideWinding && w < kInsideWinding) return Verdict::kOnSurface;
    outside = outside || w <= kOutsideWinding;
  }
  return outside ? Verdict::kOutside : Verdict::kInside;
}

std::vector<Eigen::Vector3d> segmentSamples(const SurfaceMesh& s, int a, int b) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 1; i < kSamples; ++i) {
    const double t = static_cast<double>(i) / kSamples;
    points.push_back((1 - t) * Eigen::Vector3d(s.vertices.row(a)) +
                     t * Eigen::Vector3d(s.vertices.row(b)));
  }
  return points;
}

// A grid inside the triangle, and rows along its edges at barycentric
// distances kEdgeOffsets from them: where the triangle leaves the solid
// near an edge, only a thin sliver along it is outside.
std::vector<Eigen::Vector3d> triangleSamples(const SurfaceMesh& s, int a, int b, int c) {
  const Eigen::Vector3d corners[3] = {s.vertices.row(a), s.vertices.row(b), s.vertices.row(c)};
  auto at = [&](double u, double v) {
    return (1 - u - v) * corners[0] + u * corners[1] + v * corners[2];
  };
  std::vector<Eigen::Vector3d> points;
  constexpr int n = kSamples / 4;
  for (int i = 1; i < n; ++i) {
    for (int j = 1; i + j < n; ++j) points.push_back(at(double(i) / n, double(j) / n));
  }
  for (const double offset : kEdgeOffsets) {
    for (int i = 1; i < kSamples; ++i) {
      const double t = (1 - 2 * offset) * i / kSamples + offset;
      points.push_back(at(t, offset));                   // along edge a-b
      points.push_back(at(offset, t));                   // along edge a-c
      points.push_back(at(t, 1 - t - offset));           // along edge b-c
    }
  }
  return points;
}

// A cylinder bent into a U (its arms 0.8 apart, 0.3 thick): segments and
// triangles across the gap leave the solid.
SurfaceMesh bentCylinder() {
  SurfaceMesh s = boundarySurface(cylinderTetMesh(2, 24, 0.3, 4.0));
  s.vertices = bendAboutAxis(s.vertices, Eigen::Vector3d(-2, 0, 0), Eigen::Vector3d::UnitX(),
                             Eigen::Vector3d::UnitY(), kPi, 4.0);
  return s;
}

struct Tally {
  int inside = 0;
  int outside = 0;
};

void checkAgainstOracle(const SurfaceMesh& surface, std::mt19937_64& rng, Tally& tally) {
  ASSERT_EQ(findSelfIntersections(surface.vertices, surface.triangles, 1).pairCount, 0u);
  const SurfaceInterior interior(surface.vertices, surface.triangles);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(surface.vertices.rows()) - 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int a = vertex(rng), b = vertex(rng), c = vertex(rng);
    if (a == b || b == c || a == c) continue;
    const Verdict segment = judge(surface, segmentSamples(surface, a, b));
    if (segment != Verdict::kOnSurface) {
      EXPECT_EQ(interior.segmentInside(a, b), segment == Verdict::kInside)
          << "segment " << a << " " << b;
      ++(segment == Verdict::kInside ? tally.inside : tally.outside);
    }
    const Verdict triangle = judge(surface, triangleSamples(surface, a, b, c));
    if (triangle != Verdict::kOnSurface) {
      EXPECT_EQ(interior.triangleInside(a, b, c), triangle == Verdict::kInside)
          << "triangle " << a << " " << b << " " << c;
      ++(triangle == Verdict::kInside ? tally.inside : tally.outside);
    }
  }
}

TEST(SurfaceInterior, AgreesWithTheWindingNumberOnNonConvexShapes) {
  std::mt19937_64 rng(testing_surfaces::testSeed());
  Tally tally;
  checkAgainstOracle(bentCylinder(), rng, tally);
  for (int shape = 0; shape < 4; ++shape) {
    checkAgainstOracle(testing_surfaces::randomStarShape(rng), rng, tally);
  }
  // Both answers occur often, so neither is right by default.
  EXPECT_GT(tally.inside, 100);
  EXPECT_GT(tally.outside, 100);
}

// The segment across the U's gap touches no face: only its midpoint tells
// it is outside. The segment across one arm's thickness lies inside.
TEST(SurfaceInterior, SegmentAcrossTheGapIsOutsideAndAcrossAnArmInside) {
  const SurfaceMesh straight = boundarySurface(cylinderTetMesh(2, 24, 0.3, 4.0));
  // Rim vertices (z = 0) of the sections at x = ∓1.5, on the side the bend
  // turns towards (+y, the inside of the U) and away from it. The bend by π
  // (arc radius R = 4/π) puts the inner rim on the circle of radius R − 0.3,
  // the two sections at angles 0.5/R and 3.5/R: a chord of that circle, in
  // the U's inner gap, 2 (R − 0.3) sin(π/2 − 0.5/R) long.
  auto rimVertex = [&](double x, double side) {
    int best = -1;
    for (int v = 0; v < straight.vertices.rows(); ++v) {
      const Eigen::Vector3d p = straight.vertices.row(v);
      if (std::abs(p.x() - x) > kVertexSelection || std::abs(p.z()) > kVertexSelection) continue;
      if (best < 0 || side * p.y() > side * straight.vertices(best, 1)) best = v;
    }
    return best;
  };
  const int inner = rimVertex(-1.5, 1.0), outer = rimVertex(-1.5, -1.0);
  const int otherInner = rimVertex(1.5, 1.0);
  ASSERT_GE(inner, 0);
  ASSERT_GE(outer, 0);
  ASSERT_GE(otherInner, 0);
  const SurfaceMesh u = bentCylinder();
  ASSERT_NEAR((u.vertices.row(inner) - u.vertices.row(otherInner)).norm(),
              2 * (4 / kPi - 0.3) * std::sin(kPi / 2 - 0.5 * kPi / 4), kChordTolerance);
  const SurfaceInterior interior(u.vertices, u.triangles);
  EXPECT_TRUE(interior.segmentInside(inner, outer));
  EXPECT_FALSE(interior.segmentInside(inner, otherInner));
}

// A face list that is no manifold mesh (two faces running an edge the same
// way) cannot be judged: every answer is "inside", so nothing is split.
TEST(SurfaceInterior, NoClaimOnASurfaceThatIsNoManifoldMesh) {
  Vertices vertices(4, 3);
  vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Triangles triangles(2, 3);
  triangles << 0, 1, 2, 0, 1, 3;
  const SurfaceInterior interior(vertices, triangles);
  EXPECT_TRUE(interior.segmentInside(2, 3));
  EXPECT_TRUE(interior.triangleInside(1, 2, 3));
}

}  // namespace
}  // namespace tetblend
