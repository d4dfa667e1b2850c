// tetblend batch: jobs in parallel, a failing job reported while the others
// are written, resume skipping finished jobs (also after a real kill -9),
// summary and collection files.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <set>
#include <thread>

#include "apps_test_support.h"
#include "test_seed.h"

extern char** environ;

namespace tetblend::apps_test {
namespace {

using nlohmann::json;

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
  fs::path writeSpec(const json& jobs, const std::string& outputDir = "out") const {
    const json spec{
        {"model", "bar.tbm"}, {"output_dir", outputDir}, {"threads", 2}, {"jobs", jobs}};
    const fs::path path = dir_ / ("spec_" + outputDir + ".json");
    std::ofstream(path) << spec.dump(2);
    return path;
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
  EXPECT_NEAR(s["jobs"][0]["quality"]["min_volume_ratio"].get<double>(), 1.0,
              kRestQualityTolerance);
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

  // The first line says what runs, what is skipped and why, and where.
  const std::string into = ", writing into " + (fs::absolute(dir_) / "out").string() + "\n";
  RunResult r = tetblend({"batch", spec.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 0 of 2 jobs to run (2 done by an earlier run: same "
                        "model file, method, weights and options, files present)" + into, 0),
            0u)
      << r.out;
  json s = summary();
  EXPECT_TRUE(s["jobs"][0]["skipped_this_run"].get<bool>());
  EXPECT_TRUE(s["jobs"][1]["skipped_this_run"].get<bool>());
  EXPECT_EQ(fs::last_write_time(dir_ / "out" / "a.vtu"), timeA);
  EXPECT_TRUE(s["jobs"][0].contains("quality"));  // carried over from the first run

  jobs[1]["weights"] = {0, 0.5};
  spec = writeSpec(jobs);
  r = tetblend({"batch", spec.string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 1 of 2 jobs to run (1 done by an earlier run", 0), 0u)
      << r.out;
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

/// Starts `program` with `args` as a child process (posix_spawn), its stdin,
/// stdout and stderr on /dev/null; returns its pid, -1 if it did not start.
pid_t startProgram(const std::string& program, const std::vector<std::string>& args) {
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO})
    posix_spawn_file_actions_addopen(&actions, fd, "/dev/null",
                                     fd == STDIN_FILENO ? O_RDONLY : O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

/// Names of the jobs a batch journal records as finished: its lines that
/// parse, as the resumed run reads them (a line cut by the kill names none;
/// a journal not yet written, none).
std::set<std::string> journaledJobs(const fs::path& journal) {
  std::set<std::string> names;
  std::istringstream text(slurp(journal));
  for (std::string line; std::getline(text, line);) {
    const json record = json::parse(line, nullptr, false);
    if (!record.is_discarded()) names.insert(record["name"].get<std::string>());
  }
  return names;
}

/// A batch of kJobCount blends killed with SIGKILL at chosen moments, each in
/// its own output directory, then re-run, and compared with an uninterrupted
/// run in "reference".
class KilledBatch : public BatchCommand {
 protected:
  // Enough blends that the kills at 0, 1 and half the journal lines land
  // with jobs still to do; few enough that the test takes seconds.
  static constexpr std::size_t kJobCount = 16;
  // Short beside one blend, so the kill lands close to the moment polled for.
  static constexpr std::chrono::milliseconds kPollInterval{1};

  static json jobs() {
    json list = json::array();
    for (std::size_t i = 0; i < kJobCount; ++i) {
      const double t = static_cast<double>(i) / kJobCount;
      list.push_back({{"name", "job" + std::to_string(i)}, {"weights", {t, 1.0 - t}}});
    }
    return list;
  }

  fs::path journal(const std::string& outputDir) const {
    return dir_ / outputDir / ".tetblend-batch.journal";
  }

  /// True once the journal of `outputDir` exists and holds `lines` whole lines.
  std::function<bool()> journalHolds(const std::string& outputDir, std::size_t lines) const {
    return [path = journal(outputDir), lines] {
      if (!fs::exists(path)) return false;
      const std::string text = slurp(path);
      return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) >= lines;
    };
  }

  /// Starts the batch into `outputDir`, polls `moment` and sends SIGKILL once
  /// it holds. Returns whether the kill ended the run (false: the batch ended
  /// first; that fails the test unless `mayFinishFirst`).
  bool killWhen(const std::string& outputDir, const std::function<bool()>& moment,
                bool mayFinishFirst = false) const {
    const pid_t pid = startProgram(TETBLEND_EXE, {"batch", writeSpec(jobs(), outputDir).string()});
    EXPECT_GT(pid, 0) << "cannot start " << TETBLEND_EXE;
    if (pid <= 0) return false;
    int status = 0;
    while (!moment()) {
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        EXPECT_TRUE(mayFinishFirst) << "the batch ended before the kill, status " << status;
        return false;
      }
      std::this_thread::sleep_for(kPollInterval);
    }
    ::kill(pid, SIGKILL);
    EXPECT_EQ(::waitpid(pid, &status, 0), pid);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  }

  /// Re-runs the killed batch of `outputDir` to completion and checks that it
  /// skips exactly the jobs `finished` before the kill, redoes the others, and
  /// leaves the outputs of an uninterrupted run, byte for byte.
  void expectResumeCompletes(const std::string& outputDir,
                             const std::set<std::string>& finished) const {
    const fs::path out = dir_ / outputDir;
    const RunResult r = tetblend({"batch", writeSpec(jobs(), outputDir).string()}, dir_);
    ASSERT_EQ(r.code, 0) << r.err;
    const json s = json::parse(slurp(out / "summary.json"));
    ASSERT_EQ(s["jobs"].size(), kJobCount);
    for (const json& job : s["jobs"]) {
      const std::string name = job["name"].get<std::string>();
      EXPECT_EQ(job["status"], "done") << name;
      EXPECT_EQ(job["skipped_this_run"].get<bool>(), finished.count(name) == 1) << name;
      for (const char* extension : {".vtu", ".vtp"}) {
        const std::string file = name + extension;
        ASSERT_TRUE(fs::exists(out / file)) << file;
        EXPECT_TRUE(slurp(out / file) == slurp(dir_ / "reference" / file))
            << file << " differs from the uninterrupted run's";
      }
    }
    const auto rows = parseCsv(slurp(out / "summary.csv"));
    ASSERT_EQ(rows.size(), kJobCount + 1);  // header + jobs
    for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i][2], "done") << rows[i][0];
    const std::regex temporary(R"(\..+\.[0-9]+\.tmp)");  // writeFileAtomically's
    for (const std::string& name : listDir(out))
      EXPECT_FALSE(std::regex_match(name, temporary)) << name << " was left behind";
  }
};

// A real kill -9 (not a simulated one) at a job boundary or anywhere: the
// re-run redoes only the jobs the journal does not hold, and the result is
// the uninterrupted run's.
TEST_F(KilledBatch, ResumeAfterKill9RedoesOnlyUnfinishedJobsAndMatchesAnUninterruptedRun) {
  const auto start = std::chrono::steady_clock::now();
  const RunResult reference = tetblend({"batch", writeSpec(jobs(), "reference").string()}, dir_);
  ASSERT_EQ(reference.code, 0) << reference.err;
  const std::chrono::duration<double> runTime = std::chrono::steady_clock::now() - start;

  for (const std::size_t lines : {std::size_t{0}, std::size_t{1}, kJobCount / 2}) {
    const std::string outputDir = "killed_at_" + std::to_string(lines);
    SCOPED_TRACE(outputDir);
    EXPECT_TRUE(killWhen(outputDir, journalHolds(outputDir, lines)));
    const std::set<std::string> finished = journaledJobs(journal(outputDir));
    EXPECT_GE(finished.size(), lines);
    expectResumeCompletes(outputDir, finished);
  }

  // Any moment of a run, the start and the writes inside a job included.
  std::mt19937 rng(test_seed::seedFor(
      ::testing::UnitTest::GetInstance()->current_test_info()->name(), 20240917u));
  const double delay = test_seed::uniform(rng, 0.0, runTime.count());
  SCOPED_TRACE("killed " + std::to_string(delay) + " s after the start");
  const auto killAt = std::chrono::steady_clock::now() + std::chrono::duration<double>(delay);
  killWhen("killed_at_random", [killAt] { return std::chrono::steady_clock::now() >= killAt; },
           true);
  expectResumeCompletes("killed_at_random", journaledJobs(journal("killed_at_random")));
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
