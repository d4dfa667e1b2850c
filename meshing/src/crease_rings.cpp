#include "crease_rings.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

#include "tetblend/core/constants.h"

namespace tetblend {
namespace {

// The components of c − a and d − a across the line through a along unit d.
std::pair<Eigen::Vector3d, Eigen::Vector3d> acrossEdge(const Vertices& positions, int a,
                                                       const Eigen::Vector3d& direction, int c,
                                                       int d) {
  const Eigen::Vector3d origin = positions.row(a);
  Eigen::Vector3d u = Eigen::Vector3d(positions.row(c)) - origin;
  Eigen::Vector3d w = Eigen::Vector3d(positions.row(d)) - origin;
  u -= direction * direction.dot(u);
  w -= direction * direction.dot(w);
  return {u, w};
}

Eigen::Vector3d unitEdge(const Vertices& positions, int a, int b) {
  return (Eigen::Vector3d(positions.row(b)) - Eigen::Vector3d(positions.row(a))).normalized();
}

}  // namespace

double interiorDihedralAngle(const Vertices& positions, int a, int b, int p, int q) {
  const Eigen::Vector3d direction = unitEdge(positions, a, b);
  const auto [u, w] = acrossEdge(positions, a, direction, p, q);
  // The outward normal of (a, b, p) is direction × u: u turned by +π/2
  // about the edge. The solid lies at negative turns from u.
  const double turn = std::atan2(direction.dot(u.cross(w)), u.dot(w));
  return turn <= 0.0 ? -turn : 2.0 * kPi - turn;
}

double tetDihedralAngle(const Vertices& positions, int a, int b, int c, int d) {
  const Eigen::Vector3d direction = unitEdge(positions, a, b);
  const auto [u, w] = acrossEdge(positions, a, direction, c, d);
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

std::vector<BoundaryEdgeRing> boundaryEdgeRings(const TetMesh& mesh, const Triangles& outward) {
  // Each directed boundary edge (a, b) of a face (a, b, p), sorted by its
  // undirected key; a manifold edge appears twice, once each way.
  struct Directed {
    Simplex key;
    int a, b, third;
  };
  std::vector<Directed> directed;
  for (Eigen::Index f = 0; f < outward.rows(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const int a = outward(f, i), b = outward(f, (i + 1) % 3), third = outward(f, (i + 2) % 3);
      directed.push_back({makeSimplex({a, b}), a, b, third});
    }
  }
  std::sort(directed.begin(), directed.end(),
            [](const Directed& x, const Directed& y) { return x.key < y.key; });
  std::vector<BoundaryEdgeRing> rings;
  std::vector<Simplex> keys;
  for (std::size_t i = 0; i < directed.size();) {
    std::size_t j = i;
    while (j < directed.size() && directed[j].key == directed[i].key) ++j;
    if (j - i == 2 && directed[i].a == directed[i + 1].b) {
      BoundaryEdgeRing ring;
      ring.a = directed[i].a;
      ring.b = directed[i].b;
      ring.p = directed[i].third;
      ring.q = directed[i + 1].third;
      rings.push_back(std::move(ring));
      keys.push_back(directed[i].key);
    }
    i = j;
  }
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        const Simplex edge = makeSimplex({mesh.tets(t, i), mesh.tets(t, j)});
        const auto found = std::lower_bound(keys.begin(), keys.end(), edge);
        if (found != keys.end() && *found == edge) {
          rings[static_cast<std::size_t>(found - keys.begin())].tets.push_back(static_cast<int>(t));
        }
      }
    }
  }
  return rings;
}

std::vector<Simplex> creaseRingSplits(const TetMesh& mesh,
                                      const std::vector<BoundaryEdgeRing>& rings,
                                      const std::vector<const Vertices*>& examples,
                                      const BoundarySimplices& boundary, double maxTetDihedral) {
  std::vector<Simplex> splits;
  for (const BoundaryEdgeRing& ring : rings) {
    const double span = maxTetDihedral * static_cast<double>(ring.tets.size());
    const bool crowded =
        std::any_of(examples.begin(), examples.end(), [&](const Vertices* example) {
          return interiorDihedralAngle(*example, ring.a, ring.b, ring.p, ring.q) > span;
        });
    if (!crowded) continue;
    double widest = -1.0;
    Simplex chosen;
    for (int t : ring.tets) {
      int opposite[2];
      int count = 0;
      for (int c = 0; c < 4; ++c) {
        const int v = mesh.tets(t, c);
        if (v != ring.a && v != ring.b) opposite[count++] = v;
      }
      const Simplex edge = makeSimplex({opposite[0], opposite[1]});
      if (std::binary_search(boundary.edges.begin(), boundary.edges.end(), edge)) continue;
      const double angle =
          tetDihedralAngle(mesh.vertices, ring.a, ring.b, opposite[0], opposite[1]);
      if (angle > widest) {
        widest = angle;
        chosen = edge;
      }
    }
    if (chosen.count == 2) splits.push_back(chosen);
  }
  std::sort(splits.begin(), splits.end());
  splits.erase(std::unique(splits.begin(), splits.end()), splits.end());
  return splits;
}

}  // namespace tetblend
