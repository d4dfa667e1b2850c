// End to end: rests with an edge that more than two faces share, which no
// tet mesh can bound as one solid. prepare splits the rest there into parts
// (manifoldRegions) and prepares them part by part: a fin on a body (one
// face on a body's edge) gets a tet of its own while the body keeps its
// interior; two bodies touching along an edge are each meshed on their own
// and share the rows of that edge's vertices. Blends give the rest at zero
// weights and each example at unit weights with kaji, liebodies and dq.

#include "posed_rest_fixture.h"
#include "test_surfaces.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

// An ellipsoid (an icosphere scaled by `radii`) centred at `centre`.
SurfaceMesh ellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii) {
  SurfaceMesh body = testing_surfaces::icosphere(3);
  for (Eigen::Index i = 0; i < body.vertices.rows(); ++i) {
    body.vertices.row(i) =
        body.vertices.row(i).cwiseProduct(radii.transpose()) + centre.transpose();
  }
  return body;
}

// Per tet row, whether some tet uses it.
std::vector<char> usedRows(const ModelData& m) {
  std::vector<char> used(static_cast<std::size_t>(m.rest.vertices.rows()), 0);
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) used[static_cast<std::size_t>(m.rest.tets(t, c))] = 1;
  }
  return used;
}

class NonManifoldEdges : public PosedRest {};

// A body 4 by 1 by 1 and one face on its topmost edge, pointing outward
// (edge (a, b) then has three faces).
TEST_F(NonManifoldEdges, AFinGetsATetOfItsOwnAndTheBodyKeepsItsInterior) {
  SurfaceMesh rest = ellipsoid(Eigen::Vector3d::Zero(), Eigen::Vector3d(2.0, 0.5, 0.5));
  Eigen::Index top = 0;
  rest.vertices.col(2).maxCoeff(&top);
  Eigen::Index face = 0;
  while (rest.triangles(face, 0) != top) ++face;
  const int a = rest.triangles(face, 0), b = rest.triangles(face, 1);
  const Eigen::RowVector3d mid = 0.5 * (rest.vertices.row(a) + rest.vertices.row(b));
  const auto apex = static_cast<int>(rest.vertices.rows());
  rest.vertices.conservativeResize(apex + 1, 3);
  rest.vertices.row(apex) = mid + Eigen::RowVector3d(0.0, 0.0, 0.4);
  rest.triangles.conservativeResize(rest.triangles.rows() + 1, 3);
  rest.triangles.row(rest.triangles.rows() - 1) << a, b, apex;
  writePoses(rest);

  const RunResult r = tetblend(prepareArgs("fin.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("1 of its parts (its components, split at 1 edge of more than two "
                       "faces; first: the one of face " +
                       std::to_string(rest.triangles.rows() - 1) + ")"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("each of their 1 faces gets a tet of its own"), std::string::npos) << r.err;
  const ModelData m = readModelFile(path("fin.tbm"));
  EXPECT_TRUE(m.inputVertices(m.rest.vertices) == rest.vertices);
  // The body's interior vertices and the fin's apex row come after the
  // surface: more than one row more means the body has an interior.
  EXPECT_GT(m.rest.vertices.rows(), rest.vertices.rows() + 1);
  EXPECT_TRUE(m.excludedTets.empty());
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    EXPECT_GT(tetSignedVolume(m.rest.vertices, m.rest.tets.row(t)), 0.0) << "tet " << t;
    for (const Vertices& example : m.examples) {
      EXPECT_GT(tetSignedVolume(example, m.rest.tets.row(t)), 0.0) << "tet " << t;
    }
  }
  expectTheKeysBack("fin.tbm");
}

// Two ellipsoids touching along one edge: the second is the first reflected
// through the midpoint of its rightmost edge (faces reversed), so a plane
// through that edge parts them and the edge has four faces.
TEST_F(NonManifoldEdges, BodiesTouchingAlongAnEdgeAreEachMeshedOnTheirOwn) {
  const SurfaceMesh left =
      ellipsoid(Eigen::Vector3d(-1.0, 0.0, 0.0), Eigen::Vector3d(0.9, 0.5, 0.4));
  int a = -1, b = -1;
  double rightmost = -1e300;
  for (Eigen::Index f = 0; f < left.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int u = left.triangles(f, c), v = left.triangles(f, (c + 1) % 3);
      const double x = left.vertices(u, 0) + left.vertices(v, 0);
      if (x > rightmost) {
        rightmost = x;
        a = u;
        b = v;
      }
    }
  }
  const Eigen::RowVector3d mid = 0.5 * (left.vertices.row(a) + left.vertices.row(b));
  // The reflection of vertex a lands on b and that of b on a: the right
  // body uses the left's rows there and has no copies of them.
  const auto nl = static_cast<int>(left.vertices.rows());
  SurfaceMesh rest{Vertices(2 * nl - 2, 3), Triangles(2 * left.triangles.rows(), 3)};
  rest.vertices.topRows(nl) = left.vertices;
  std::vector<int> rowOf(static_cast<std::size_t>(nl));
  int next = nl;
  for (int v = 0; v < nl; ++v) {
    if (v == a || v == b) {
      rowOf[static_cast<std::size_t>(v)] = v == a ? b : a;
      continue;
    }
    rowOf[static_cast<std::size_t>(v)] = next;
    rest.vertices.row(next++) = 2.0 * mid - left.vertices.row(v);
  }
  rest.triangles.topRows(left.triangles.rows()) = left.triangles;
  for (Eigen::Index f = 0; f < left.triangles.rows(); ++f) {
    rest.triangles.row(left.triangles.rows() + f)
        << rowOf[static_cast<std::size_t>(left.triangles(f, 0))],
        rowOf[static_cast<std::size_t>(left.triangles(f, 2))],
        rowOf[static_cast<std::size_t>(left.triangles(f, 1))];
  }
  writePoses(rest);

  const RunResult r = tetblend(prepareArgs("touching.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("is shared by 4 faces"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("each of its 2 parts (its components, split at 1 edge of more than two "
                       "faces) is prepared on its own"),
            std::string::npos)
      << r.err;
  const ModelData m = readModelFile(path("touching.tbm"));
  EXPECT_TRUE(m.inputVertices(m.rest.vertices) == rest.vertices);
  EXPECT_GT(m.rest.vertices.rows(), rest.vertices.rows());  // interiors
  EXPECT_TRUE(m.excludedTets.empty());
  // The second body's own rows of the edge's two vertices are the only rows
  // in no tet: its tets use the first body's (model_join.h).
  const std::vector<char> used = usedRows(m);
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 2);
  // Both bodies' tets use the row of a: some of its tets lie left of the
  // reflection's plane (x of the edge's midpoint), some right of it.
  const int rowA = m.inputVertexRows.empty() ? a : m.inputVertexRows[static_cast<std::size_t>(a)];
  int leftOfA = 0, rightOfA = 0;
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    if ((m.rest.tets.row(t).array() != rowA).all()) continue;
    double x = 0.0;
    for (int c = 0; c < 4; ++c) x += 0.25 * m.rest.vertices(m.rest.tets(t, c), 0);
    ++(x < mid(0) ? leftOfA : rightOfA);
  }
  EXPECT_GT(leftOfA, 0);
  EXPECT_GT(rightOfA, 0);
  expectTheKeysBack("touching.tbm");
}

}  // namespace
}  // namespace tetblend::apps_test
