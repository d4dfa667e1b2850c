// What `tetblend blend` writes on request: --quality-arrays all|none|a,b
// gives exactly the cell arrays asked for, -o OUT.vtp the surface alone (the
// .vtu run's surface, bit for bit), and bad values one error line and no
// files.

#include <set>

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using Names = std::set<std::string>;


/// Every value of array `name` of `a` and `b`, compared exactly (same blend,
/// same computation: no tolerance).
void expectSameArray(vtkDataArray* a, vtkDataArray* b) {
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i) {
    const double x = a->GetVariantValue(i).ToDouble(), y = b->GetVariantValue(i).ToDouble();
    ASSERT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << a->GetName() << "[" << i << "]";
  }
}

class BlendOutputChoice : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
  }
  RunResult blend(const std::string& output, const std::vector<std::string>& extra) const {
    std::vector<std::string> args{"blend", model_.string(),         "-w", "0.3,0.4",
                                  "-o",    (dir_ / output).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return tetblend(args, dir_);
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(BlendOutputChoice, EachQualityArrayChoiceWritesExactlyThoseArrays) {
  ASSERT_EQ(blend("default.vtu", {}).code, 0);
  const auto full = readVtu(dir_ / "default.vtu");
  const Names all{"volume_ratio", "inverted", "distortion", "rotation_angle", "target_residual"};
  EXPECT_EQ(cellArrayNames(full), all);  // the bar has no excluded tets
  const struct {
    std::string choice;
    Names expected;
  } cases[] = {{"all", all},
               {"none", {}},
               {"volume_ratio", {"volume_ratio"}},
               {"rotation_angle,inverted", {"inverted", "rotation_angle"}},
               {"target_residual,distortion,target_residual", {"distortion", "target_residual"}}};
  for (const auto& c : cases) {
    SCOPED_TRACE("--quality-arrays " + c.choice);
    const RunResult r = blend("c.vtu", {"--quality-arrays", c.choice});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto vtu = readVtu(dir_ / "c.vtu");
    EXPECT_EQ(cellArrayNames(vtu), c.expected);
    for (const std::string& name : c.expected)
      expectSameArray(vtu->GetCellData()->GetArray(name.c_str()),
                      full->GetCellData()->GetArray(name.c_str()));
    EXPECT_NE(vtu->GetPointData()->GetArray("displacement"), nullptr);
    EXPECT_EQ(pointsOf(vtu), pointsOf(full));
  }
}

TEST_F(BlendOutputChoice, VtpOutputIsTheSurfaceOfTheVtuRunAndNothingElse) {
  ASSERT_EQ(blend("full.vtu", {}).code, 0);
  const std::vector<std::string> before = listDir(dir_);
  const RunResult r = blend("surface.vtp", {"--surface-format", "obj"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> expected = before;
  expected.push_back("surface.obj");
  expected.push_back("surface.vtp");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(listDir(dir_), expected);  // no surface.vtu

  const auto surface = readVtp(dir_ / "surface.vtp");
  const auto fullSurface = readVtp(dir_ / "full.vtp");
  const Eigen::Index ns = readSurface((dir_ / "bar_rest.obj").string()).vertices.rows();
  ASSERT_EQ(surface->GetNumberOfPoints(), ns);
  EXPECT_EQ(pointsOf(surface), pointsOf(readVtu(dir_ / "full.vtu")).topRows(ns));  // bit for bit
  EXPECT_EQ(pointsOf(surface), pointsOf(fullSurface));
  EXPECT_EQ(surface->GetNumberOfPolys(), fullSurface->GetNumberOfPolys());
  for (const char* name : {"displacement", "input_vertex_index"})
    expectSameArray(surface->GetPointData()->GetArray(name),
                    fullSurface->GetPointData()->GetArray(name));
  EXPECT_EQ(surface->GetCellData()->GetNumberOfArrays(), 0);
  EXPECT_EQ(readSurface((dir_ / "surface.obj").string()).vertices.rows(), ns);
}

TEST_F(BlendOutputChoice, BadChoicesGiveOneLineAndNoFiles) {
  const std::vector<std::string> before = listDir(dir_);
  const struct {
    std::string output;
    std::vector<std::string> extra;
    std::string message;
  } cases[] = {
      {"x.vtu", {"--quality-arrays", "volume"}, "unknown quality array 'volume'"},
      {"x.vtu", {"--quality-arrays", ""}, "--quality-arrays: empty"},
      {"x.vtu", {"--quality-arrays", "inverted,"}, "an empty array name in 'inverted,'"},
      {"x.vtu", {"--quality-arrays", "inverted,,distortion"}, "an empty array name"},
      {"x.vtu", {"--quality-arrays", "excluded"}, "the model has no excluded tets"},
      {"x.vtu",
       {"--quality-arrays", "target_residual", "--method", "vertex-linear"},
       "vertex-linear has no per-tet targets"},
      {"x.vtp", {"--quality-arrays", "inverted"}, "writes the surface only"},
      {"x.obj", {}, "must be a .vtu file"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("-o " + c.output + " " + (c.extra.empty() ? "" : c.extra[1]));
    const RunResult r = blend(c.output, c.extra);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(listDir(dir_), before);
  }
}

TEST_F(BlendOutputChoice, SeriesShareTheQualityArraysOption) {
  const RunResult r = tetblend({"variations", model_.string(), "--count", "2", "--seed", "3",
                                "--quality-arrays", "volume_ratio", "-o", (dir_ / "v").string()},
                               dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"variation_000.vtu", "variation_001.vtu"})
    EXPECT_EQ(cellArrayNames(readVtu(dir_ / "v" / name)), Names{"volume_ratio"}) << name;
}

}  // namespace
}  // namespace tetblend::apps_test
