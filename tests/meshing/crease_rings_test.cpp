// Boundary-edge rings (meshing/src/crease_rings.h) on an L-shaped block of
// Kuhn-split cubes: the interior dihedral angle of the surface at each
// boundary edge against the sum of its tets' dihedral angles computed from
// face normals, and the splits that give crowded rings one tet more.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "crease_rings.h"
#include "tet_stellar_split.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// Angles from unit-scale coordinates: atan2 carries a few ulps, and acos is
// well conditioned at the Kuhn tets' dihedral angles (45° to 120°, away from
// 0 and π); 1e-12 rad is ~4500 ε.
constexpr double kAngleTolerance = 1e-12;
// A sum of the angles of the tets around one edge: at most 8 in this block.
constexpr double kRingSumTolerance = 8 * kAngleTolerance;

// A 2 × 2 × 1 block of unit cubes (6 Kuhn tets each) without the cube at
// x > 0, y > 0: a reflex edge of 3π/2 along z at the origin.
TetMesh lBlock() {
  const TetMesh box = boxTetMesh(2, 2, 1, Eigen::Vector3d(2.0, 2.0, 1.0));
  std::vector<int> kept;
  for (Eigen::Index t = 0; t < box.tets.rows(); ++t) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int c = 0; c < 4; ++c) centroid += box.vertices.row(box.tets(t, c)) / 4.0;
    if (!(centroid.x() > 0.0 && centroid.y() > 0.0)) kept.push_back(static_cast<int>(t));
  }
  TetMesh mesh;
  mesh.vertices = box.vertices;
  mesh.tets = box.tets(kept, Eigen::all);
  return mesh;
}

// The dihedral angle of tet (a, b, c, d) at edge (a, b) from the normals of
// its faces (a, b, c) and (a, b, d): an oracle independent of the
// projections tetDihedralAngle uses.
double dihedralFromNormals(const Vertices& x, int a, int b, int c, int d) {
  const Eigen::Vector3d edge = x.row(b) - x.row(a);
  const Eigen::Vector3d n1 = edge.cross(Eigen::Vector3d(x.row(c) - x.row(a))).normalized();
  const Eigen::Vector3d n2 = edge.cross(Eigen::Vector3d(x.row(d) - x.row(a))).normalized();
  return std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
}

// The two corners of tet t other than a and b.
std::array<int, 2> oppositeCorners(const TetMesh& mesh, int t, int a, int b) {
  std::array<int, 2> opposite{};
  int count = 0;
  for (int c = 0; c < 4; ++c) {
    const int v = mesh.tets(t, c);
    if (v != a && v != b) opposite[static_cast<std::size_t>(count++)] = v;
  }
  return opposite;
}

TEST(CreaseRings, InteriorAngleOfEveryBoundaryEdgeIsTheSumOfItsTetsAngles) {
  const TetMesh mesh = lBlock();
  const Triangles outward = boundarySurface(mesh).triangles;
  const std::vector<BoundaryEdgeRing> rings = boundaryEdgeRings(mesh, outward);
  ASSERT_FALSE(rings.empty());
  EXPECT_TRUE(std::is_sorted(rings.begin(), rings.end(), [](const auto& x, const auto& y) {
    return std::pair(std::min(x.a, x.b), std::max(x.a, x.b)) <
           std::pair(std::min(y.a, y.b), std::max(y.a, y.b));
  }));
  int reflex = 0;
  for (const BoundaryEdgeRing& ring : rings) {
    std::vector<int> around;  // brute force: every tet holding both ends
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
      const auto row = mesh.tets.row(t);
      if ((row.array() == ring.a).any() && (row.array() == ring.b).any()) {
        around.push_back(static_cast<int>(t));
      }
    }
    EXPECT_EQ(ring.tets, around);
    double sum = 0.0;
    for (int t : ring.tets) {
      const auto [c, d] = oppositeCorners(mesh, t, ring.a, ring.b);
      sum += dihedralFromNormals(mesh.vertices, ring.a, ring.b, c, d);
      EXPECT_NEAR(tetDihedralAngle(mesh.vertices, ring.a, ring.b, c, d),
                  dihedralFromNormals(mesh.vertices, ring.a, ring.b, c, d), kAngleTolerance);
    }
    const double angle = interiorDihedralAngle(mesh.vertices, ring.a, ring.b, ring.p, ring.q);
    ASSERT_LE(ring.tets.size(), 8u);
    EXPECT_NEAR(angle, sum, kRingSumTolerance) << ring.a << "-" << ring.b;
    // A block of axis-aligned cubes: convex edges, flat face diagonals, and
    // the reflex edge along z through the origin.
    const double quarters = std::round(angle / (kPi / 2.0));
    EXPECT_NEAR(angle, quarters * kPi / 2.0, kAngleTolerance) << ring.a << "-" << ring.b;
    if (quarters == 3.0) ++reflex;
  }
  EXPECT_GE(reflex, 1);
}

TEST(CreaseRings, CrowdedRingsAreSplitOnceAndGainATet) {
  const TetMesh mesh = lBlock();
  const Triangles outward = boundarySurface(mesh).triangles;
  const BoundarySimplices boundary = boundarySimplices(outward);
  const std::vector<BoundaryEdgeRing> rings = boundaryEdgeRings(mesh, outward);
  // A per-tet bound of 80°: the reflex edge (270°) and convex edges with
  // one tet (90°) are crowded, flat edges with two tets are not.
  const double bound = 80.0 * kPi / 180.0;
  const std::vector<const Vertices*> examples = {&mesh.vertices};
  const std::vector<Simplex> splits = creaseRingSplits(mesh, rings, examples, boundary, bound);
  ASSERT_FALSE(splits.empty());
  int crowded = 0;
  for (const BoundaryEdgeRing& ring : rings) {
    const double angle = interiorDihedralAngle(mesh.vertices, ring.a, ring.b, ring.p, ring.q);
    std::vector<Simplex> chosen;  // the ring's opposite edges that were returned
    bool splittable = false;
    for (int t : ring.tets) {
      const auto [c, d] = oppositeCorners(mesh, t, ring.a, ring.b);
      const Simplex edge = makeSimplex({c, d});
      if (std::binary_search(splits.begin(), splits.end(), edge)) chosen.push_back(edge);
      splittable =
          splittable || !std::binary_search(boundary.edges.begin(), boundary.edges.end(), edge);
    }
    // A crowded ring has an opposite edge split unless every one lies on the
    // boundary (an uncrowded one may share an opposite edge with a crowded
    // one); that split alone adds a tet around its edge.
    if (!(angle > bound * static_cast<double>(ring.tets.size()) && splittable)) continue;
    ++crowded;
    ASSERT_FALSE(chosen.empty()) << ring.a << "-" << ring.b;
    const TetMesh refined = splitSimplices(mesh, {chosen.front()});
    const std::vector<BoundaryEdgeRing> after =
        boundaryEdgeRings(refined, boundarySurface(refined).triangles);
    const auto same = std::find_if(after.begin(), after.end(), [&](const BoundaryEdgeRing& r) {
      return r.a == ring.a && r.b == ring.b;
    });
    ASSERT_NE(same, after.end());
    EXPECT_EQ(same->tets.size(), ring.tets.size() + 1) << ring.a << "-" << ring.b;
  }
  EXPECT_GT(crowded, 0);
  for (const Simplex& edge : splits) {
    EXPECT_EQ(edge.count, 2);
    EXPECT_FALSE(std::binary_search(boundary.edges.begin(), boundary.edges.end(), edge));
  }
}

}  // namespace
}  // namespace tetblend
