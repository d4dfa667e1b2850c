// findSelfIntersections against an exact integer oracle (separating axes)
// on small-integer soups full of coplanar, collinear and touching faces, and
// on flat and rigidly turned grids, where the floating-point filters cannot
// decide and the answer is known by construction.
#include "tetblend/meshing/self_intersection.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "../test_seed.h"

namespace tetblend {
namespace {

using IntPoint = std::array<std::int64_t, 3>;

IntPoint operator-(const IntPoint& a, const IntPoint& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

IntPoint cross(const IntPoint& a, const IntPoint& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::int64_t dot(const IntPoint& a, const IntPoint& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool isZero(const IntPoint& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// Edge vectors of a segment (2 points) or triangle (3 points).
std::vector<IntPoint> edges(const std::vector<IntPoint>& simplex) {
  std::vector<IntPoint> result;
  for (std::size_t i = 0; i + 1 < simplex.size(); ++i) {
    for (std::size_t j = i + 1; j < simplex.size(); ++j) result.push_back(simplex[j] - simplex[i]);
  }
  return result;
}

// Whether two closed simplices (segments or triangles) share a point: they
// are disjoint iff some axis strictly separates their projections, and for
// two such convex sets the candidates are their face normals, their
// in-plane edge normals and the cross products of their edges; this takes
// every cross product of edges and normals, a superset. Exact in int64 for
// coordinates of a few units.
bool closedSimplicesMeet(const std::vector<IntPoint>& a, const std::vector<IntPoint>& b) {
  std::vector<IntPoint> directions = edges(a);
  const std::vector<IntPoint> edgesB = edges(b);
  directions.insert(directions.end(), edgesB.begin(), edgesB.end());
  if (a.size() == 3) directions.push_back(cross(a[1] - a[0], a[2] - a[0]));
  if (b.size() == 3) directions.push_back(cross(b[1] - b[0], b[2] - b[0]));
  std::vector<IntPoint> axes = directions;
  for (const IntPoint& u : directions) {
    for (const IntPoint& v : directions) axes.push_back(cross(u, v));
  }
  for (const IntPoint& axis : axes) {
    if (isZero(axis)) continue;
    auto range = [&](const std::vector<IntPoint>& simplex) {
      std::int64_t lo = dot(axis, simplex[0]), hi = lo;
      for (const IntPoint& p : simplex) {
        lo = std::min(lo, dot(axis, p));
        hi = std::max(hi, dot(axis, p));
      }
      return std::make_pair(lo, hi);
    };
    const auto [loA, hiA] = range(a);
    const auto [loB, hiB] = range(b);
    if (hiA < loB || hiB < loA) return false;
  }
  return true;
}

// The oracle of findSelfIntersections' contract: faces f and g meet other
// than in the vertices and edges they share.
bool oracleIntersect(const std::vector<IntPoint>& points, const std::array<int, 3>& f,
                     const std::array<int, 3>& g) {
  std::vector<int> shared;
  for (int v : f) {
    if (std::find(g.begin(), g.end(), v) != g.end()) shared.push_back(v);
  }
  auto corners = [&](const std::array<int, 3>& face, bool skipShared) {
    std::vector<IntPoint> result;
    for (int v : face) {
      if (!skipShared || std::find(shared.begin(), shared.end(), v) == shared.end()) {
        result.push_back(points[static_cast<std::size_t>(v)]);
      }
    }
    return result;
  };
  auto triangle = [&](const std::array<int, 3>& face) { return corners(face, false); };
  if (shared.empty()) return closedSimplicesMeet(triangle(f), triangle(g));
  if (shared.size() == 1) {  // the edge opposite the shared corner against the other face
    return closedSimplicesMeet(corners(f, true), triangle(g)) ||
           closedSimplicesMeet(corners(g, true), triangle(f));
  }
  if (shared.size() == 2) {  // folded onto each other: coplanar, on one side of the edge
    const IntPoint& p = points[static_cast<std::size_t>(shared[0])];
    const IntPoint edge = points[static_cast<std::size_t>(shared[1])] - p;
    const IntPoint r = corners(f, true)[0] - p;
    const IntPoint s = corners(g, true)[0] - p;
    return dot(cross(edge, r), s) == 0 && dot(cross(edge, r), cross(edge, s)) > 0;
  }
  return false;
}

bool collinear(const std::vector<IntPoint>& points, const std::array<int, 3>& face) {
  const IntPoint& a = points[static_cast<std::size_t>(face[0])];
  return isZero(cross(points[static_cast<std::size_t>(face[1])] - a,
                      points[static_cast<std::size_t>(face[2])] - a));
}

// Random soups on the grid {0..3}³ (every other soup flat, z = 0): their
// intersecting pairs, all of them, equal the oracle's.
TEST(SelfIntersections, SmallIntegerSoupsMatchAnExactSeparatingAxisOracle) {
  std::mt19937 rng(test_seed::seedOfCurrentTest(20261203));
  std::uniform_int_distribution<int> coordinate(0, 3);
  constexpr int kSoups = 600;
  constexpr int kPoints = 10;
  constexpr int kFaces = 14;
  std::size_t oraclePairs = 0;
  for (int soup = 0; soup < kSoups; ++soup) {
    const bool flat = soup % 2 == 0;
    std::vector<IntPoint> points;
    Vertices vertices(kPoints, 3);
    for (int i = 0; i < kPoints; ++i) {
      points.push_back({coordinate(rng), coordinate(rng), flat ? 0 : coordinate(rng)});
      for (int c = 0; c < 3; ++c) vertices(i, c) = static_cast<double>(points.back()[c]);
    }
    std::vector<std::array<int, 3>> faces;
    std::uniform_int_distribution<int> index(0, kPoints - 1);
    while (static_cast<int>(faces.size()) < kFaces) {
      std::array<int, 3> face{index(rng), index(rng), index(rng)};
      if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2]) continue;
      faces.push_back(face);
    }
    Triangles triangles(kFaces, 3);
    for (int f = 0; f < kFaces; ++f) {
      for (int c = 0; c < 3; ++c) triangles(f, c) = faces[static_cast<std::size_t>(f)][c];
    }
    std::vector<std::pair<int, int>> expected;
    for (int f = 0; f < kFaces; ++f) {
      for (int g = f + 1; g < kFaces; ++g) {
        const auto& ff = faces[static_cast<std::size_t>(f)];
        const auto& gg = faces[static_cast<std::size_t>(g)];
        if (collinear(points, ff) || collinear(points, gg)) continue;
        if (oracleIntersect(points, ff, gg)) expected.emplace_back(f, g);
      }
    }
    oraclePairs += expected.size();
    const SelfIntersections found = findSelfIntersections(vertices, triangles, kFaces * kFaces);
    ASSERT_EQ(found.pairs, expected) << "soup " << soup << (flat ? " (flat)" : "");
    ASSERT_EQ(found.pairCount, expected.size());
  }
  // The soups exercise both answers.
  EXPECT_GT(oraclePairs, static_cast<std::size_t>(kSoups));
}

// An n × n grid of unit squares in z = 0, two triangles each, turned by
// `rotation`.
SurfaceMesh turnedGrid(int n, const Eigen::Matrix3d& rotation) {
  SurfaceMesh grid;
  grid.vertices.resize((n + 1) * (n + 1), 3);
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      grid.vertices.row(i * (n + 1) + j) = (rotation * Eigen::Vector3d(i, j, 0)).transpose();
    }
  }
  grid.triangles.resize(2 * n * n, 3);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j, b = a + n + 1;
      grid.triangles.row(2 * (i * n + j)) << a, b, b + 1;
      grid.triangles.row(2 * (i * n + j) + 1) << a, b + 1, a + 1;
    }
  }
  return grid;
}

// A flat grid meets itself only along shared edges and corners, exactly
// coplanar or turned (nearly coplanar after rounding). Moving one interior
// vertex within the exact plane past its neighbour folds its fan onto the
// neighbouring faces, which must then be found. (Turned, the folded faces
// are not exactly coplanar, and whether they cross depends on rounding.)
TEST(SelfIntersections, FlatAndTurnedGridsAreCleanUntilAVertexFoldsWithinThePlane) {
  constexpr int kCells = 6;
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const SurfaceMesh turned = turnedGrid(kCells, turn);
  EXPECT_EQ(findSelfIntersections(turned.vertices, turned.triangles, 1).pairCount, 0u);
  SurfaceMesh grid = turnedGrid(kCells, Eigen::Matrix3d::Identity());
  EXPECT_EQ(findSelfIntersections(grid.vertices, grid.triangles, 1).pairCount, 0u);
  const int center = 3 * (kCells + 1) + 3;
  grid.vertices.row(center) << 4.5, 3.25, 0.0;  // past its neighbour (4, 3)
  const SelfIntersections folded = findSelfIntersections(grid.vertices, grid.triangles, 100);
  EXPECT_GT(folded.pairCount, 0u);
  for (const auto& [f, g] : folded.pairs) {  // every pair has a face of the moved fan
    EXPECT_TRUE((grid.triangles.row(f).array() == center).any() ||
                (grid.triangles.row(g).array() == center).any())
        << f << " " << g;
  }
}

}  // namespace
}  // namespace tetblend
