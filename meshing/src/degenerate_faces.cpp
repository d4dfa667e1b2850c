#include "tetblend/meshing/degenerate_faces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

std::uint64_t edgeKey(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) |
         static_cast<std::uint32_t>(to);
}

// The faces of a surface with its directed edges indexed: the face that runs
// each edge from -> to.
class EdgeFaces {
 public:
  explicit EdgeFaces(const Triangles& triangles) : triangles_(triangles) {
    for (Eigen::Index f = 0; f < triangles_.rows(); ++f) add(static_cast<int>(f));
  }
  // The face running from -> to, or -1.
  int face(int from, int to) const {
    const auto found = faces_.find(edgeKey(from, to));
    return found == faces_.end() ? -1 : found->second;
  }
  void replace(int f, int a, int b, int c) {
    remove(f);
    triangles_.row(f) << a, b, c;
    add(f);
  }
  const Triangles& triangles() const { return triangles_; }

 private:
  void add(int f) {
    for (int k = 0; k < 3; ++k) {
      faces_[edgeKey(triangles_(f, k), triangles_(f, (k + 1) % 3))] = f;
    }
  }
  void remove(int f) {
    for (int k = 0; k < 3; ++k) {
      const auto found = faces_.find(edgeKey(triangles_(f, k), triangles_(f, (k + 1) % 3)));
      if (found != faces_.end() && found->second == f) faces_.erase(found);
    }
  }
  Triangles triangles_;
  std::unordered_map<std::uint64_t, int> faces_;
};

}  // namespace

DegenerateFaceFlips flipDegenerateFaces(SurfaceMesh& mesh, double zeroAreaRelTol,
                                        double capRelHeight) {
  const Vertices& x = mesh.vertices;
  const double diagonal = boundingBoxDiagonal(x);
  const double minArea = zeroAreaRelTol * diagonal * diagonal;
  const auto area = [&](int a, int b, int c) {
    const Eigen::Vector3d ab = (x.row(b) - x.row(a)).transpose();
    const Eigen::Vector3d ac = (x.row(c) - x.row(a)).transpose();
    return 0.5 * ab.cross(ac).norm();
  };
  // Zero area, or 2 area / longest edge² (the relative height of the vertex
  // opposite the longest edge) below capRelHeight.
  const auto flat = [&](int a, int b, int c) {
    const double twiceArea = 2.0 * area(a, b, c);
    const double longest =
        std::max({(x.row(a) - x.row(b)).squaredNorm(), (x.row(b) - x.row(c)).squaredNorm(),
                  (x.row(c) - x.row(a)).squaredNorm()});
    return twiceArea < 2.0 * minArea || twiceArea < capRelHeight * longest;
  };
  const auto degenerate = [&](const Eigen::RowVector3i& t) {
    return t(0) != t(1) && t(1) != t(2) && t(0) != t(2) && flat(t(0), t(1), t(2));
  };
  std::vector<int> pending;
  for (Eigen::Index f = mesh.triangles.rows() - 1; f >= 0; --f) {
    if (degenerate(mesh.triangles.row(f))) pending.push_back(static_cast<int>(f));
  }
  DegenerateFaceFlips result;
  if (pending.empty()) return result;  // the usual case: no edge index needed
  EdgeFaces edges(mesh.triangles);
  // Each pass tries every pending face once; a flip can make a skipped face
  // flippable, so passes repeat while they flip something.
  for (bool progress = true; progress && !pending.empty();) {
    progress = false;
    std::vector<int> stuck;
    for (const int f : pending) {
      const Eigen::RowVector3i t = edges.triangles().row(f);
      if (!degenerate(t)) continue;
      int longest = 0;  // the edge t(k) -> t(k + 1) of greatest length
      for (int k = 1; k < 3; ++k) {
        if ((x.row(t(k)) - x.row(t((k + 1) % 3))).squaredNorm() >
            (x.row(t(longest)) - x.row(t((longest + 1) % 3))).squaredNorm()) {
          longest = k;
        }
      }
      const int u = t(longest), v = t((longest + 1) % 3), c = t((longest + 2) % 3);
      const int g = edges.face(v, u);
      int d = -1;
      if (g >= 0) {
        for (int k = 0; k < 3; ++k) {
          const int corner = edges.triangles()(g, k);
          if (corner != u && corner != v) d = corner;
        }
      }
      if (d < 0 || d == c || edges.face(c, d) >= 0 || edges.face(d, c) >= 0 || flat(u, d, c) ||
          flat(d, v, c)) {
        stuck.push_back(f);
        continue;
      }
      edges.replace(f, u, d, c);
      edges.replace(g, d, v, c);
      ++result.flipped;
      progress = true;
    }
    pending = std::move(stuck);
  }
  result.left = static_cast<int>(pending.size());
  mesh.triangles = edges.triangles();
  return result;
}

}  // namespace tetblend
