#include "tetblend/meshing/surface_orientation.h"

#include <Eigen/Geometry>

#include <cmath>
#include <deque>
#include <string>

#include "half_edge_table.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// |winding number| above this counts as inside: the exact value is 0 or 1 for
// a point off a closed, consistently oriented surface.
constexpr double kInsideWinding = 0.5;

Eigen::Vector3d corner(const SurfaceMesh& mesh, int f, int k) {
  return mesh.vertices.row(mesh.triangles(f, k)).transpose();
}

// Solid angle of triangle f seen from p (Van Oosterom & Strackee 1983).
double solidAngle(const SurfaceMesh& mesh, int f, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = corner(mesh, f, 0) - p;
  const Eigen::Vector3d b = corner(mesh, f, 1) - p;
  const Eigen::Vector3d c = corner(mesh, f, 2) - p;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

void checkIndices(const SurfaceMesh& mesh) {
  const Eigen::Index n = mesh.vertices.rows();
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      if (v < 0 || v >= n) {
        throw InputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                         ", outside 0.." + std::to_string(n - 1) +
                         ": fix the face indices before orienting the surface");
      }
    }
  }
}

}  // namespace

std::vector<SurfaceComponent> surfaceComponents(const SurfaceMesh& mesh,
                                                std::vector<int>* faceComponent) {
  const Triangles& tri = mesh.triangles;
  const std::size_t faceCount = static_cast<std::size_t>(tri.rows());
  const std::vector<char> skip = detail::repeatedIndexFaces(tri);
  const detail::HalfEdgeTable table = detail::buildHalfEdgeTable(tri, skip);

  detail::UnionFind sets(faceCount);
  std::vector<char> open(faceCount, 0), inconsistent(faceCount, 0);
  for (const auto& [begin, end] : table.edges) {
    const auto& he = table.halfEdges;
    for (std::size_t i = begin + 1; i < end; ++i) sets.unite(he[begin].face, he[i].face);
    const bool manifold = end - begin == 2;
    const bool opposite = manifold && he[begin].forward != he[begin + 1].forward;
    for (std::size_t i = begin; i < end; ++i) {
      if (!manifold) open[he[i].face] = 1;
      if (!opposite) inconsistent[he[i].face] = 1;
    }
  }

  std::vector<int> rootToComponent(faceCount, -1), component(faceCount, -1);
  std::vector<SurfaceComponent> components;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (skip[f]) continue;
    int& id = rootToComponent[sets.find(f)];
    if (id < 0) {
      id = static_cast<int>(components.size());
      components.push_back({static_cast<int>(f), 0, true, true, 0.0, 0});
      boxes.emplace_back();
    }
    component[f] = id;
    SurfaceComponent& c = components[static_cast<std::size_t>(id)];
    ++c.faceCount;
    c.closed = c.closed && !open[f];
    c.consistent = c.consistent && !inconsistent[f];
    const int fi = static_cast<int>(f);
    Eigen::Matrix3d p;
    for (int k = 0; k < 3; ++k) p.col(k) = corner(mesh, fi, k);
    c.signedVolume += p.determinant() / 6.0;
    for (int k = 0; k < 3; ++k) boxes[static_cast<std::size_t>(id)].extend(p.col(k));
  }

  for (std::size_t a = 0; a < components.size(); ++a) {
    const int f = components[a].firstFace;
    const Eigen::Vector3d probe =
        (corner(mesh, f, 0) + corner(mesh, f, 1) + corner(mesh, f, 2)) / 3.0;
    for (std::size_t b = 0; b < components.size(); ++b) {
      if (b == a || !components[b].closed || !components[b].consistent) continue;
      if (!boxes[b].contains(probe)) continue;
      double omega = 0.0;
      for (std::size_t g = 0; g < faceCount; ++g) {
        if (component[g] == static_cast<int>(b))
          omega += solidAngle(mesh, static_cast<int>(g), probe);
      }
      if (std::abs(omega / (4.0 * kPi)) > kInsideWinding) ++components[a].nestingDepth;
    }
  }
  if (faceComponent != nullptr) *faceComponent = std::move(component);
  return components;
}

double windingNumber(const SurfaceMesh& mesh, const Eigen::Vector3d& point) {
  double omega = 0.0;
  for (int f = 0; f < static_cast<int>(mesh.triangles.rows()); ++f) {
    omega += solidAngle(mesh, f, point);
  }
  return omega / (4.0 * kPi);
}

double enclosedVolume(const SurfaceMesh& mesh) {
  double volume = 0.0;
  for (int f = 0; f < static_cast<int>(mesh.triangles.rows()); ++f) {
    Eigen::Matrix3d p;
    for (int k = 0; k < 3; ++k) p.col(k) = corner(mesh, f, k);
    volume += p.determinant() / 6.0;
  }
  return volume;
}

OrientationFix orientConsistently(SurfaceMesh& mesh) {
  checkIndices(mesh);
  Triangles& tri = mesh.triangles;
  const std::size_t faceCount = static_cast<std::size_t>(tri.rows());
  const detail::HalfEdgeTable table =
      detail::buildHalfEdgeTable(tri, detail::repeatedIndexFaces(tri));

  // Neighbours across manifold edges, with whether they run the edge the same way.
  struct Link {
    int other;
    bool sameDirection;
  };
  std::vector<std::vector<Link>> links(faceCount);
  for (const auto& [begin, end] : table.edges) {
    const auto& he = table.halfEdges;
    if (end - begin > 2) {
      throw InputError("edge (" + std::to_string(he[begin].lo) + ", " +
                       std::to_string(he[begin].hi) + ") is shared by " +
                       std::to_string(end - begin) + " faces (first face " +
                       std::to_string(he[begin].face) +
                       "): a non-manifold surface cannot be oriented; split or repair it");
    }
    if (end - begin == 2) {
      const bool same = he[begin].forward == he[begin + 1].forward;
      links[he[begin].face].push_back({he[begin + 1].face, same});
      links[he[begin + 1].face].push_back({he[begin].face, same});
    }
  }

  // Breadth-first propagation; flip[f] = 1 when face f must be reversed.
  std::vector<int> flip(faceCount, -1);
  for (std::size_t seed = 0; seed < faceCount; ++seed) {
    if (flip[seed] >= 0 || detail::repeatsAVertex(tri, static_cast<Eigen::Index>(seed))) continue;
    std::vector<std::size_t> members{seed};
    std::deque<std::size_t> queue{seed};
    flip[seed] = 0;
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop_front();
      for (const Link& link : links[f]) {
        const std::size_t g = static_cast<std::size_t>(link.other);
        const int wanted = flip[f] ^ (link.sameDirection ? 1 : 0);
        if (flip[g] < 0) {
          flip[g] = wanted;
          members.push_back(g);
          queue.push_back(g);
        } else if (flip[g] != wanted) {
          throw InputError("faces " + std::to_string(f) + " and " + std::to_string(g) +
                           " close a non-orientable loop (Möbius-like component): no "
                           "consistent orientation exists; cut or rebuild that component");
        }
      }
    }
    std::size_t flipped = 0;
    for (std::size_t f : members) flipped += static_cast<std::size_t>(flip[f]);
    if (2 * flipped > members.size()) {
      for (std::size_t f : members) flip[f] ^= 1;
    }
  }
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (flip[f] == 1) tri.row(static_cast<Eigen::Index>(f)).tail<2>().reverseInPlace();
  }

  OrientationFix fix;
  std::vector<int> faceComponent;
  const std::vector<SurfaceComponent> components = surfaceComponents(mesh, &faceComponent);
  fix.componentCount = static_cast<int>(components.size());
  for (std::size_t c = 0; c < components.size(); ++c) {
    const SurfaceComponent& comp = components[c];
    if (!comp.closed || !comp.consistent) continue;
    const double wantedSign = comp.nestingDepth % 2 == 0 ? 1.0 : -1.0;
    if (comp.signedVolume * wantedSign >= 0.0) continue;
    fix.reversedComponents.push_back(static_cast<int>(c));
    for (std::size_t f = 0; f < faceCount; ++f) {
      if (faceComponent[f] != static_cast<int>(c)) continue;
      tri.row(static_cast<Eigen::Index>(f)).tail<2>().reverseInPlace();
      flip[f] ^= 1;
    }
  }
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (flip[f] == 1) fix.flippedFaces.push_back(static_cast<int>(f));
  }
  return fix;
}

}  // namespace tetblend
