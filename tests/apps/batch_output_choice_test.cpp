// What `tetblend batch` writes on request: summary.json paths that resolve
// from the spec's folder whatever the working directory, "surface_only" jobs
// (the .vtp alone), "quality_arrays", and one error line for bad values.

#include <nlohmann/json.hpp>
#include <set>

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using Names = std::set<std::string>;

using nlohmann::json;

/// The quality figures of the first job of dir/summary.json.
Names summaryFigures(const fs::path& dir) {
  const json summary = json::parse(slurp(dir / "summary.json"));
  Names names;
  for (const auto& item : summary["jobs"][0]["quality"].items()) names.insert(item.key());
  return names;
}

// The figures a summary always has: a determinant per tet gives them.
const Names kVolumeFigures{"inverted_tets", "max_volume_ratio", "min_volume_ratio"};

class BatchOutputChoice : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
    fs::create_directories(dir_ / "specs");
    fs::create_directories(dir_ / "elsewhere");
  }
  /// dir/specs/<name>.json over ../bar.tbm writing into specs/<name>_out.
  fs::path writeSpec(const std::string& name, const json& options) const {
    json spec{{"model", "../bar.tbm"},
              {"threads", 2},
              {"jobs", json::array({{{"name", "a"}, {"weights", {0.25, 0}}},
                                    {{"name", "b"}, {"weights", {0, 0.75}}}})}};
    spec.update(options);
    const fs::path path = dir_ / "specs" / (name + ".json");
    std::ofstream(path) << spec.dump(2);
    return path;
  }
  /// `tetblend batch specArgument` run from the working directory `cwd`.
  RunResult batchFrom(const fs::path& cwd, const std::string& specArgument) const {
    return runProgram("env", {"-C", cwd.string(), TETBLEND_EXE, "batch", specArgument}, dir_);
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(BatchOutputChoice, SummaryPathsResolveFromTheSpecFolder) {
  writeSpec("s", json::object());
  const fs::path specDir = dir_ / "specs";
  // From the spec's parent (spec given as specs/s.json), then from a sibling
  // folder (../specs/s.json, a re-run that skips both jobs): the same paths.
  const std::vector<std::pair<fs::path, std::string>> runs{{dir_, "specs/s.json"},
                                                           {dir_ / "elsewhere", "../specs/s.json"}};
  for (const auto& [cwd, argument] : runs) {
    SCOPED_TRACE("from " + cwd.string());
    const RunResult r = batchFrom(cwd, argument);
    ASSERT_EQ(r.code, 0) << r.err;
    const json s = json::parse(slurp(specDir / "s_out" / "summary.json"));
    EXPECT_EQ(s["spec"], "s.json");
    EXPECT_EQ(s["model"], "../bar.tbm");
    EXPECT_TRUE(fs::equivalent(specDir / s["model"].get<std::string>(), model_));
    ASSERT_EQ(s["jobs"].size(), 2u);
    for (const json& job : s["jobs"]) {
      const std::string name = job["name"].get<std::string>();
      const std::vector<std::string> expected{"s_out/" + name + ".vtu", "s_out/" + name + ".vtp"};
      EXPECT_EQ(job["files"].get<std::vector<std::string>>(), expected);
      for (const std::string& f : expected) EXPECT_TRUE(fs::exists(specDir / f)) << f;
    }
  }
}

TEST_F(BatchOutputChoice, SurfaceOnlyJobsWriteTheSurfaceOfTheFullJobsAndNoVtu) {
  ASSERT_EQ(batchFrom(dir_, writeSpec("full", json::object()).string()).code, 0);
  const fs::path spec = writeSpec("surf", {{"surface_only", true}});
  RunResult r = batchFrom(dir_, spec.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path out = dir_ / "specs" / "surf_out";
  for (const std::string name : {"a", "b"}) {
    EXPECT_FALSE(fs::exists(out / (name + ".vtu"))) << name;
    EXPECT_EQ(pointsOf(readVtp(out / (name + ".vtp"))),
              pointsOf(readVtp(dir_ / "specs" / "full_out" / (name + ".vtp"))))
        << name;  // bit for bit
  }
  const std::string pvd = slurp(out / "batch.pvd");
  EXPECT_NE(pvd.find("\"a.vtp\""), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find(".vtu"), std::string::npos) << pvd;
  const json s = json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(s["jobs"][0]["files"], json::array({"surf_out/a.vtp"}));
  // No .vtu, so none of the costlier figures is computed.
  EXPECT_EQ(summaryFigures(out), kVolumeFigures);

  r = batchFrom(dir_, spec.string());  // a re-run finds the .vtp jobs done
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 0 of 2 jobs to run", 0), 0u) << r.out;
}

TEST_F(BatchOutputChoice, QualityArraysKeyChoosesTheCellArraysAndRerunsWhenChanged) {
  const Names distortion{"mean_distortion", "max_distortion"};
  Names all = kVolumeFigures;
  for (const char* n : {"mean_distortion", "max_distortion", "mean_rotation_angle",
                        "max_rotation_angle", "mean_target_residual", "max_target_residual"})
    all.insert(n);
  Names volumeAndDistortion = kVolumeFigures;
  volumeAndDistortion.insert(distortion.begin(), distortion.end());
  const struct {
    json value;
    Names expected;
    Names figures;  // of the summary: only those of written arrays
  } cases[] = {
      {"none", {}, kVolumeFigures},
      {json::array({"inverted", "volume_ratio"}), {"inverted", "volume_ratio"}, kVolumeFigures},
      {"distortion", {"distortion"}, volumeAndDistortion},
      {json::array(), {}, kVolumeFigures},
      {"all", {"volume_ratio", "inverted", "distortion", "rotation_angle", "target_residual"}, all},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("quality_arrays " + c.value.dump());
    const RunResult r = batchFrom(dir_, writeSpec("q", {{"quality_arrays", c.value}}).string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(cellArrayNames(readVtu(dir_ / "specs" / "q_out" / "a.vtu")), c.expected);
    EXPECT_EQ(summaryFigures(dir_ / "specs" / "q_out"), c.figures);
  }
  // The same choice written another way is the same fingerprint: nothing reruns.
  ASSERT_EQ(
      batchFrom(dir_, writeSpec("q", {{"quality_arrays", "inverted,volume_ratio"}}).string()).code,
      0);
  const RunResult r = batchFrom(
      dir_,
      writeSpec("q", {{"quality_arrays", json::array({"volume_ratio", "inverted"})}}).string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 0 of 2 jobs to run", 0), 0u) << r.out;
}

TEST_F(BatchOutputChoice, BadValuesAreOneLineAndWriteNothing) {
  const struct {
    json options;
    std::string message;
  } cases[] = {
      {{{"quality_arrays", "volume"}}, "unknown quality array 'volume'"},
      {{{"quality_arrays", 3}}, "\"quality_arrays\" is 3"},
      {{{"quality_arrays", json::array({"inverted", 3})}}, "lists 3: not a name"},
      {{{"quality_arrays", "inverted"}, {"surface_only", true}}, "writes no .vtu"},
      {{{"surface_only", "yes"}}, "bad entry"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options.dump());
    const RunResult r = batchFrom(dir_, writeSpec("bad", c.options).string());
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "specs" / "bad_out"));
  }
}

}  // namespace
}  // namespace tetblend::apps_test
