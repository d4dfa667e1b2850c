#include "tetblend/meshing/procedural_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

void requirePositiveCount(int value, const char* name, const char* function) {
  if (value < 1) {
    throw InputError(std::string(function) + ": " + name + " = " + std::to_string(value) +
                     " must be at least 1");
  }
}

void requirePositiveSize(double value, const char* name, const char* function) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(std::string(function) + ": " + name + " = " + std::to_string(value) +
                     " must be positive and finite");
  }
}

// Swaps two corners of every negatively oriented tet so all are positive.
void orientPositively(const Vertices& vertices, Tets& tets) {
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    const Eigen::RowVector4i tet = tets.row(t);
    if (tetSignedVolume(vertices, tet) < 0.0) std::swap(tets(t, 2), tets(t, 3));
  }
}

// Triangulation of the hexagonal-ring disc of the given radius in the (y, z)
// plane: ring r (1..rings) has 6r vertices at radius radius*r/rings.
void discTriangulation(int rings, double radius, std::vector<Eigen::Vector2d>& points,
                       std::vector<std::array<int, 3>>& triangles) {
  points.assign(1, Eigen::Vector2d::Zero());
  std::vector<int> ringStart(1, 0);
  for (int r = 1; r <= rings; ++r) {
    ringStart.push_back(static_cast<int>(points.size()));
    const int count = 6 * r;
    for (int j = 0; j < count; ++j) {
      const double angle = 2.0 * kPi * j / count;
      points.emplace_back(radius * r / rings * std::cos(angle),
                          radius * r / rings * std::sin(angle));
    }
  }
  for (int r = 1; r <= rings; ++r) {
    const int outerCount = 6 * r;
    const int innerCount = r == 1 ? 1 : 6 * (r - 1);
    auto outer = [&](int j) { return ringStart[r] + j % outerCount; };
    auto inner = [&](int i) { return ringStart[r - 1] + i % innerCount; };
    if (r == 1) {
      for (int j = 0; j < outerCount; ++j) triangles.push_back({0, outer(j), outer(j + 1)});
      continue;
    }
    // Zipper around the annulus: advance on the ring whose next vertex comes
    // first in angle; both rings start at angle 0.
    int i = 0;
    int j = 0;
    while (i < innerCount || j < outerCount) {
      const double nextInner = static_cast<double>(i + 1) / innerCount;
      const double nextOuter = static_cast<double>(j + 1) / outerCount;
      if (j < outerCount && (i == innerCount || nextOuter <= nextInner)) {
        triangles.push_back({inner(i), outer(j), outer(j + 1)});
        ++j;
      } else {
        triangles.push_back({inner(i), outer(j), inner(i + 1)});
        ++i;
      }
    }
  }
}

}  // namespace

TetMesh boxTetMesh(int nx, int ny, int nz, const Eigen::Vector3d& size) {
  requirePositiveCount(nx, "nx", "boxTetMesh");
  requirePositiveCount(ny, "ny", "boxTetMesh");
  requirePositiveCount(nz, "nz", "boxTetMesh");
  for (int d = 0; d < 3; ++d) requirePositiveSize(size(d), "size component", "boxTetMesh");
  const std::array<int, 3> n = {nx, ny, nz};
  auto index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };

  TetMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        const std::array<int, 3> ijk = {i, j, k};
        for (int d = 0; d < 3; ++d) {
          mesh.vertices(index(i, j, k), d) = size(d) * (static_cast<double>(ijk[d]) / n[d] - 0.5);
        }
      }
    }
  }
  // Kuhn split: one tet per axis permutation, walking from corner (0,0,0) to
  // (1,1,1) one axis at a time.
  std::array<int, 3> perm = {0, 1, 2};
  std::vector<std::array<int, 3>> perms;
  do perms.push_back(perm);
  while (std::next_permutation(perm.begin(), perm.end()));

  mesh.tets.resize(static_cast<Eigen::Index>(6) * nx * ny * nz, 4);
  Eigen::Index t = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        for (const auto& p : perms) {
          std::array<int, 3> corner = {i, j, k};
          mesh.tets(t, 0) = index(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step) {
            ++corner[p[step]];
            mesh.tets(t, step + 1) = index(corner[0], corner[1], corner[2]);
          }
          ++t;
        }
      }
    }
  }
  orientPositively(mesh.vertices, mesh.tets);
  return mesh;
}

TetMesh cylinderTetMesh(int rings, int layers, double radius, double length) {
  requirePositiveCount(rings, "rings", "cylinderTetMesh");
  requirePositiveCount(layers, "layers", "cylinderTetMesh");
  requirePositiveSize(radius, "radius", "cylinderTetMesh");
  requirePositiveSize(length, "length", "cylinderTetMesh");
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 3>> triangles;
  discTriangulation(rings, radius, points, triangles);
  const int sectionCount = static_cast<int>(points.size());

  TetMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(sectionCount) * (layers + 1), 3);
  for (int l = 0; l <= layers; ++l) {
    const double x = length * (static_cast<double>(l) / layers - 0.5);
    for (int v = 0; v < sectionCount; ++v) {
      mesh.vertices.row(l * sectionCount + v) << x, points[v].x(), points[v].y();
    }
  }
  // Each prism (triangle × layer) splits into 3 tets; with corners sorted by
  // global index, every quad face (vi, vj, vi', vj'), i < j, gets diagonal
  // vi–vj', so neighbouring prisms agree.
  mesh.tets.resize(static_cast<Eigen::Index>(3) * triangles.size() * layers, 4);
  Eigen::Index t = 0;
  for (int l = 0; l < layers; ++l) {
    for (std::array<int, 3> tri : triangles) {
      std::sort(tri.begin(), tri.end());
      const int b0 = l * sectionCount + tri[0];
      const int b1 = l * sectionCount + tri[1];
      const int b2 = l * sectionCount + tri[2];
      const int u0 = b0 + sectionCount;
      const int u1 = b1 + sectionCount;
      const int u2 = b2 + sectionCount;
      mesh.tets.row(t++) << b0, b1, b2, u2;
      mesh.tets.row(t++) << b0, b1, u1, u2;
      mesh.tets.row(t++) << b0, u0, u1, u2;
    }
  }
  orientPositively(mesh.vertices, mesh.tets);
  return mesh;
}

double cylinderSectionArea(int rings, double radius) {
  requirePositiveCount(rings, "rings", "cylinderSectionArea");
  const int sides = 6 * rings;
  return 0.5 * sides * radius * radius * std::sin(2.0 * kPi / sides);
}

Vertices twistAboutAxis(const Vertices& vertices, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& direction, double totalAngle, double length) {
  if (direction.norm() == 0.0) throw InputError("twistAboutAxis: direction is the zero vector");
  requirePositiveSize(length, "length", "twistAboutAxis");
  const Eigen::Vector3d axis = direction.normalized();
  Vertices result(vertices.rows(), 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const Eigen::Vector3d p = vertices.row(v).transpose() - origin;
    const double angle = totalAngle * p.dot(axis) / length;
    result.row(v) = (origin + Eigen::AngleAxisd(angle, axis) * p).transpose();
  }
  return result;
}

Vertices bendAboutAxis(const Vertices& vertices, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& lengthDirection, const Eigen::Vector3d& bendDirection,
                       double totalAngle, double length) {
  requirePositiveSize(length, "length", "bendAboutAxis");
  if (lengthDirection.norm() == 0.0) {
    throw InputError("bendAboutAxis: lengthDirection is the zero vector");
  }
  const Eigen::Vector3d ex = lengthDirection.normalized();
  const Eigen::Vector3d yRaw = bendDirection - bendDirection.dot(ex) * ex;
  if (yRaw.norm() == 0.0) {
    throw InputError("bendAboutAxis: bendDirection is zero or parallel to lengthDirection");
  }
  if (totalAngle == 0.0) return vertices;
  const Eigen::Vector3d ey = yRaw.normalized();
  const double radius = length / totalAngle;  // signed: a negative angle bends away
  Vertices result(vertices.rows(), 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const Eigen::Vector3d p = vertices.row(v).transpose() - origin;
    const double s = p.dot(ex);
    const double y = p.dot(ey);
    const Eigen::Vector3d rest = p - s * ex - y * ey;  // component along ex × ey
    if (s <= 0.0) {
      result.row(v) = vertices.row(v);
      continue;
    }
    const double arc = std::min(s, length);
    const double theta = arc / radius;
    Eigen::Vector3d q =
        (radius - (radius - y) * std::cos(theta)) * ey + (radius - y) * std::sin(theta) * ex + rest;
    if (s > length) q += (s - length) * (std::cos(theta) * ex + std::sin(theta) * ey);
    result.row(v) = (origin + q).transpose();
  }
  return result;
}

Eigen::MatrixXd twoBoneWeights(const Vertices& vertices, const Eigen::Vector3d& joint,
                               const Eigen::Vector3d& boneDirection, double blendHalfWidth) {
  requirePositiveSize(blendHalfWidth, "blendHalfWidth", "twoBoneWeights");
  if (boneDirection.norm() == 0.0) {
    throw InputError("twoBoneWeights: boneDirection is the zero vector");
  }
  const Eigen::Vector3d d = boneDirection.normalized();
  Eigen::MatrixXd weights(vertices.rows(), 2);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const double s = (vertices.row(v).transpose() - joint).dot(d);
    const double u = std::clamp((s + blendHalfWidth) / (2.0 * blendHalfWidth), 0.0, 1.0);
    const double w1 = u * u * (3.0 - 2.0 * u);
    weights(v, 0) = 1.0 - w1;
    weights(v, 1) = w1;
  }
  return weights;
}

Eigen::Isometry3d rotationAboutLine(const Eigen::Vector3d& joint, const Eigen::Vector3d& axis,
                                    double angle) {
  if (axis.norm() == 0.0) throw InputError("rotationAboutLine: axis is the zero vector");
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  motion.translation() = joint - motion.linear() * joint;
  return motion;
}

}  // namespace tetblend
