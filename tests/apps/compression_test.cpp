// The compressor of blended shapes' .vtu/.vtp files: --compression and
// --compression-level of blend, "compression" and "compression_level" of a
// batch spec (and batch's flags over them). Every choice must give files
// VTK's own readers read back to the same points and arrays, bit for bit.

#include <nlohmann/json.hpp>

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

using nlohmann::json;

/// The compressor a VTK XML file declares ("" for none).
std::string compressorOf(const fs::path& file) {
  const std::string text = slurp(file);
  const std::string key = "compressor=\"";
  const std::size_t at = text.find(key);
  if (at == std::string::npos || at > text.find("<AppendedData")) return "";
  return text.substr(at + key.size(), text.find('"', at + key.size()) - at - key.size());
}

/// Every value of every point and cell array of `a` equals `b`'s, NaN = NaN.
void expectSameData(vtkDataSet* a, vtkDataSet* b) {
  for (auto [fa, fb] :
       {std::pair<vtkFieldData*, vtkFieldData*>{a->GetPointData(), b->GetPointData()},
        {a->GetCellData(), b->GetCellData()}}) {
    ASSERT_EQ(fa->GetNumberOfArrays(), fb->GetNumberOfArrays());
    for (int k = 0; k < fa->GetNumberOfArrays(); ++k) {
      vtkDataArray* x = fa->GetArray(k);
      vtkDataArray* y = fb->GetArray(x->GetName());
      ASSERT_NE(y, nullptr) << x->GetName();
      ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << x->GetName();
      for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i) {
        const double p = x->GetVariantValue(i).ToDouble(), q = y->GetVariantValue(i).ToDouble();
        ASSERT_TRUE(p == q || (std::isnan(p) && std::isnan(q))) << x->GetName() << "[" << i << "]";
      }
    }
  }
}

/// `stem`.vtu and `stem`.vtp equal `reference`.vtu/.vtp: points and arrays.
void expectSameShape(const fs::path& stem, const fs::path& reference) {
  const auto vtu = readVtu(stem.string() + ".vtu");
  const auto vtp = readVtp(stem.string() + ".vtp");
  ASSERT_GT(vtu->GetNumberOfPoints(), 0) << stem;
  ASSERT_GT(vtp->GetNumberOfPoints(), 0) << stem;
  EXPECT_EQ(pointsOf(vtu), pointsOf(readVtu(reference.string() + ".vtu"))) << stem;
  EXPECT_EQ(pointsOf(vtp), pointsOf(readVtp(reference.string() + ".vtp"))) << stem;
  expectSameData(vtu, readVtu(reference.string() + ".vtu"));
  expectSameData(vtp, readVtp(reference.string() + ".vtp"));
}

class Compression : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
  }
  RunResult blend(const std::string& stem, const std::vector<std::string>& extra) const {
    std::vector<std::string> args{
        "blend", model_.string(), "-w", "0.3,0.4", "-o", (dir_ / (stem + ".vtu")).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return tetblend(args, dir_);
  }
  /// dir/<name>.json over bar.tbm (2 jobs) with `options`, run with `flags`.
  RunResult batch(const std::string& name, const json& options,
                  const std::vector<std::string>& flags = {}) const {
    json spec{{"model", "bar.tbm"},
              {"threads", 2},
              {"jobs", json::array({{{"name", "a"}, {"weights", {0.25, 0.5}}},
                                    {{"name", "b"}, {"weights", {1.0, 0.0}}}})}};
    spec.update(options);
    std::ofstream(dir_ / (name + ".json")) << spec.dump(2);
    std::vector<std::string> args{"batch", (dir_ / (name + ".json")).string()};
    args.insert(args.end(), flags.begin(), flags.end());
    return tetblend(args, dir_);
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(Compression, BlendWritesEveryCompressorToTheSameShape) {
  ASSERT_EQ(blend("default", {}).code, 0);
  EXPECT_EQ(compressorOf(dir_ / "default.vtu"), "vtkLZ4DataCompressor");  // the default
  EXPECT_EQ(compressorOf(dir_ / "default.vtp"), "vtkLZ4DataCompressor");
  const struct {
    std::vector<std::string> flags;
    std::string compressor;
  } cases[] = {{{"--compression", "zlib"}, "vtkZLibDataCompressor"},
               {{"--compression", "zlib", "--compression-level", "1"}, "vtkZLibDataCompressor"},
               {{"--compression", "lz4", "--compression-level", "9"}, "vtkLZ4DataCompressor"},
               {{"--compression", "none"}, ""}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.flags[1] + (c.flags.size() > 2 ? " level " + c.flags[3] : ""));
    const RunResult r = blend("c", c.flags);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(compressorOf(dir_ / "c.vtu"), c.compressor);
    EXPECT_EQ(compressorOf(dir_ / "c.vtp"), c.compressor);
    expectSameShape(dir_ / "c", dir_ / "default");
  }
}

TEST_F(Compression, BlendRefusesAnUnknownCompressorOrLevel) {
  const struct {
    std::vector<std::string> flags;
    std::string message;
  } cases[] = {{{"--compression", "gzip"}, "unknown compressor 'gzip'"},
               {{"--compression-level", "10"}, "level 10 is outside 1..9"},
               {{"--compression-level", "0"}, "level 0 is outside 1..9"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.flags[1]);
    const RunResult r = blend("bad", c.flags);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad.vtu"));
  }
}

TEST_F(Compression, BatchSpecKeysAndFlagsChooseTheCompressorAndRerunWhenChanged) {
  ASSERT_EQ(batch("default", json::object()).code, 0);
  const fs::path reference = dir_ / "default_out";
  EXPECT_EQ(compressorOf(reference / "a.vtu"), "vtkLZ4DataCompressor");
  RunResult r = batch("z", {{"compression", "zlib"}, {"compression_level", 9}});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string job : {"a", "b"}) {
    EXPECT_EQ(compressorOf(dir_ / "z_out" / (job + ".vtu")), "vtkZLibDataCompressor");
    expectSameShape(dir_ / "z_out" / job, reference / job);
  }
  // The flag overrides the spec, and a changed compressor reruns the jobs.
  r = batch("z", {{"compression", "zlib"}, {"compression_level", 9}}, {"--compression", "none"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 2 of 2 jobs to run", 0), 0u) << r.out;
  EXPECT_EQ(compressorOf(dir_ / "z_out" / "b.vtp"), "");
  expectSameShape(dir_ / "z_out" / "b", reference / "b");
  // The same choice again: nothing reruns.
  r = batch("z", {{"compression", "none"}});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("tetblend: batch: 0 of 2 jobs to run", 0), 0u) << r.out;
}

TEST_F(Compression, BatchRefusesBadCompressionEntriesWithOneLine) {
  const struct {
    json options;
    std::string message;
  } cases[] = {
      {{{"compression", "gzip"}}, "unknown compressor 'gzip'"},
      {{{"compression", 1}}, "bad entry"},
      {{{"compression_level", 0}}, "level 0 is outside 1..9"},
      {{{"compression_level", "5"}}, "\"compression_level\" is \"5\""},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options.dump());
    const RunResult r = batch("bad", c.options);
    expectOneLineError(r);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad_out"));
  }
}

}  // namespace
}  // namespace tetblend::apps_test
