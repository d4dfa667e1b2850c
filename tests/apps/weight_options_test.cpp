// blend's weight options (weight_options.h): --weight NAME_OR_INDEX=VALUE
// writes the very bytes of the equivalent -w list, by file stem, whole source
// and index; every bad entry is one error line, exit status non-zero and no
// file; exactly one of -w and --weight is required.

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

class WeightOptions : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);  // examples 1 bar_twist4pi.obj, 2 bar_bend.obj
  }
  /// blend of the model into dir/<name>.vtu with `weightArgs`.
  RunResult blend(const std::string& name, const std::vector<std::string>& weightArgs) const {
    std::vector<std::string> args{"blend", model_.string()};
    args.insert(args.end(), weightArgs.begin(), weightArgs.end());
    args.insert(args.end(), {"-o", (dir_ / (name + ".vtu")).string(), "--quiet"});
    return tetblend(args, dir_);
  }
  /// Both files of blends `a` and `b` are byte for byte the same.
  void expectSameFiles(const std::string& a, const std::string& b) const {
    for (const std::string ext : {".vtu", ".vtp"}) {
      const std::string bytesA = slurp(dir_ / (a + ext)), bytesB = slurp(dir_ / (b + ext));
      ASSERT_FALSE(bytesA.empty()) << a + ext;
      EXPECT_TRUE(bytesA == bytesB) << a + ext << " differs from " << b + ext;
    }
  }
  /// One error line naming `expected`, exit status non-zero, nothing written.
  void expectRefused(const std::vector<std::string>& weightArgs, const std::string& expected) {
    SCOPED_TRACE(testing::PrintToString(weightArgs));
    const std::vector<std::string> before = listDir(dir_);
    const RunResult r = blend("refused", weightArgs);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(listDir(dir_), before);
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(WeightOptions, SparseWeightsWriteTheBytesOfTheDenseList) {
  ASSERT_EQ(blend("dense", {"-w", "0,0.5"}).code, 0);
  ASSERT_EQ(blend("by_stem", {"--weight", "bar_bend=0.5"}).code, 0);
  ASSERT_EQ(blend("by_index", {"--weight", "2=0.5"}).code, 0);
  expectSameFiles("dense", "by_stem");
  expectSameFiles("dense", "by_index");

  ASSERT_EQ(blend("dense2", {"-w", "0.3,-0.2"}).code, 0);
  const RunResult mixed = blend(
      "mixed", {"--weight", (dir_ / "bar_twist4pi.obj").string() + "=0.3", "--weight", "2=-0.2"});
  ASSERT_EQ(mixed.code, 0) << mixed.err;
  expectSameFiles("dense2", "mixed");

  // --weight takes one entry per occurrence: the model may follow it.
  const RunResult after = tetblend({"blend", "--weight", "bar_bend=0.5", model_.string(), "-o",
                                    (dir_ / "after.vtu").string(), "--quiet"},
                                   dir_);
  ASSERT_EQ(after.code, 0) << after.err;
  expectSameFiles("dense", "after");
}

TEST_F(WeightOptions, BadEntriesAreOneLineAndWriteNothing) {
  expectRefused({"--weight", "bar_bnd=0.5"},
                "--weight bar_bnd=0.5: no example is named 'bar_bnd'; examples: bar_twist4pi, "
                "bar_bend (2 in all;");
  expectRefused({"--weight", "bar_bnd=0.5"}, "'tetblend inspect " + model_.string() + "'");
  // Several entries in one --weight ("1=0.5,2=0.3") name no example.
  expectRefused({"--weight", "1=0.5,2=0.3"},
                "no example is named '1=0.5,2'; examples: bar_twist4pi, bar_bend (2 in all;");
  expectRefused({"--weight", "1=0.5,2=0.3"}, "give each example its own --weight");
  expectRefused({"--weight", "3=0.5"},
                "--weight 3=0.5: there is no example 3; the examples are numbered 1..2");
  expectRefused({"--weight", "0=0.5"}, "there is no example 0; the examples are numbered 1..2");
  expectRefused({"--weight", "bar_bend=0.5", "--weight", "bar_bend=0.1"},
                "--weight bar_bend=0.1: example 2 (");
  expectRefused({"--weight", "2=0.5", "--weight", "bar_bend=0.1"},
                "already has a weight, from --weight 2=0.5");
  for (const std::string value : {"nan", "inf", "-inf", "1e999", "0.5x", ""}) {
    expectRefused({"--weight", "bar_bend=" + value}, "is not a finite number");
  }
  expectRefused({"--weight", "bar_bend"}, "give NAME_OR_INDEX=VALUE");
}

// Examples given as --example files are named by those paths, and the names
// are checked before TetGen runs.
TEST_F(WeightOptions, StemOfTwoExamplesAsksForTheIndex) {
  fs::create_directories(dir_ / "other");
  fs::copy_file(dir_ / "bar_bend.obj", dir_ / "other" / "bar_bend.obj");
  const std::vector<std::string> before = listDir(dir_);
  const RunResult r = tetblend(
      {"blend", "--rest", (dir_ / "bar_rest.obj").string(), "--example",
       (dir_ / "bar_bend.obj").string(), "--example", (dir_ / "other" / "bar_bend.obj").string(),
       "--weight", "bar_bend=0.5", "-o", (dir_ / "x.vtu").string()},
      dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("'bar_bend' names 2 examples, 1 (" + (dir_ / "bar_bend.obj").string() +
                       "), 2 (" + (dir_ / "other" / "bar_bend.obj").string() +
                       "); give the index of the one you mean instead"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("inspect"), std::string::npos) << r.err;
  EXPECT_EQ(listDir(dir_), before);
}

TEST_F(WeightOptions, ExactlyOneOfTheTwoOptions) {
  for (const auto& args : {std::vector<std::string>{},
                           std::vector<std::string>{"-w", "0,1", "--weight", "bar_bend=1"}}) {
    SCOPED_TRACE(testing::PrintToString(args));
    const std::vector<std::string> before = listDir(dir_);
    const RunResult r = blend("x", args);
    expectOneLineError(r);
    EXPECT_EQ(r.code, 2);  // command-line usage
    EXPECT_NE(r.err.find("--weight"), std::string::npos) << r.err;
    EXPECT_EQ(listDir(dir_), before);
  }
}

}  // namespace
}  // namespace tetblend::apps_test
