// Issue 11: no crash on any input, no input ever overwritten. Each test is
// the regression test of one item of the issue, named in its comment.

#include <sys/stat.h>

#include <cstdint>

#include "address_sanitizer.h"
#include "apps_test_support.h"
#include "cli_common.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

using test::kAddressSanitizer;

class Reliability : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    makeSamples(dir_);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

void appendLittle(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

// A model file with a valid header and checksum around `payload` (the layout
// of model_file.h), so only the counts inside are wrong.
void writeModel(const fs::path& path, const std::string& payload) {
  std::string bytes("TBMODEL\0", 8);
  appendLittle(bytes, kModelFormatVersion, 4);
  appendLittle(bytes, payload.size(), 8);
  bytes += payload;
  appendLittle(bytes,
               modelChecksum(reinterpret_cast<const unsigned char*>(payload.data()), payload.size(),
                             kModelFormatVersion),
               8);
  std::ofstream(path, std::ios::binary) << bytes;
}

// Item 2: a count near 2^31 allocated gigabytes and ended in std::bad_alloc
// with no file named.
TEST_F(Reliability, ModelFileCountsBeyondThePayloadAreRefusedNamingTheFile) {
  constexpr std::uint64_t kHuge = (1ULL << 31) - 1;
  const struct {
    const char* name;
    std::uint64_t counts[5];  // #V, #T, #F, surface vertices, #examples
    const char* expected;
  } cases[] = {{"vertices.tbm", {kHuge, 0, 0, 0, 0}, "vertex count 2147483647"},
               {"tets.tbm", {0, kHuge, 0, 0, 0}, "tet count 2147483647"},
               {"triangles.tbm", {0, 0, kHuge, 0, 0}, "triangle count 2147483647"},
               {"examples.tbm", {0, 0, 0, 0, kHuge}, "example count 2147483647"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::string payload;
    for (const std::uint64_t n : c.counts) appendLittle(payload, n, 8);
    payload += std::string(64, '\0');
    writeModel(dir_ / c.name, payload);
    const RunResult r = tetblend({"inspect", file(c.name)}, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(file(c.name) + ": damaged model file (" + c.expected), std::string::npos)
        << r.err;
  }
}

// Item 2: a std::bad_alloc escaping a command said only "std::bad_alloc".
// --count 2^31-1 reserves about 48 GiB of weight vectors; the address space
// limit makes that fail on any machine.
TEST_F(Reliability, OutOfMemoryIsOneLineNamingTheCommandAndInput) {
  if (kAddressSanitizer)
    GTEST_SKIP() << "needs an address-space limit, which ASan cannot run under";
  const fs::path model = prepareBar(dir_);
  constexpr const char* kAddressSpaceKiB = "4000000";  // 4 GB: ample for a normal run
  const RunResult r = runProgram(
      "/bin/sh",
      {"-c", std::string("ulimit -v ") + kAddressSpaceKiB + " && exec \"$0\" \"$@\"", TETBLEND_EXE,
       "variations", model.string(), "--count", "2147483647", "-o", file("out")},
      dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("out of memory in 'tetblend variations' on " + model.string()),
            std::string::npos)
      << r.err;
  EXPECT_EQ(cli::outOfMemoryMessage({"prepare", file("bar_rest.obj"), "-o", file("bar_bend.obj")})
                .rfind("out of memory in 'tetblend prepare' on " + file("bar_rest.obj") + ": ", 0),
            0u);
}

// Item 1: under a 128-192 MiB address-space limit `blend` hung: OpenBLAS's
// worker threads retry forever to map their 128 MB buffers, the
// factorisation waited for them, and so did the exit. Now the factorisation
// checks its memory first and the process leaves without waiting.
TEST_F(Reliability, BlendUnderATightMemoryLimitFailsWithOneLine) {
  if (kAddressSanitizer)
    GTEST_SKIP() << "needs an address-space limit, which ASan cannot run under";
  const fs::path model = prepareBar(dir_);
  const std::vector<std::string> before = listDir(dir_);
  // ctest's timeout would catch a hang; `timeout` turns one into exit 124 here.
  constexpr const char* kHangSeconds = "60";
  for (const char* kibibytes : {"131072", "196608"}) {
    const RunResult r = runProgram(
        "/bin/sh",
        {"-c", std::string("ulimit -v ") + kibibytes + " && exec timeout " + kHangSeconds +
                   " \"$0\" \"$@\"",
         TETBLEND_EXE, "blend", model.string(), "--weights", "0.5,0.2", "-o", file("low.vtu")},
        dir_);
    SCOPED_TRACE(kibibytes);
    expectOneLineError(r);
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.find("not enough memory for the stitch's Cholesky factorisation") !=
                    std::string::npos ||
                r.err.find("out of memory in 'tetblend blend'") != std::string::npos)
        << r.err;
    EXPECT_EQ(listDir(dir_), before);
  }
}

// Item 4: `prepare R.obj E.obj -o R.obj` replaced the rest surface, and
// `blend --rest r.vtp ... -o r.vtu` replaced r.vtp with the blend's surface.
TEST_F(Reliability, OutputThatIsAnInputIsRefusedBeforeAnyWork) {
  fs::copy_file(dir_ / "bar_rest.obj", dir_ / "r.vtp");
  fs::create_hard_link(dir_ / "bar_bend.obj", dir_ / "alias.tbm");
  const std::string rest = slurp(dir_ / "bar_rest.obj");
  const std::vector<std::string> before = listDir(dir_);
  const struct {
    std::vector<std::string> args;
    std::string output, input;
  } cases[] = {
      {{"prepare", file("bar_rest.obj"), file("bar_bend.obj"), "-o", file("bar_rest.obj")},
       file("bar_rest.obj"),
       file("bar_rest.obj")},
      {{"prepare", file("bar_rest.obj"), file("bar_bend.obj"), "-o",
        (dir_ / "." / "alias.tbm").string()},
       (dir_ / "." / "alias.tbm").string(),
       file("bar_bend.obj")},
      {{"blend", "--rest", file("r.vtp"), "--example", file("bar_bend.obj"), "-w", "0.5", "-o",
        file("r.vtu")},
       file("r.vtp"),
       file("r.vtp")},
      {{"deform", file("bar_rest.obj"), "--handles", file("bar_bend.obj"), "-o",
        file("bar_bend.obj")},
       file("bar_bend.obj"),
       file("bar_bend.obj")},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args[0] + " -o " + c.output);
    const RunResult r = tetblend(c.args, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.output + ": is the same file as the input " + c.input),
              std::string::npos)
        << r.err;
  }
  EXPECT_EQ(listDir(dir_), before);
  EXPECT_EQ(slurp(dir_ / "bar_rest.obj"), rest);
}

// Item 4: an output that exists and is not a regular file is refused with
// the reason, before any work and without touching it.
TEST_F(Reliability, OutputThatIsNotARegularFileIsRefusedWithTheReason) {
  fs::create_directory(dir_ / "folder.tbm");
  fs::create_symlink(dir_ / "bar_twist4pi.obj", dir_ / "link.tbm");
  ASSERT_EQ(::mkfifo((dir_ / "pipe.tbm").c_str(), 0600), 0);
  const std::vector<std::string> before = listDir(dir_);
  const struct {
    std::string output;
    const char* reason;
  } cases[] = {{file("folder.tbm"), "is a directory"},
               {file("link.tbm"), "is a symbolic link"},
               {file("pipe.tbm"), "is a FIFO"},
               {"/dev/null", "is a device"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.output);
    const RunResult r = tetblend(
        {"prepare", file("bar_rest.obj"), file("bar_bend.obj"), "-o", c.output, "--quiet"}, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.output + ": " + c.reason), std::string::npos) << r.err;
  }
  EXPECT_EQ(listDir(dir_), before);
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.tbm"));
}

// Item 5: --threads 1000000000 (or "threads" in a batch spec) ended in
// std::bad_alloc or gigabytes of thread state.
TEST_F(Reliability, ThreadCountsAboveTheMaximumAreRefused) {
  const std::string maximum = std::to_string(cli::kMaxThreads);
  const std::vector<std::string> commands[] = {
      {"prepare", file("bar_rest.obj"), file("bar_bend.obj"), "-o", file("x.tbm")},
      {"blend", file("x.tbm"), "-w", "0", "-o", file("x.vtu")},
      {"variations", file("x.tbm"), "-o", file("out")}};
  for (std::vector<std::string> args : commands) {
    SCOPED_TRACE(args[0]);
    args.insert(args.end(), {"--threads", "1000000000"});
    const RunResult r = tetblend(args, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(maximum), std::string::npos) << r.err;
  }
  for (const char* threads : {"1000000000", "-3", "1.5"}) {
    SCOPED_TRACE(threads);
    std::ofstream(dir_ / "spec.json") << R"({"model": "bar.tbm", "threads": )" << threads
                                      << R"(, "jobs": [{"name": "a", "weights": [0, 0]}]})";
    const RunResult r = tetblend({"batch", file("spec.json")}, dir_);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(file("spec.json") + ": \"threads\" is " + threads), std::string::npos)
        << r.err;
  }
}

}  // namespace
}  // namespace tetblend::apps_test
