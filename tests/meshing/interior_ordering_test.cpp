// The interior elimination order (meshing/src/interior_ordering.h): METIS's
// order against the fill of the natural one (an elimination game played
// here), when the background order starts, the rule for appended vertices,
// and a builder factoring with an order of the mesh it refines against one
// ordering for itself.

#include <gtest/gtest.h>

#include <algorithm>
#include <future>
#include <set>
#include <vector>

#include <tbb/global_control.h>

#include "interior_ordering.h"
#include "tet_stellar_split.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/compatible_tets.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// Two factorisations of the same K_II (cond ~ 1e2 on this box) solve the
// harmonic extension to a few hundred ulps of the unit-size coordinates.
constexpr double kSameSolveTolerance = 1e-12;

#ifndef TETBLEND_HAVE_METIS
#define SKIP_WITHOUT_METIS() GTEST_SKIP() << "tetblend is built without METIS: no interior order"
#else
#define SKIP_WITHOUT_METIS() static_cast<void>(0)
#endif

BoundaryFirstMesh box(int cells) {
  return reorderBoundaryFirst(boxTetMesh(cells, cells, cells, Eigen::Vector3d(1.0, 1.0, 1.0)));
}

// Fill edges of eliminating the interior graph (vertices joined by tet
// edges) in `order`: each eliminated vertex joins its remaining neighbours
// into a clique (the graph model of symmetric Gaussian elimination).
long long eliminationFill(const BoundaryFirstMesh& mesh, const std::vector<int>& order) {
  const int surface = mesh.boundaryVertexCount;
  const auto interior = static_cast<std::size_t>(mesh.mesh.vertices.rows() - surface);
  std::vector<std::set<int>> adjacent(interior);
  for (Eigen::Index t = 0; t < mesh.mesh.tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        const int u = mesh.mesh.tets(t, a) - surface;
        const int w = mesh.mesh.tets(t, b) - surface;
        if (u >= 0 && w >= 0 && u != w) adjacent[static_cast<std::size_t>(u)].insert(w);
      }
    }
  }
  long long fill = 0;
  std::vector<char> eliminated(interior, 0);
  for (int v : order) {
    eliminated[static_cast<std::size_t>(v)] = 1;
    std::vector<int> remaining;
    for (int w : adjacent[static_cast<std::size_t>(v)]) {
      if (!eliminated[static_cast<std::size_t>(w)]) remaining.push_back(w);
    }
    for (int a : remaining) {
      for (int b : remaining) {
        if (a < b && adjacent[static_cast<std::size_t>(a)].insert(b).second) {
          adjacent[static_cast<std::size_t>(b)].insert(a);
          ++fill;
        }
      }
    }
  }
  return fill;
}

TEST(InteriorOrdering, MetisOrdersEveryInteriorVertexOnceWithLessFillThanTheNaturalOrder) {
  SKIP_WITHOUT_METIS();
  const BoundaryFirstMesh mesh = box(9);
  const int interior = static_cast<int>(mesh.mesh.vertices.rows()) - mesh.boundaryVertexCount;
  ASSERT_EQ(interior, 8 * 8 * 8);
  const InteriorOrder order = metisInteriorOrder(mesh.mesh.tets, mesh.boundaryVertexCount,
                                                 static_cast<int>(mesh.mesh.vertices.rows()));
  ASSERT_EQ(static_cast<int>(order.size()), interior);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < interior; ++k) ASSERT_EQ(sorted[static_cast<std::size_t>(k)], k);
  std::vector<int> natural(static_cast<std::size_t>(interior));
  for (int k = 0; k < interior; ++k) natural[static_cast<std::size_t>(k)] = k;
  const long long metisFill = eliminationFill(mesh, order);
  const long long naturalFill = eliminationFill(mesh, natural);
  // The natural order of a box sweeps it plane by plane (a band of about a
  // plane's vertices); nested dissection must do clearly better (here 0.56
  // of it; the gap widens with the box).
  EXPECT_LT(4 * metisFill, 3 * naturalFill) << "METIS " << metisFill << ", natural " << naturalFill;
}

// The order is METIS's with its fixed seed: preparing the same rest twice
// gives the same factor, and so the same model.
TEST(InteriorOrdering, TheSameTetsAreOrderedTheSameEveryTime) {
  SKIP_WITHOUT_METIS();
  const BoundaryFirstMesh mesh = box(12);
  const int vertexCount = static_cast<int>(mesh.mesh.vertices.rows());
  const InteriorOrder first =
      metisInteriorOrder(mesh.mesh.tets, mesh.boundaryVertexCount, vertexCount);
  ASSERT_EQ(static_cast<int>(first.size()), vertexCount - mesh.boundaryVertexCount);
  for (int attempt = 0; attempt < 3; ++attempt) {
    EXPECT_EQ(metisInteriorOrder(mesh.mesh.tets, mesh.boundaryVertexCount, vertexCount), first);
  }
}

// The background order starts only for interiors of kMetisOnlyInteriorVertices
// or more and only when TBB may use a second thread (an interior without
// tets: METIS orders its isolated vertices at once).
TEST(InteriorOrdering, TheBackgroundOrderStartsForLargeInteriorsWhenASecondThreadIsAllowed) {
  SKIP_WITHOUT_METIS();
  const Tets none(0, 4);
  EXPECT_FALSE(metisInteriorOrderInBackground(none, 1, kMetisOnlyInteriorVertices).valid());
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_FALSE(metisInteriorOrderInBackground(none, 0, kMetisOnlyInteriorVertices).valid());
  }
  const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  const std::shared_future<InteriorOrder> order =
      metisInteriorOrderInBackground(none, 0, kMetisOnlyInteriorVertices);
  ASSERT_TRUE(order.valid());
  std::vector<int> sorted = order.get();
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(static_cast<int>(sorted.size()), kMetisOnlyInteriorVertices);
  for (int k = 0; k < kMetisOnlyInteriorVertices; ++k)
    ASSERT_EQ(sorted[static_cast<std::size_t>(k)], k);
}

TEST(InteriorOrdering, AnOrderIsExtendedByAtMostOneVertexInAHundredAfterIt) {
  std::vector<int> order(300);
  for (int k = 0; k < 300; ++k) order[static_cast<std::size_t>(k)] = 299 - k;
  EXPECT_EQ(extendedInteriorOrder(order, 300), order);
  std::vector<int> appended = order;
  appended.insert(appended.end(), {300, 301, 302});
  EXPECT_EQ(extendedInteriorOrder(order, 303), appended);
  EXPECT_TRUE(extendedInteriorOrder(order, 304).empty());  // 4 appended to 300
  EXPECT_TRUE(extendedInteriorOrder(order, 299).empty());  // more ordered than there are
  EXPECT_TRUE(extendedInteriorOrder({}, 10).empty());
  std::vector<int> repeated = order;
  repeated[0] = repeated[1];
  EXPECT_TRUE(extendedInteriorOrder(repeated, 300).empty());
  std::vector<int> outOfRange = order;
  outOfRange[0] = 300;
  EXPECT_TRUE(extendedInteriorOrder(outOfRange, 300).empty());
}

// A builder on a refined box given the order of the box before the split
// (the refined mesh's new vertices then come last) places a twisted example
// as a builder that orders the refined interior itself.
TEST(InteriorOrdering, ABuilderGivenTheOrderOfTheMeshItRefinesSolvesTheSame) {
  SKIP_WITHOUT_METIS();
  const BoundaryFirstMesh mesh = box(9);
  const int surface = mesh.boundaryVertexCount;
  const int vertexCount = static_cast<int>(mesh.mesh.vertices.rows());
  const InteriorOrder order = metisInteriorOrder(mesh.mesh.tets, surface, vertexCount);
  ASSERT_FALSE(order.empty());
  // Split two interior edges between interior vertices: 2 of 514 appended.
  std::vector<Simplex> edges;
  for (Eigen::Index t = 0; t < mesh.mesh.tets.rows() && edges.size() < 2; ++t) {
    const int a = mesh.mesh.tets(t, 0);
    const int b = mesh.mesh.tets(t, 1);
    if (a < surface || b < surface) continue;
    const Simplex edge = makeSimplex({a, b});
    if (std::find(edges.begin(), edges.end(), edge) == edges.end()) edges.push_back(edge);
  }
  ASSERT_EQ(edges.size(), 2u);
  std::sort(edges.begin(), edges.end());
  const TetMesh refined = splitSimplices(mesh.mesh, edges);
  ASSERT_EQ(refined.vertices.rows(), vertexCount + 2);
  ASSERT_EQ(extendedInteriorOrder(order, vertexCount + 2 - surface).size(),
            static_cast<std::size_t>(vertexCount + 2 - surface));

  std::promise<InteriorOrder> promise;
  promise.set_value(order);
  const CompatibleTetBuilder given(refined, surface, {}, promise.get_future().share());
  const CompatibleTetBuilder own(refined, surface);
  const Vertices twisted =
      twistAboutAxis(refined.vertices.topRows(surface), Eigen::Vector3d(0.5, 0.5, 0.0),
                     Eigen::Vector3d::UnitZ(), kPi / 2, 1.0);
  const Vertices withGiven = given.harmonicExtension(twisted);
  const Vertices withOwn = own.harmonicExtension(twisted);
  EXPECT_LE((withGiven - withOwn).cwiseAbs().maxCoeff(), kSameSolveTolerance);
  // The twist moves the interior: the solves are not trivially equal.
  EXPECT_GT((withOwn - refined.vertices).cwiseAbs().maxCoeff(), 0.1);
}

}  // namespace
}  // namespace tetblend
