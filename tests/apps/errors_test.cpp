// Bad arguments and bad files: one clear line on stderr, a non-zero exit, and
// nothing written.

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

class CommandErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
    before_ = listDir(dir_);
  }
  void expectNothingWritten() const { EXPECT_EQ(listDir(dir_), before_); }
  fs::path dir_;
  fs::path model_;
  std::vector<std::string> before_;
};

TEST_F(CommandErrors, WrongWeightCount) {
  const RunResult r =
      tetblend({"blend", model_.string(), "-w", "1", "-o", (dir_ / "x.vtu").string()}, dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("2 examples"), std::string::npos) << r.err;
  expectNothingWritten();
}

TEST_F(CommandErrors, BadNumberAndMissingOptionAndUnknownMethod) {
  RunResult r =
      tetblend({"blend", model_.string(), "-w", "0,abc", "-o", (dir_ / "x.vtu").string()}, dir_);
  expectOneLineError(r);
  r = tetblend({"blend", model_.string(), "-w", "0,0"}, dir_);
  expectOneLineError(r);
  EXPECT_EQ(r.code, 2);
  r = tetblend(
      {"blend", model_.string(), "-w", "0,0", "--method", "nope", "-o", (dir_ / "x.vtu").string()},
      dir_);
  expectOneLineError(r);
  r = tetblend({"blend", model_.string(), "-w", "0,0", "-o", (dir_ / "no/such/x.vtu").string()},
               dir_);
  expectOneLineError(r);
  expectNothingWritten();
}

TEST_F(CommandErrors, MissingOrForeignInputs) {
  expectOneLineError(tetblend({"prepare", (dir_ / "none.obj").string(),
                               (dir_ / "bar_bend.obj").string(), "-o", (dir_ / "m.tbm").string()},
                              dir_));
  // An example with other triangles than the rest.
  expectOneLineError(tetblend({"prepare", (dir_ / "bar_rest.obj").string(),
                               (dir_ / "cyl_bend90.off").string(), "-o", (dir_ / "m.tbm").string()},
                              dir_));
  const RunResult r = tetblend(
      {"blend", (dir_ / "bar_rest.obj").string(), "-w", "0,0", "-o", (dir_ / "x.vtu").string()},
      dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("not a tetblend model"), std::string::npos) << r.err;
  expectNothingWritten();
}

void corrupt(const fs::path& source, const fs::path& target, std::size_t at, int delta,
             std::size_t keep = std::string::npos) {
  std::string bytes = slurp(source);
  if (at < bytes.size()) bytes[at] = static_cast<char>(bytes[at] + delta);
  if (keep != std::string::npos) bytes.resize(keep);
  std::ofstream(target, std::ios::binary) << bytes;
}

TEST_F(CommandErrors, DamagedModelIsRefused) {
  const std::size_t size = fs::file_size(model_);
  const struct {
    const char* name;
    std::size_t at;
    std::size_t keep;
    const char* expected;
  } cases[] = {{"flipped.tbm", size / 2, std::string::npos, "checksum"},
               {"truncated.tbm", 0, size - 100, "damaged"},
               {"version.tbm", 8, std::string::npos, "version"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    corrupt(model_, dir_ / c.name, c.at, c.name[0] == 't' ? 0 : 1, c.keep);
    before_ = listDir(dir_);
    const RunResult r = tetblend(
        {"blend", (dir_ / c.name).string(), "-w", "0,0", "-o", (dir_ / "x.vtu").string()}, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    expectNothingWritten();
  }
}

// Issue 11, item 3: control bytes of a file name or value reached the
// terminal verbatim; the error line escapes them.
TEST(CommandErrorLine, ControlBytesAreEscaped) {
  const fs::path dir = scratchDir();
  const RunResult r = tetblend({"inspect", (dir / "a\x1b[2J\tb.obj").string()}, dir);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("a\\x1b[2J\\x09b.obj"), std::string::npos) << r.err;
  for (const char c : r.err.substr(0, r.err.size() - 1))
    EXPECT_GE(static_cast<unsigned char>(c), 0x20) << r.err;
}

TEST(CommandHelp, EverySubcommandDocumentsItsOptions) {
  const fs::path dir = scratchDir();
  const struct {
    const char* command;
    std::vector<std::string> mentions;
  } cases[] = {
      {"prepare", {"--quality", "--max-volume", "--tetrise", "--threads", "2"}},
      {"blend",
       {"--weights", "--weight", "NAME_OR_INDEX=VALUE", "--method", "kaji", "dqs = dq",
        "--consistency", "--nonlinear", "--surface-format"}},
      {"batch", {"--threads", "summary.json", "fingerprint"}},
      {"variations", {"--count", "--seed", "--extrapolate", "--pca", "Dirichlet"}},
      {"animate", {"--keys", "--frames", "--spline", "catmull-rom", "24"}},
      {"deform", {"--handles", "--method", "--falloff", "lbs, dq, kaji", "dqs = dq"}},
      {"inspect", {"FILE"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.command);
    const RunResult r = tetblend({c.command, "--help"}, dir);
    EXPECT_EQ(r.code, 0);
    for (const std::string& m : c.mentions) EXPECT_NE(r.out.find(m), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace tetblend::apps_test
