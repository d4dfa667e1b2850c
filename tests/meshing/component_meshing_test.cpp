// Closed components that overlap one another, meshed each on its own and
// joined (component_meshing.h); the self-intersection test that counts only
// faces of one component; and buildCompatibleTetMeshes, which treats each tet
// component as a solid of its own.

#include "tetblend/meshing/component_meshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>

#include "test_surfaces.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/meshing/tet_boundary.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {
namespace {

using testing_surfaces::icosphere;
using testing_surfaces::join;

// Volumes are sums of ~10^3 tets of volume ~10^-3 against totals ~1:
// round-off is ~1e-15 relative; 1e-12 leaves room and still catches a
// missing or doubled tet (each is >1e-5 of the total).
constexpr double kVolumeRelTol = 1e-12;

SurfaceMesh sphereAt(double x, double y, double z, double radius, int levels) {
  SurfaceMesh s = icosphere(levels);
  s.vertices *= radius;
  s.vertices.rowwise() += Eigen::RowVector3d(x, y, z);
  return s;
}

// A unit sphere with an "eye" (radius 0.3 centred on its surface, half in,
// half out) and a "tooth" (radius 0.2, inside but crossing the eye), their
// vertices interleaved with the head's in the file: a surface whose faces of
// different components intersect at many pairs, none within a component.
struct Head {
  SurfaceMesh surface;
  std::vector<int> faceComponent;
  std::vector<double> componentVolumes;
};

Head headWithEyeAndTooth() {
  const std::vector<SurfaceMesh> parts = {sphereAt(0, 0, 0, 1.0, 3), sphereAt(1.0, 0, 0, 0.3, 2),
                                          sphereAt(0.8, 0.2, 0, 0.2, 2)};
  Head head;
  head.surface = join(join(parts[0], parts[1]), parts[2]);
  for (std::size_t c = 0; c < parts.size(); ++c) {
    head.faceComponent.insert(head.faceComponent.end(),
                              static_cast<std::size_t>(parts[c].triangles.rows()),
                              static_cast<int>(c));
    head.componentVolumes.push_back(enclosedVolume(parts[c]));
  }
  // Renumber the vertices by x: the components' rows then interleave, with
  // no block structure left for the join to rely on.
  const Eigen::Index n = head.surface.vertices.rows();
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return head.surface.vertices(a, 0) < head.surface.vertices(b, 0);
  });
  std::vector<int> rank(order.size());
  Vertices sorted(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    sorted.row(i) = head.surface.vertices.row(order[static_cast<std::size_t>(i)]);
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = static_cast<int>(i);
  }
  head.surface.vertices = sorted;
  for (Eigen::Index f = 0; f < head.surface.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      head.surface.triangles(f, c) = rank[static_cast<std::size_t>(head.surface.triangles(f, c))];
    }
  }
  return head;
}

TEST(ComponentMeshing, OverlappingComponentsIntersectOnlyAcrossComponents) {
  const Head head = headWithEyeAndTooth();
  const SelfIntersections all =
      findSelfIntersections(head.surface.vertices, head.surface.triangles, 1);
  EXPECT_GT(all.pairCount, 50u);
  EXPECT_EQ(
      findSelfIntersections(head.surface.vertices, head.surface.triangles, 1, head.faceComponent)
          .pairCount,
      0u);
  // A fold within one component is still found: the eye's cap pushed
  // through its own far side.
  SurfaceMesh folded = head.surface;
  int moved = 0;
  for (Eigen::Index v = 0; v < folded.vertices.rows(); ++v) {
    if (folded.vertices(v, 0) > 1.2) {
      folded.vertices(v, 0) -= 0.5;
      ++moved;
    }
  }
  ASSERT_GT(moved, 0);
  const SelfIntersections within =
      findSelfIntersections(folded.vertices, folded.triangles, 1, head.faceComponent);
  ASSERT_GT(within.pairCount, 0u);
  EXPECT_EQ(head.faceComponent[static_cast<std::size_t>(within.pairs[0].first)],
            head.faceComponent[static_cast<std::size_t>(within.pairs[0].second)]);
  const std::vector<int> tooFew = {0, 1};
  EXPECT_THROW(findSelfIntersections(head.surface.vertices, head.surface.triangles, 1, tooFew),
               InputError);
}

TEST(ComponentMeshing, EachComponentIsMeshedWholeAndTheSurfaceKept) {
  const Head head = headWithEyeAndTooth();
  const TetMesh mesh =
      tetrahedralizeEachComponent(head.surface, head.faceComponent, 3, TetGenOptions{});
  const Eigen::Index surfaceCount = head.surface.vertices.rows();
  ASSERT_GE(mesh.vertices.rows(), surfaceCount);
  EXPECT_TRUE(mesh.vertices.topRows(surfaceCount) == head.surface.vertices);
  EXPECT_EQ(testing_surfaces::sortedFaces(boundarySurface(mesh).triangles),
            testing_surfaces::sortedFaces(head.surface.triangles));
  double volume = 0.0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const double v = tetSignedVolume(mesh.vertices, mesh.tets.row(t));
    EXPECT_GT(v, 0.0) << "tet " << t;
    volume += v;
  }
  // Each component's solid is filled whole, overlaps and all: the volumes
  // add up (one mesh of the union would hold less).
  double expected = 0.0;
  for (double v : head.componentVolumes) expected += v;
  EXPECT_NEAR(volume, expected, kVolumeRelTol * expected);
}

TEST(ComponentMeshing, SurfacePartKeepsTheSurfacesOrder) {
  const Head head = headWithEyeAndTooth();
  const SurfacePart eye = surfacePart(head.surface, head.faceComponent, 1);
  EXPECT_TRUE(std::is_sorted(eye.vertexRows.begin(), eye.vertexRows.end()));
  ASSERT_EQ(eye.surface.vertices.rows(), static_cast<Eigen::Index>(eye.vertexRows.size()));
  Eigen::Index f = 0;
  for (Eigen::Index g = 0; g < head.surface.triangles.rows(); ++g) {
    if (head.faceComponent[static_cast<std::size_t>(g)] != 1) continue;
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(eye.vertexRows[static_cast<std::size_t>(eye.surface.triangles(f, c))],
                head.surface.triangles(g, c));
    }
    ++f;
  }
  EXPECT_EQ(f, eye.surface.triangles.rows());
  EXPECT_NEAR(enclosedVolume(eye.surface), head.componentVolumes[1],
              kVolumeRelTol * head.componentVolumes[1]);
}

// Two separate balls (two tet components); the example moves one halfway
// into the other. Its faces then intersect, but only across components:
// each ball is still embedded exactly (a rigid motion), the example counts
// as clean, and no tet is inverted.
TEST(ComponentMeshing, ExampleWhoseComponentsCollideIsClean) {
  const SurfaceMesh balls = join(sphereAt(0, 0, 0, 1.0, 2), sphereAt(3.0, 0, 0, 1.0, 2));
  const TetMesh rest = tetrahedralize(balls);
  const auto surfaceCount = static_cast<int>(balls.vertices.rows());
  Vertices collided = balls.vertices;
  for (Eigen::Index v = balls.vertices.rows() / 2; v < collided.rows(); ++v) collided(v, 0) -= 2.0;
  ASSERT_GT(findSelfIntersections(collided, balls.triangles, 1).pairCount, 0u);
  const CompatibleTetMeshes built = buildCompatibleTetMeshes(rest, surfaceCount, {collided});
  EXPECT_EQ(built.selfIntersections[0].pairCount, 0u);
  EXPECT_TRUE(built.examples[0].invertedTets.empty());
  EXPECT_EQ(built.steinerPoints, 0);
}

// Regions part where an edge has more than two faces, and nowhere else:
// two disjoint spheres are two regions either way; a fin (a face on a
// sphere's edge, with a face of its own beyond) is a region of its own, and
// the sphere stays one; a face repeating a vertex gets -1.
TEST(ComponentMeshing, ManifoldRegionsPartAtEdgesOfMoreThanTwoFaces) {
  SurfaceMesh spheres = join(icosphere(1), icosphere(1));
  spheres.vertices.bottomRows(icosphere(1).vertices.rows()).col(0).array() += 3.0;
  std::vector<int> region, component;
  ASSERT_EQ(manifoldRegions(spheres.triangles, region), 2);
  surfaceComponents(spheres, &component);
  EXPECT_EQ(region, component);

  SurfaceMesh fin = icosphere(1);
  const auto sphereFaces = static_cast<int>(fin.triangles.rows());
  const int a = fin.triangles(0, 0), b = fin.triangles(0, 1);
  const auto apex = static_cast<int>(fin.vertices.rows());
  fin.vertices.conservativeResize(apex + 2, 3);
  fin.vertices.row(apex) = 2.0 * (fin.vertices.row(a) + fin.vertices.row(b));
  fin.vertices.row(apex + 1) = 3.0 * fin.vertices.row(a);
  fin.triangles.conservativeResize(sphereFaces + 3, 3);
  fin.triangles.row(sphereFaces) << a, b, apex;
  fin.triangles.row(sphereFaces + 1) << a, apex, apex + 1;  // joined to the fin's first face
  fin.triangles.row(sphereFaces + 2) << a, a, b;            // repeats a vertex
  ASSERT_EQ(manifoldRegions(fin.triangles, region), 2);
  for (int f = 0; f < sphereFaces; ++f) EXPECT_EQ(region[static_cast<std::size_t>(f)], 0) << f;
  EXPECT_EQ(region[static_cast<std::size_t>(sphereFaces)], 1);
  EXPECT_EQ(region[static_cast<std::size_t>(sphereFaces + 1)], 1);
  EXPECT_EQ(region[static_cast<std::size_t>(sphereFaces + 2)], -1);
}

}  // namespace
}  // namespace tetblend
