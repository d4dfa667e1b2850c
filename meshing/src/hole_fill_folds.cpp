#include "hole_fill_folds.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "tetblend/core/constants.h"

namespace tetblend {
namespace {

std::uint64_t directedKey(int from, int to) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32 |
         static_cast<std::uint32_t>(to);
}

// The unit normal of triangle (a, b, c), or zero when it has no area.
Eigen::Vector3d unitNormal(const Vertices& p, int a, int b, int c) {
  const Eigen::Vector3d u = (p.row(b) - p.row(a)).transpose();
  const Eigen::Vector3d v = (p.row(c) - p.row(a)).transpose();
  const Eigen::Vector3d n = u.cross(v);
  const double length = n.norm();
  return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

}  // namespace

double sharpestFold(const FillTriangles& fill, const std::vector<Border>& rim,
                    const Triangles& surfaceTriangles, const Vertices& positions) {
  // The normal of the face that runs each directed edge.
  std::unordered_map<std::uint64_t, Eigen::Vector3d> normalAlong;
  double sharpest = 0.0;
  for (const std::array<int, 3>& t : fill) {
    const Eigen::Vector3d n = unitNormal(positions, t[0], t[1], t[2]);
    if (n.isZero()) sharpest = kPi;
    for (int k = 0; k < 3; ++k) normalAlong[directedKey(t[k], t[(k + 1) % 3])] = n;
  }
  for (const Border& b : rim) {
    const auto f = surfaceTriangles.row(b.face);
    normalAlong[directedKey(b.to, b.from)] = unitNormal(positions, f(0), f(1), f(2));
  }
  for (const std::array<int, 3>& t : fill) {
    for (int k = 0; k < 3; ++k) {
      const auto here = normalAlong.find(directedKey(t[k], t[(k + 1) % 3]));
      const auto across = normalAlong.find(directedKey(t[(k + 1) % 3], t[k]));
      if (across == normalAlong.end()) continue;  // not this hole's edge
      if (here->second.isZero() || across->second.isZero()) return kPi;
      const double cosine = std::clamp(here->second.dot(across->second), -1.0, 1.0);
      sharpest = std::max(sharpest, std::acos(cosine));
    }
  }
  return sharpest;
}

}  // namespace tetblend
