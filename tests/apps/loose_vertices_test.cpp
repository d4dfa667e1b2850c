// End to end: a rest and examples with vertices that no face uses (an
// exporter's stray points, first and in the middle of the vertex list; the
// last one used only by a face that repeats a vertex, as a triangle strip
// leaves) are prepared, with TetGen and tetrised; the blended surfaces keep
// every input vertex and face: the faces' vertices reproduce the rest and
// each example, and the loose vertices follow the examples linearly.

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

// A loose vertex is the blend (1 - w) rest + w example of coordinates below
// 10, written to the .vtp as doubles: a few ulps of 10 (~2e-15) apart.
constexpr double kLinearBlendTolerance = 1e-12;

// Where the stray vertices go in the vertex list, and the rest's and the
// example's positions of each (away from the bar, moved by the example).
const std::vector<int>& strayIndices() {
  static const std::vector<int> indices{0, 1, 40};
  return indices;
}

// `mesh` with the stray vertices inserted at strayIndices() (the faces
// renumbered to keep their corners); stray i at `base` + i * `step`.
SurfaceMesh withStrayVertices(const SurfaceMesh& mesh, const Eigen::RowVector3d& base,
                              const Eigen::RowVector3d& step) {
  const auto total = mesh.vertices.rows() + static_cast<Eigen::Index>(strayIndices().size());
  SurfaceMesh out;
  out.vertices.resize(total, 3);
  std::vector<int> newIndex;
  std::size_t stray = 0;
  for (Eigen::Index row = 0; row < total; ++row) {
    if (stray < strayIndices().size() && strayIndices()[stray] == row) {
      out.vertices.row(row) = base + static_cast<double>(stray) * step;
      ++stray;
    } else {
      out.vertices.row(row) = mesh.vertices.row(static_cast<Eigen::Index>(newIndex.size()));
      newIndex.push_back(static_cast<int>(row));
    }
  }
  out.triangles.resize(mesh.triangles.rows() + 1, 3);
  out.triangles.topRows(mesh.triangles.rows()) =
      mesh.triangles.unaryExpr([&](int v) { return newIndex[v]; });
  // A strip's degenerate face: the last stray vertex twice and a bar vertex.
  out.triangles.bottomRows(1) << strayIndices().back(), strayIndices().back(), newIndex[0];
  return out;
}

class LooseVertices : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    makeSamples(dir_);
    rest_ = withStrayVertices(readSurface((dir_ / "bar_rest.obj").string()),
                              Eigen::RowVector3d(5, 0, 0), Eigen::RowVector3d(0, 1, 0));
    twist_ = withStrayVertices(readSurface((dir_ / "bar_twist4pi.obj").string()),
                               Eigen::RowVector3d(6, 2, 1), Eigen::RowVector3d(0, 0, 1));
    writeSurface((dir_ / "rest.obj").string(), rest_);
    writeSurface((dir_ / "twist.obj").string(), twist_);
  }
  fs::path dir_;
  SurfaceMesh rest_, twist_;
};

TEST_P(LooseVertices, ArePreparedAndFollowTheExamplesLinearly) {
  std::vector<std::string> prepare{"prepare", (dir_ / "rest.obj").string(),
                                   (dir_ / "twist.obj").string(), "-o", (dir_ / "m.tbm").string()};
  if (GetParam()) prepare.push_back("--tetrise");
  const RunResult prepared = tetblend(prepare, dir_);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("3 vertices are used by no face (first: vertex 0)"),
            std::string::npos)
      << prepared.err;
  EXPECT_NE(prepared.err.find("1 face repeats a vertex (first: face " +
                              std::to_string(rest_.triangles.rows() - 1) + ")"),
            std::string::npos)
      << prepared.err;
  for (const double w : {0.0, 0.5, 1.0}) {
    const fs::path out = dir_ / ("w" + std::to_string(w) + ".vtp");
    const RunResult r = tetblend({"blend", (dir_ / "m.tbm").string(), "-w", std::to_string(w), "-o",
                                  out.string(), "--quiet"},
                                 dir_);
    ASSERT_EQ(r.code, 0) << r.err;
    const Vertices blended = pointsOf(readVtp(out));
    ASSERT_EQ(blended.rows(), rest_.vertices.rows());
    EXPECT_EQ(readVtp(out)->GetNumberOfCells(), rest_.triangles.rows());
    // Every vertex: a face's vertex exactly at the rest (w 0) and the
    // example (w 1) up to the stitch's round-off; a loose one at the linear
    // blend (round-off of one multiply-add).
    const Vertices linear = (1.0 - w) * rest_.vertices + w * twist_.vertices;
    for (int v : strayIndices()) {
      EXPECT_LT((blended.row(v) - linear.row(v)).norm(), kLinearBlendTolerance)
          << "vertex " << v << " at " << w;
    }
    if (w != 0.5) {
      EXPECT_LT(maxDistance(blended, linear), kInterpolationTolerance) << w;
    }
  }
  const RunResult inspected = tetblend({"inspect", (dir_ / "m.tbm").string()}, dir_);
  EXPECT_NE(inspected.out.find("3 used by no face"), std::string::npos) << inspected.out;
}

INSTANTIATE_TEST_SUITE_P(TetGenAndTetrised, LooseVertices, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return std::string(info.param ? "Tetrised" : "TetGen");
                         });

}  // namespace
}  // namespace tetblend::apps_test
