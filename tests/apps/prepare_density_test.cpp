// prepare's default mesh density follows the surface: TetGen's quality bound
// alone grades the interior from the surface's edge lengths inwards. The old
// default (one volume bound: a regular tet of the mean surface edge) filled a
// finely tessellated surface with uniformly small tets (the 26k-vertex
// armadillo: 1.34 M tets instead of 134 k).

#include "apps_test_support.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

// A graded fill of a closed surface needs about as many tets as it has
// surface triangles (each boundary face is one tet's face, and the interior
// grows coarser inwards); the uniform fill of the bar sample at its mean edge
// length needs several times more. Two tets per triangle separates the two.
constexpr double kGradedTetsPerTriangle = 2.0;

TEST(PrepareDensity, DefaultGradesFromTheSurface) {
  const fs::path dir = scratchDir();
  const fs::path model = prepareBar(dir);
  const ModelData m = readModelFile(model.string());
  const double triangles = static_cast<double>(m.surfaceTriangles.rows());
  EXPECT_LE(static_cast<double>(m.rest.tets.rows()), kGradedTetsPerTriangle * triangles);

  // The old default, asked for explicitly, is several times finer.
  const SurfaceMesh rest = readSurface((dir / "bar_rest.obj").string());
  double edges = 0.0;
  for (Eigen::Index f = 0; f < rest.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      edges += (rest.vertices.row(rest.triangles(f, c)) -
                rest.vertices.row(rest.triangles(f, (c + 1) % 3)))
                   .norm();
    }
  }
  const double meanEdge = edges / (3.0 * triangles);
  const double uniformBound = meanEdge * meanEdge * meanEdge / (6.0 * std::sqrt(2.0));
  const fs::path uniform = dir / "uniform.tbm";
  const RunResult r =
      tetblend({"prepare", (dir / "bar_rest.obj").string(), (dir / "bar_twist4pi.obj").string(),
                "--max-volume", std::to_string(uniformBound), "-o", uniform.string()},
               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(static_cast<double>(readModelFile(uniform.string()).rest.tets.rows()),
            kGradedTetsPerTriangle * triangles);
}

}  // namespace
}  // namespace tetblend::apps_test
