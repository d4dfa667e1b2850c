#pragma once
// Small surfaces with known volumes for the meshing tests (closed, or open
// with planar holes), built by hand (not by the code under test).

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "test_seed.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {
namespace testing_surfaces {

/// A stack of regular n-gons (ring k: radius radii[k] at height heights[k],
/// vertex angles 2πi/n in every ring) joined by bands of quads, each split
/// into two triangles, outward; no caps, so the top and bottom rings are
/// holes. The quads are planar trapezoids (chords at equal angles are
/// parallel), so a band with its planar rings closed is a frustum of an
/// n-gon pyramid: the enclosed volume has a closed form (frustaVolume).
/// `saddle` > 0 lifts each vertex by saddle·sin 2θ: non-planar rings, for
/// which the closed form does not hold.
struct RingStack {
  SurfaceMesh mesh;
  int n;
  int vertex(int ring, int i) const { return ring * n + (i % n); }
};

inline RingStack ringStack(int n, const std::vector<double>& radii,
                           const std::vector<double>& heights, double saddle = 0.0) {
  RingStack stack{{}, n};
  const int rings = static_cast<int>(radii.size());
  stack.mesh.vertices.resize(rings * n, 3);
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * kPi * i / n;
      stack.mesh.vertices.row(k * n + i) << radii[k] * std::cos(angle), radii[k] * std::sin(angle),
          heights[k] + saddle * std::sin(2.0 * angle);
    }
  }
  stack.mesh.triangles.resize(2 * (rings - 1) * n, 3);
  int f = 0;
  for (int k = 0; k + 1 < rings; ++k) {
    for (int i = 0; i < n; ++i) {
      const int a = stack.vertex(k, i), b = stack.vertex(k, i + 1);
      const int c = stack.vertex(k + 1, i + 1), d = stack.vertex(k + 1, i);
      stack.mesh.triangles.row(f++) << a, b, c;
      stack.mesh.triangles.row(f++) << a, c, d;
    }
  }
  return stack;
}

/// Enclosed volume of the stack of frusta (regular n-gon areas n/2 r² sin 2π/n).
inline double frustaVolume(int n, const std::vector<double>& radii,
                           const std::vector<double>& heights) {
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < radii.size(); ++k) {
    const double a1 = 0.5 * n * radii[k] * radii[k] * std::sin(2.0 * kPi / n);
    const double a2 = 0.5 * n * radii[k + 1] * radii[k + 1] * std::sin(2.0 * kPi / n);
    volume += (heights[k + 1] - heights[k]) / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
  }
  return volume;
}

/// Axis-aligned cube [lo, lo + size]^3, 8 vertices, 12 triangles, outward and
/// counter-clockwise (each face normal checked by hand: -z, +z, -y, +y, -x, +x).
inline SurfaceMesh cube(const Eigen::Vector3d& lo = Eigen::Vector3d::Zero(), double size = 1.0) {
  SurfaceMesh m;
  m.vertices.resize(8, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  m.vertices *= size;
  m.vertices.rowwise() += lo.transpose();
  m.triangles.resize(12, 3);
  m.triangles << 0, 2, 1, 0, 3, 2,  // z = lo (-z)
      4, 5, 6, 4, 6, 7,             // z = hi (+z)
      0, 1, 5, 0, 5, 4,             // y = lo (-y)
      3, 7, 6, 3, 6, 2,             // y = hi (+y)
      0, 4, 7, 0, 7, 3,             // x = lo (-x)
      1, 2, 6, 1, 6, 5;             // x = hi (+x)
  return m;
}

/// The faces as sorted triples, each rotated to start at its smallest index
/// (orientation kept): two surfaces have the same faces when these agree.
inline std::vector<std::array<int, 3>> sortedFaces(const Triangles& triangles) {
  std::vector<std::array<int, 3>> faces;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    std::array<int, 3> face{triangles(f, 0), triangles(f, 1), triangles(f, 2)};
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.push_back(face);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// Concatenation of two surfaces (b's indices shifted).
inline SurfaceMesh join(const SurfaceMesh& a, const SurfaceMesh& b) {
  SurfaceMesh m;
  m.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  m.vertices << a.vertices, b.vertices;
  m.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  m.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.rows())).matrix();
  return m;
}

/// Every face reversed.
inline SurfaceMesh reversed(SurfaceMesh m) {
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
    std::swap(m.triangles(f, 1), m.triangles(f, 2));
  return m;
}

/// Splits vertex u of a closed manifold surface into u and a new last vertex
/// w at the same position: the last `count` faces of u's fan (in its
/// counter-clockwise order from its first face) take w instead of u, and two
/// faces of zero area, (u, n_k, w) and (w, n_0, u), close the gap between
/// the arcs (a vertex split of zero length: what an exporter's collapsed
/// edge looks like). Merging w into u and dropping the two faces gives the
/// input back.
inline void splitVertexInPlace(SurfaceMesh& mesh, int u, int count) {
  std::vector<std::pair<int, int>> fan;  // (face, corner of u)
  for (int f = 0; f < mesh.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      if (mesh.triangles(f, c) == u) fan.emplace_back(f, c);
    }
  }
  const auto next = [&](std::size_t i) {
    return mesh.triangles(fan[i].first, (fan[i].second + 1) % 3);
  };
  const auto last = [&](std::size_t i) {
    return mesh.triangles(fan[i].first, (fan[i].second + 2) % 3);
  };
  for (std::size_t i = 0; i + 1 < fan.size(); ++i) {  // order: face i+1 starts where face i ends
    for (std::size_t j = i + 1; j < fan.size(); ++j) {
      if (next(j) == last(i)) std::swap(fan[i + 1], fan[j]);
    }
  }
  const int w = static_cast<int>(mesh.vertices.rows());
  mesh.vertices.conservativeResize(w + 1, 3);
  mesh.vertices.row(w) = mesh.vertices.row(u);
  const std::size_t k = fan.size() - static_cast<std::size_t>(count);
  const int nk = next(k), n0 = next(0);
  for (std::size_t i = k; i < fan.size(); ++i) mesh.triangles(fan[i].first, fan[i].second) = w;
  const Eigen::Index f = mesh.triangles.rows();
  mesh.triangles.conservativeResize(f + 2, 3);
  mesh.triangles.row(f) << u, nk, w;
  mesh.triangles.row(f + 1) << w, n0, u;
}

/// Splits face f's edge corner k -> corner k+1 (a -> b, third corner x) at
/// `points` points m1..mP along it: face f becomes the fan (a, m1, x), (m1,
/// m2, x), ..., (mP, b, x), and the run is closed against the neighbour's
/// b -> a by P faces of zero area (a, b, mP), (a, mP, mP-1), ..., (a, m2, m1),
/// as a mesher leaves a T-junction.
inline void insertCap(SurfaceMesh& mesh, int f, int k, int points) {
  const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
  const int x = mesh.triangles(f, (k + 2) % 3);
  std::vector<int> run{a};
  for (int i = 1; i <= points; ++i) {
    const Eigen::Index row = mesh.vertices.rows();
    mesh.vertices.conservativeResize(row + 1, 3);
    const double s = static_cast<double>(i) / (points + 1);
    mesh.vertices.row(row) = (1.0 - s) * mesh.vertices.row(a) + s * mesh.vertices.row(b);
    run.push_back(static_cast<int>(row));
  }
  run.push_back(b);
  std::vector<Eigen::RowVector3i> added;
  mesh.triangles.row(f) << run[0], run[1], x;
  for (int i = 1; i <= points; ++i) added.emplace_back(run[i], run[i + 1], x);
  for (int i = points; i >= 1; --i) added.emplace_back(a, run[i + 1], run[i]);
  const Eigen::Index first = mesh.triangles.rows();
  mesh.triangles.conservativeResize(first + static_cast<Eigen::Index>(added.size()), 3);
  for (std::size_t i = 0; i < added.size(); ++i) {
    mesh.triangles.row(first + static_cast<Eigen::Index>(i)) = added[i];
  }
}

/// Icosahedron subdivided `levels` times (each face into four; once: 42
/// vertices, 80 faces; three times: 642 and 1280) on the unit sphere.
inline SurfaceMesh icosphere(int levels = 1) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                    {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                    {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back((v[a] + v[b]) / 2.0);
      return midpoint[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> fine;
    for (const auto& tri : f) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      fine.push_back({tri[0], ab, ca});
      fine.push_back({tri[1], bc, ab});
      fine.push_back({tri[2], ca, bc});
      fine.push_back({ab, bc, ca});
    }
    f = std::move(fine);
  }
  SurfaceMesh m;
  m.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t i = 0; i < v.size(); ++i) m.vertices.row(i) = v[i].normalized().transpose();
  m.triangles.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i) m.triangles.row(i) << f[i][0], f[i][1], f[i][2];
  return m;
}

/// The icosphere with each vertex's radius drawn from [0.6, 1.4]: star-shaped
/// about the origin, hence embedded (no self-intersection) and closed.
inline SurfaceMesh randomStarShape(std::mt19937_64& rng) {
  SurfaceMesh m = icosphere();
  std::uniform_real_distribution<double> radius(0.6, 1.4);
  for (Eigen::Index i = 0; i < m.vertices.rows(); ++i) m.vertices.row(i) *= radius(rng);
  return m;
}

/// Seed of the randomised tests: TETBLEND_SEED if set, else a fixed default.
/// Printed so that a failure can be reproduced.
inline std::uint64_t testSeed() { return test_seed::seedOfCurrentTest(20240521u); }

}  // namespace testing_surfaces
}  // namespace tetblend
