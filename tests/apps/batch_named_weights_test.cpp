// A batch job's "weights" as an object of some examples' weights, keyed by
// name or 1-based index (batch_job_weights.h, named_weights.h), and a job's
// "method" alias: the files of the equivalent array / canonical name, byte
// for byte; a bad object fails its job alone.

#include <nlohmann/json.hpp>

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using nlohmann::json;

class BatchNamedWeights : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);  // examples 1 bar_twist4pi.obj, 2 bar_bend.obj
  }
  /// Runs a batch of `jobs` over the model into dir/out.
  RunResult runBatch(const json& jobs) const {
    const json spec{{"model", "bar.tbm"}, {"output_dir", "out"}, {"threads", 2}, {"jobs", jobs}};
    std::ofstream(dir_ / "spec.json") << spec.dump(2);
    return tetblend({"batch", (dir_ / "spec.json").string(), "--quiet"}, dir_);
  }
  json summary() const { return json::parse(slurp(dir_ / "out" / "summary.json")); }
  /// Both files of jobs `a` and `b` are byte for byte the same.
  void expectSameFiles(const std::string& a, const std::string& b) const {
    for (const std::string ext : {".vtu", ".vtp"}) {
      const std::string bytesA = slurp(dir_ / "out" / (a + ext));
      ASSERT_FALSE(bytesA.empty()) << a + ext;
      EXPECT_TRUE(bytesA == slurp(dir_ / "out" / (b + ext))) << a + ext << " differs from " << b;
    }
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(BatchNamedWeights, ObjectWeightsAndMethodAliasWriteTheFilesOfTheirTwins) {
  const RunResult r = runBatch(
      json::array({{{"name", "dense"}, {"weights", {0.3, 0.4}}},
                   {{"name", "named"}, {"weights", {{"bar_twist4pi", 0.3}, {"2", 0.4}}}},
                   {{"name", "dq"}, {"weights", {0, 0.5}}, {"method", "dq"}},
                   {{"name", "dqs"}, {"weights", {{"bar_bend", 0.5}}}, {"method", "dqs"}}}));
  ASSERT_EQ(r.code, 0) << r.err;
  expectSameFiles("dense", "named");
  expectSameFiles("dq", "dqs");
  const json s = summary();
  EXPECT_EQ(s["jobs"][1]["weights"], (json{{"bar_twist4pi", 0.3}, {"2", 0.4}}));
  EXPECT_EQ(s["jobs"][3]["method"], "dq");  // the alias is recorded by its name
  const std::string csv = slurp(dir_ / "out" / "summary.csv");
  EXPECT_NE(csv.find("named,kaji,done,2=0.4 bar_twist4pi=0.3,"), std::string::npos) << csv;
}

TEST_F(BatchNamedWeights, BadObjectsFailTheirJobAlone) {
  const struct {
    const char* name;
    json weights;
    std::string error;
  } bad[] = {
      {"unknown", {{"bar_bnd", 1}}, "\"weights\": \"bar_bnd\": no example is named 'bar_bnd'"},
      {"twice", {{"2", 0.1}, {"bar_bend", 0.2}}, "already has a weight, from \"weights\": \"2\""},
      {"range", {{"3", 1}}, "there is no example 3; the examples are numbered 1..2"},
      {"text", {{"bar_bend", "x"}}, "\"weights\": \"bar_bend\" is \"x\": not a number"},
      {"scalar", 0.5, "\"weights\" is 0.5; give an array of one number per example, or an object"},
  };
  json jobs = json::array({{{"name", "ok"}, {"weights", json::object()}}});
  for (const auto& b : bad) jobs.push_back({{"name", b.name}, {"weights", b.weights}});
  const RunResult r = runBatch(jobs);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("5 of 6 jobs failed"), std::string::npos) << r.err;
  const json s = summary();
  EXPECT_EQ(s["jobs"][0]["status"], "done");  // {}: every weight 0, the rest
  for (std::size_t i = 0; i < std::size(bad); ++i) {
    SCOPED_TRACE(bad[i].name);
    const json& job = s["jobs"][i + 1];
    EXPECT_EQ(job["status"], "failed");
    EXPECT_NE(job["error"].get<std::string>().find(bad[i].error), std::string::npos)
        << job["error"];
    EXPECT_FALSE(fs::exists(dir_ / "out" / (std::string(bad[i].name) + ".vtu")));
  }
}

}  // namespace
}  // namespace tetblend::apps_test
