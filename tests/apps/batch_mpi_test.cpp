// tetblend batch under mpirun (built only when CMake found MPI): the jobs
// split over two ranks give the same files, byte for byte, as one process;
// the summary's job list is the same apart from the seconds; a failing job is
// reported as in one process; resume works across runs with different rank
// counts.

#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>

#include "address_sanitizer.h"
#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using nlohmann::json;

class BatchMpi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // OpenMPI in a container, possibly as root: no cross-memory attach, no
    // refusal to run as root, shared memory and TCP transports only.
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    ::setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
    ::setenv("OMPI_MCA_btl", "self,vader,tcp", 1);
  }
  void SetUp() override {
    dir_ = scratchDir();
    prepareBar(dir_);
  }
  /// dir_/<folder>/spec.json over ../bar.tbm, output into dir_/<folder>/out.
  fs::path writeSpec(const std::string& folder, const json& jobs,
                     const json& extra = json::object()) const {
    json spec{{"model", "../bar.tbm"}, {"output_dir", "out"}, {"threads", 2}, {"jobs", jobs}};
    spec.update(extra);
    fs::create_directories(dir_ / folder);
    const fs::path path = dir_ / folder / "spec.json";
    std::ofstream(path) << spec.dump(2);
    return path;
  }
  static RunResult mpirun(int ranks, const fs::path& spec, const fs::path& scratch,
                          const std::vector<std::string>& options = {}) {
    std::vector<std::string> args{"-n", std::to_string(ranks), "--oversubscribe",
                                  "--allow-run-as-root", "--bind-to", "none"};
    // Under AddressSanitizer the ranks are still checked for memory errors,
    // but not for leaks: OpenMPI's components, unloaded at MPI_Finalize,
    // leave allocations LeakSanitizer can only attribute to "<unknown
    // module>" (no suppression can name them); the batch's own leaks are
    // checked by the one-process batch tests.
    if (test::kAddressSanitizer) {
      args.insert(args.end(), {"-x", "ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1"});
    }
    args.insert(args.end(), {TETBLEND_EXE, "batch", spec.string()});
    args.insert(args.end(), options.begin(), options.end());
    // A rank left waiting for work would hang the suite: 120 s at most.
    args.insert(args.begin(), {"--kill-after=5", "120", TETBLEND_MPIEXEC});
    return runProgram("timeout", args, scratch);
  }
  static json summaryWithoutSeconds(const fs::path& out) {
    json s = json::parse(slurp(out / "summary.json"));
    for (json& job : s["jobs"]) job.erase("seconds");
    return s;
  }
  /// summary.csv without its seconds column.
  static std::string csvWithoutSeconds(const fs::path& out) {
    std::istringstream in(slurp(out / "summary.csv"));
    std::string text, line;
    std::size_t column = 0;
    while (std::getline(in, line)) {
      std::vector<std::string> fields;
      std::stringstream cells(line);
      for (std::string f; std::getline(cells, f, ',');) fields.push_back(f);
      if (column == 0) {
        column = static_cast<std::size_t>(std::find(fields.begin(), fields.end(), "seconds") -
                                          fields.begin());
      }
      if (column < fields.size()) fields.erase(fields.begin() + static_cast<long>(column));
      for (const std::string& f : fields) text += f + ",";
      text += "\n";
    }
    return text;
  }
  /// The lines of a journal, its absolute paths' ".../one/out/",
  /// ".../two/out/" and ".../three/out/" all read as ".../out/".
  static std::multiset<std::string> lines(const fs::path& p) {
    std::istringstream in(slurp(p));
    std::multiset<std::string> set;
    for (std::string line; std::getline(in, line);) {
      for (const std::string folder : {"/one/out/", "/two/out/", "/three/out/"}) {
        for (std::size_t at = line.find(folder); at != std::string::npos; at = line.find(folder))
          line.replace(at, folder.size(), "/out/");
      }
      set.insert(line);
    }
    return set;
  }
  /// Every file of `a` and `b`: the same names; the job files, batch.pvd
  /// and the lock byte for byte; the journal the same lines (in the order
  /// the jobs ended); the summaries the same apart from the seconds.
  static void expectSameOutputs(const fs::path& a, const fs::path& b) {
    ASSERT_EQ(listDir(a), listDir(b));
    for (const std::string& name : listDir(a)) {
      if (name == "summary.json") {
        EXPECT_EQ(summaryWithoutSeconds(a), summaryWithoutSeconds(b));
      } else if (name == "summary.csv") {
        EXPECT_EQ(csvWithoutSeconds(a), csvWithoutSeconds(b));
      } else if (name == ".tetblend-batch.journal") {
        EXPECT_EQ(lines(a / name), lines(b / name));
      } else {
        EXPECT_TRUE(slurp(a / name) == slurp(b / name)) << name << " differs";
      }
    }
  }
  static json jobs() {
    json list = json::array();
    const double w[][2] = {{0, 0}, {0.25, 0}, {0, 0.75}, {0.5, 0.5}, {1, 0}, {0.1, 0.9}};
    for (int j = 0; j < 6; ++j) {
      json job{{"name", "j" + std::to_string(j)}, {"weights", {w[j][0], w[j][1]}}};
      if (j == 3) job["method"] = "dq";
      list.push_back(job);
    }
    return list;
  }
  fs::path dir_;
};

TEST_F(BatchMpi, TwoRanksWriteWhatOneProcessWrites) {
  json list = jobs();
  list.push_back({{"name", "bad"}, {"weights", {0.5}}});  // fails: one weight too few
  const json extra{{"surface_formats", {"obj"}}};
  const fs::path one = writeSpec("one", list, extra);
  const fs::path two = writeSpec("two", list, extra);
  const fs::path three = writeSpec("three", list, extra);
  const RunResult r1 = tetblend({"batch", one.string()}, dir_);
  // Rank 0 only hands out the jobs: rank 1 runs all seven.
  const RunResult r2 = mpirun(2, two, dir_, {"--coordinator-only"});
  // Both ranks run jobs (how many each depends on timing).
  const RunResult r3 = mpirun(2, three, dir_);
  expectOneLineError(r1);
  EXPECT_EQ(r1.out.find("per rank"), std::string::npos) << r1.out;
  // rank 0's error line, as in one process (mpirun adds its own note after it)
  const std::string error = r1.err.substr(0, r1.err.find(" see "));
  for (const RunResult* r : {&r2, &r3}) {
    EXPECT_NE(r->code, 0);
    EXPECT_EQ(r->err.rfind(error, 0), 0u) << r->err;
    EXPECT_EQ(r->out.rfind("tetblend: batch: 7 of 7 jobs to run, writing into ", 0), 0u) << r->out;
  }
  EXPECT_NE(r2.out.find("\ntetblend: batch: jobs run per rank: 0: 0, 1: 7\n"), std::string::npos)
      << r2.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r3.out, m, std::regex("jobs run per rank: 0: (\\d+), 1: (\\d+)")))
      << r3.out;
  EXPECT_EQ(std::stoi(m[1]) + std::stoi(m[2]), 7) << r3.out;
  std::cout << "[ note     ] default split over 2 ranks: " << m[0] << "\n";
  expectSameOutputs(dir_ / "one" / "out", dir_ / "two" / "out");
  expectSameOutputs(dir_ / "one" / "out", dir_ / "three" / "out");
  const json s = json::parse(slurp(dir_ / "two" / "out" / "summary.json"));
  EXPECT_EQ(s["jobs"][6]["status"], "failed");
  EXPECT_NE(s["jobs"][6]["error"].get<std::string>().find("weights"), std::string::npos);
}

TEST_F(BatchMpi, ResumeAcrossRankCounts) {
  const fs::path one = writeSpec("one", jobs());
  const fs::path two = writeSpec("two", jobs());
  ASSERT_EQ(tetblend({"batch", one.string()}, dir_).code, 0);
  RunResult r = mpirun(2, two, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path out = dir_ / "two" / "out";

  fs::remove(out / "j2.vtp");  // rerun with one rank (mpirun -n 1: no MPI world)
  r = mpirun(1, two, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 1 of 6 jobs to run (5 done by an earlier run", 0), 0u)
      << r.out;
  json s = json::parse(slurp(out / "summary.json"));
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_EQ(s["jobs"][j]["skipped_this_run"].get<bool>(), j != 2) << j;

  fs::remove(out / "j4.vtu");  // and again with two ranks
  fs::remove(out / "j5.vtu");
  r = mpirun(2, two, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 2 of 6 jobs to run (4 done by an earlier run", 0), 0u)
      << r.out;
  s = json::parse(slurp(out / "summary.json"));
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_EQ(s["jobs"][j]["skipped_this_run"].get<bool>(), j != 4 && j != 5) << j;

  // Nothing to do with two ranks: both end at once.
  r = mpirun(2, two, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 0 of 6 jobs to run", 0), 0u) << r.out;

  // The journal and the summary's quality figures now come from three runs;
  // the files are still those of one uninterrupted process, and the
  // summaries are too apart from seconds and skipped_this_run.
  const auto dropSkipped = [](json s) {
    for (json& job : s["jobs"]) job.erase("skipped_this_run");
    return s;
  };
  ASSERT_EQ(tetblend({"batch", one.string()}, dir_).code, 0);  // all skipped there too
  EXPECT_EQ(dropSkipped(summaryWithoutSeconds(dir_ / "one" / "out")),
            dropSkipped(summaryWithoutSeconds(out)));
  for (const std::string& name : listDir(out)) {
    if (name.rfind("summary", 0) == 0) continue;
    if (name == ".tetblend-batch.journal") {
      EXPECT_EQ(lines(dir_ / "one" / "out" / name), lines(out / name));
    } else {
      EXPECT_TRUE(slurp(dir_ / "one" / "out" / name) == slurp(out / name)) << name;
    }
  }
}

}  // namespace
}  // namespace tetblend::apps_test
