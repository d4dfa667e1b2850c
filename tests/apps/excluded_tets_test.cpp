// End to end: an example whose surface intersects itself (the limb bent 170
// degrees by linear blend skinning folds into its elbow) is accepted by
// prepare with one warning, its tets that cannot be embedded are recorded,
// listed by inspect and left out of the stitch; blends still interpolate the
// rest and every example. --strict refuses it instead, before any meshing.

#include "apps_test_support.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend::apps_test {
namespace {

// The promise: unit weights reproduce each example at the surface to
// 1e-9 of the bounding-box diagonal (the stitch is a least-squares solve of
// a compatible field; round-off is ~1e-13 of the size on this 0.5 k-tet mesh).
constexpr double kInterpolationRelTol = 1e-9;

class ExcludedTets : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    makeSamples(dir_);
    examples_ = {"limb_dqs.obj", "limb_lbs170.obj"};
  }
  std::vector<std::string> prepareArgs(const fs::path& model) const {
    std::vector<std::string> args = {"prepare", (dir_ / "limb_rest.obj").string()};
    for (const std::string& e : examples_) args.push_back((dir_ / e).string());
    args.insert(args.end(), {"-o", model.string()});
    return args;
  }
  fs::path dir_;
  std::vector<std::string> examples_;
};

TEST_F(ExcludedTets, SelfIntersectingExampleIsReportedNotRefused) {
  const fs::path model = dir_ / "limb.tbm";
  const RunResult r = tetblend(prepareArgs(model), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  // One warning line, naming the example and why.
  std::size_t warnings = 0;
  for (std::size_t at = r.err.find("tetblend: warning: "); at != std::string::npos;
       at = r.err.find("tetblend: warning: ", at + 1)) {
    ++warnings;
  }
  EXPECT_EQ(warnings, 1u) << r.err;
  EXPECT_NE(r.err.find("limb_lbs170.obj: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("intersects itself"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("worst volume ratio -"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("limb_dqs.obj"), std::string::npos) << r.err;

  const RunResult inspect = tetblend({"inspect", model.string()}, dir_);
  ASSERT_EQ(inspect.code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find("excluded from the stitch: "), std::string::npos) << inspect.out;
}

TEST_F(ExcludedTets, BlendsStillInterpolateTheRestAndEveryExample) {
  const fs::path model = dir_ / "limb.tbm";
  ASSERT_EQ(tetblend(prepareArgs(model), dir_).code, 0);
  const SurfaceMesh rest = readSurface((dir_ / "limb_rest.obj").string());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,0", "limb_rest.obj"}, {"1,0", "limb_dqs.obj"}, {"0,1", "limb_lbs170.obj"}};
  for (const std::string method : {"kaji", "liebodies", "dq", "linear", "vertex-linear"}) {
    for (const auto& [weights, expected] : cases) {
      SCOPED_TRACE(method + " at " + weights);
      const fs::path out =
          dir_ / (method + "_" + weights.substr(0, 1) + weights.substr(2) + ".vtu");
      const RunResult r = tetblend(
          {"blend", model.string(), "-w", weights, "--method", method, "-o", out.string()}, dir_);
      ASSERT_EQ(r.code, 0) << r.err;
      const SurfaceMesh target = readSurface((dir_ / expected).string());
      const Vertices surface = pointsOf(readVtp(fs::path(out).replace_extension(".vtp")));
      EXPECT_LT(maxDistance(surface, target.vertices),
                kInterpolationRelTol * boundingBoxDiagonal(target.vertices));
      const auto vtu = readVtu(out);
      vtkDataArray* excluded = vtu->GetCellData()->GetArray("excluded");
      ASSERT_NE(excluded, nullptr);
      double count = 0.0;
      for (vtkIdType j = 0; j < excluded->GetNumberOfTuples(); ++j) count += excluded->GetTuple1(j);
      EXPECT_GT(count, 0.0);
    }
  }
}

// At the self-intersecting example's unit weight its excluded tets are
// inverted (the fold). blend's warning says how many of the inverted tets
// are excluded ones, the same count as the .vtu's two cell arrays, and does
// not call weights in [0, 1] an extrapolation.
TEST_F(ExcludedTets, BlendWarningCountsTheInvertedTetsLeftOutOfTheStitch) {
  const fs::path model = dir_ / "limb.tbm";
  ASSERT_EQ(tetblend(prepareArgs(model), dir_).code, 0);
  const fs::path out = dir_ / "folded.vtu";
  const RunResult r = tetblend({"blend", model.string(), "-w", "0,1", "-o", out.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto vtu = readVtu(out);
  vtkDataArray* inverted = vtu->GetCellData()->GetArray("inverted");
  vtkDataArray* excluded = vtu->GetCellData()->GetArray("excluded");
  ASSERT_NE(inverted, nullptr);
  ASSERT_NE(excluded, nullptr);
  int invertedCount = 0, invertedExcluded = 0;
  for (vtkIdType j = 0; j < inverted->GetNumberOfTuples(); ++j) {
    if (inverted->GetTuple1(j) != 1.0) continue;
    ++invertedCount;
    if (excluded->GetTuple1(j) == 1.0) ++invertedExcluded;
  }
  ASSERT_GT(invertedExcluded, 0) << "the fold inverts no excluded tet at its own weight";
  EXPECT_NE(
      r.err.find(std::to_string(invertedCount) + " of " + std::to_string(vtu->GetNumberOfCells()) +
                 " tets are inverted at weights 0,1"),
      std::string::npos)
      << r.err;
  EXPECT_NE(
      r.err.find("; " + std::to_string(invertedExcluded) + " of them are left out of the stitch"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("extrapolate"), std::string::npos) << r.err;
}

TEST_F(ExcludedTets, StrictRefusesWithOneLineAndNoFile) {
  std::vector<std::string> args = prepareArgs(dir_ / "strict.tbm");
  args.push_back("--strict");
  const std::vector<std::string> before = listDir(dir_);
  const RunResult r = tetblend(args, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("limb_lbs170.obj: its surface intersects itself at "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--strict"), std::string::npos) << r.err;
  EXPECT_EQ(listDir(dir_), before);
}

TEST_F(ExcludedTets, CleanExamplesExcludeNothing) {
  examples_ = {"limb_dqs.obj", "limb_lbs.obj"};
  const fs::path model = dir_ / "clean.tbm";
  const RunResult r = tetblend(prepareArgs(model), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const RunResult inspect = tetblend({"inspect", model.string()}, dir_);
  EXPECT_EQ(inspect.out.find("excluded"), std::string::npos) << inspect.out;
}

TEST_F(ExcludedTets, AnExampleEqualToTheRestIsWarnedAbout) {
  examples_ = {"limb_dqs.obj", "limb_rest.obj"};
  const RunResult r = tetblend(prepareArgs(dir_ / "same.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("tetblend: warning: " + (dir_ / "limb_rest.obj").string() +
                       ": every vertex equals the rest's"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace tetblend::apps_test
