// tetblend batch: jobs in parallel, a failing job reported while the others
// are written, resume skipping finished jobs, summary and collection files.

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <thread>

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using nlohmann::json;
constexpr double kInterpolationTolerance = 1e-7 * 4.1;  // as in blend_test.cpp

/// Rows of RFC 4180 CSV text: fields split at commas outside double quotes, a
/// quoted field's "" read as one quote, rows ended by LF or CRLF outside quotes.
/// Independent of the writer in cmd_batch.cpp.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
    } else if (c == '\n' || (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
      if (c == '\r') ++i;
      row.push_back(field);
      field.clear();
      rows.push_back(row);
      row.clear();
    } else {
      field += c;
    }
  }
  EXPECT_FALSE(quoted) << "unterminated quoted field";
  if (!field.empty() || !row.empty()) {
    row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

class BatchCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
  }
  fs::path writeSpec(const json& jobs) const {
    const json spec{{"model", "bar.tbm"}, {"output_dir", "out"}, {"threads", 2}, {"jobs", jobs}};
    std::ofstream(dir_ / "spec.json") << spec.dump(2);
    return dir_ / "spec.json";
  }
  json summary() const { return json::parse(slurp(dir_ / "out" / "summary.json")); }
  /// A finished batch of two jobs, a and b, with their .vtu write times.
  struct TwoJobs {
    json jobs;
    fs::path spec;
    fs::file_time_type timeA, timeB;
  };
  void runTwoJobs(TwoJobs& run) const {
    run.jobs = json::array(
        {{{"name", "a"}, {"weights", {0.25, 0}}}, {{"name", "b"}, {"weights", {0, 0.75}}}});
    run.spec = writeSpec(run.jobs);
    ASSERT_EQ(tetblend({"batch", run.spec.string()}, dir_).code, 0);
    run.timeA = fs::last_write_time(dir_ / "out" / "a.vtu");
    run.timeB = fs::last_write_time(dir_ / "out" / "b.vtu");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // later writes get later times
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(BatchCommand, FailingJobIsReportedAndTheOthersAreWritten) {
  const fs::path spec = writeSpec(
      json::array({{{"name", "rest"}, {"weights", {0, 0}}},
                   {{"name", "bad"}, {"weights", {0.5}}},
                   {{"name", "bend"}, {"weights", {0, 1}}, {"method", "dq"}},
                   {{"name", "unknown"}, {"weights", {0, 1}}, {"method", "no-such-method"}}}));
  const RunResult r = tetblend({"batch", spec.string()}, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("2 of 4 jobs failed"), std::string::npos) << r.err;
  EXPECT_LT(maxDistance(pointsOf(readVtp(dir_ / "out" / "rest.vtp")),
                        readSurface((dir_ / "bar_rest.obj").string()).vertices),
            kInterpolationTolerance);
  EXPECT_LT(maxDistance(pointsOf(readVtp(dir_ / "out" / "bend.vtp")),
                        readSurface((dir_ / "bar_bend.obj").string()).vertices),
            kInterpolationTolerance);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "bad.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "unknown.vtu"));
  const json s = summary();
  ASSERT_EQ(s["jobs"].size(), 4u);
  EXPECT_EQ(s["jobs"][0]["status"], "done");
  EXPECT_EQ(s["jobs"][1]["status"], "failed");
  EXPECT_NE(s["jobs"][1]["error"].get<std::string>().find("weights"), std::string::npos);
  EXPECT_EQ(s["jobs"][3]["status"], "failed");
  EXPECT_DOUBLE_EQ(s["jobs"][0]["quality"]["inverted_tets"].get<double>(), 0.0);
  EXPECT_NEAR(s["jobs"][0]["quality"]["min_volume_ratio"].get<double>(), 1.0, 1e-6);
  const std::string csv = slurp(dir_ / "out" / "summary.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // header + 4 jobs
  const std::string pvd = slurp(dir_ / "out" / "batch.pvd");
  EXPECT_NE(pvd.find("rest.vtu"), std::string::npos);
  EXPECT_NE(pvd.find("bend.vtu"), std::string::npos);
  EXPECT_EQ(pvd.find("bad.vtu"), std::string::npos);
}

TEST_F(BatchCommand, SecondRunSkipsFinishedJobsAndRerunsEditedOnes) {
  TwoJobs run;
  ASSERT_NO_FATAL_FAILURE(runTwoJobs(run));
  json& jobs = run.jobs;
  fs::path& spec = run.spec;
  const auto timeA = run.timeA;
  const auto timeB = run.timeB;

  ASSERT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  json s = summary();
  EXPECT_TRUE(s["jobs"][0]["skipped_this_run"].get<bool>());
  EXPECT_TRUE(s["jobs"][1]["skipped_this_run"].get<bool>());
  EXPECT_EQ(fs::last_write_time(dir_ / "out" / "a.vtu"), timeA);
  EXPECT_TRUE(s["jobs"][0].contains("quality"));  // carried over from the first run

  jobs[1]["weights"] = {0, 0.5};
  spec = writeSpec(jobs);
  ASSERT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  s = summary();
  EXPECT_TRUE(s["jobs"][0]["skipped_this_run"].get<bool>());
  EXPECT_FALSE(s["jobs"][1]["skipped_this_run"].get<bool>());
  EXPECT_NE(fs::last_write_time(dir_ / "out" / "b.vtu"), timeB);

  fs::remove(dir_ / "out" / "a.vtp");  // a missing output reruns its job
  ASSERT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  EXPECT_FALSE(summary()["jobs"][0]["skipped_this_run"].get<bool>());
  EXPECT_TRUE(fs::exists(dir_ / "out" / "a.vtp"));
}

TEST_F(BatchCommand, SummaryCsvQuotesCommasAndQuotes) {
  const std::string method = "kaji, \"fast\"";  // an unknown method: its job fails
  const fs::path spec =
      writeSpec(json::array({{{"name", "rest"}, {"weights", {0, 0}}},
                             {{"name", "odd"}, {"weights", {0, 1}}, {"method", method}}}));
  expectOneLineError(tetblend({"batch", spec.string()}, dir_));
  const auto rows = parseCsv(slurp(dir_ / "out" / "summary.csv"));
  ASSERT_EQ(rows.size(), 3u);  // header + 2 jobs
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[0][0], "name");
  EXPECT_EQ(rows[0][1], "method");
  EXPECT_EQ(rows[2][0], "odd");
  EXPECT_EQ(rows[2][1], method);
  EXPECT_EQ(rows[2][2], "failed");
  EXPECT_EQ(rows[2].back(), summary()["jobs"][1]["error"].get<std::string>());
}

TEST_F(BatchCommand, SecondConcurrentRunIsRefused) {
  const fs::path spec = writeSpec(json::array({{{"name", "a"}, {"weights", {0.25, 0}}}}));
  fs::create_directories(dir_ / "out");
  const std::string lockPath = (dir_ / "out" / ".tetblend-batch.lock").string();
  const int fd = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as a running batch holds it
  const RunResult r = tetblend({"batch", spec.string()}, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find((dir_ / "out").string()), std::string::npos) << r.err;
  EXPECT_EQ(listDir(dir_ / "out"), std::vector<std::string>{".tetblend-batch.lock"});
  ::close(fd);  // the first run ends
  EXPECT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "a.vtu"));
}

TEST_F(BatchCommand, RunKilledBeforeTheSummaryKeepsItsFinishedJobs) {
  TwoJobs run;
  ASSERT_NO_FATAL_FAILURE(runTwoJobs(run));
  json& jobs = run.jobs;
  fs::path& spec = run.spec;
  const auto timeA = run.timeA;
  const auto timeB = run.timeB;

  // As after kill -9 before the end: no summary, the writer's temporaries left,
  // the journal's last line cut short.
  fs::remove(dir_ / "out" / "summary.json");
  fs::remove(dir_ / "out" / "summary.csv");
  std::ofstream(dir_ / "out" / ".b.vtp.1234567.tmp") << "partial";
  std::ofstream(dir_ / "out" / ".mine.txt.42.tmp") << "not a batch output";
  std::ofstream(dir_ / "out" / ".tetblend-batch.journal", std::ios::app)
      << "{\"name\": \"b\", \"fi";
  ASSERT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  json s = summary();
  ASSERT_EQ(s["jobs"].size(), 2u);
  for (const json& job : s["jobs"]) {
    EXPECT_EQ(job["status"], "done");
    EXPECT_TRUE(job["skipped_this_run"].get<bool>());
    EXPECT_DOUBLE_EQ(job["quality"]["inverted_tets"].get<double>(), 0.0);
  }
  EXPECT_EQ(fs::last_write_time(dir_ / "out" / "a.vtu"), timeA);
  EXPECT_EQ(fs::last_write_time(dir_ / "out" / "b.vtu"), timeB);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / ".b.vtp.1234567.tmp"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / ".mine.txt.42.tmp"));

  // A stale journal line (the spec's weights changed since) reruns its job.
  fs::remove(dir_ / "out" / "summary.json");
  jobs[1]["weights"] = {0, 0.5};
  spec = writeSpec(jobs);
  ASSERT_EQ(tetblend({"batch", spec.string()}, dir_).code, 0);
  s = summary();
  EXPECT_TRUE(s["jobs"][0]["skipped_this_run"].get<bool>());
  EXPECT_FALSE(s["jobs"][1]["skipped_this_run"].get<bool>());
  EXPECT_EQ(fs::last_write_time(dir_ / "out" / "a.vtu"), timeA);
  EXPECT_NE(fs::last_write_time(dir_ / "out" / "b.vtu"), timeB);
}

TEST_F(BatchCommand, BadSpecIsOneLineError) {
  std::ofstream(dir_ / "broken.json") << "{ \"model\": ";
  expectOneLineError(tetblend({"batch", (dir_ / "broken.json").string()}, dir_));
  const fs::path spec = writeSpec(
      json::array({{{"name", "x"}, {"weights", {0, 0}}}, {{"name", "x"}, {"weights", {0, 1}}}}));
  const RunResult r = tetblend({"batch", spec.string()}, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("earlier job"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
}  // namespace tetblend::apps_test
