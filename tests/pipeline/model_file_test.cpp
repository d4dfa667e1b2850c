// The model file (pipeline/model_file.h): exact round trips, the hash, the
// version 1 layout.

#include "tetblend/pipeline/model_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// A minimal valid model: one tet, one example.
ModelData oneTetModel() {
  ModelData m;
  m.rest.vertices.resize(4, 3);
  m.rest.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.rest.tets.resize(1, 4);
  m.rest.tets << 0, 1, 2, 3;
  m.surfaceTriangles.resize(1, 3);
  m.surfaceTriangles << 0, 2, 1;
  m.surfaceVertexCount = 4;
  m.examples = {m.rest.vertices * 2.0};
  m.restSource = "rest.obj";
  m.exampleSources = {"ex.obj"};
  return m;
}

TEST(ModelFile, RoundTripsExactlyAndHashesLikeFnv1a) {
  // FNV-1a 64 test vectors (Fowler/Noll/Vo reference): "" and "a".
  EXPECT_EQ(fnv1a64(nullptr, 0), 0xcbf29ce484222325ULL);
  const unsigned char a = 'a';
  EXPECT_EQ(fnv1a64(&a, 1), 0xaf63dc4c8601ec8cULL);
  ModelData m = oneTetModel();
  m.rest.vertices(3, 2) = 1.0 / 3.0;  // not exactly representable: the bits round-trip
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "unit.tbm").string();
  writeModelFile(path, m);
  const ModelData r = readModelFile(path);
  EXPECT_EQ(r.rest.vertices, m.rest.vertices);
  EXPECT_EQ(r.rest.tets, m.rest.tets);
  EXPECT_EQ(r.surfaceTriangles, m.surfaceTriangles);
  EXPECT_EQ(r.examples[0], m.examples[0]);
  EXPECT_EQ(r.exampleSources, m.exampleSources);
  m.surfaceTriangles(0, 0) = 7;
  EXPECT_THROW(writeModelFile(path, m), InputError);
}

std::vector<unsigned char> fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

void putLittle(std::vector<unsigned char>& bytes, std::size_t at, std::uint64_t value, int count) {
  for (int i = 0; i < count; ++i) bytes[at + i] = static_cast<unsigned char>(value >> (8 * i));
}

TEST(ModelFile, ExcludedTetsRoundTripAndVersionOneStillReads) {
  ModelData m = oneTetModel();
  m.excludedTets = {0};
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "excluded.tbm").string();
  writeModelFile(path, m);
  EXPECT_EQ(readModelFile(path).excludedTets, m.excludedTets);

  // Version 1 (before excluded tets): the version 2 payload without its
  // trailing excluded-tet list (u64 count 0), header and hash adjusted by
  // hand after the layout in model_file.h.
  m.excludedTets.clear();
  writeModelFile(path, m);
  std::vector<unsigned char> bytes = fileBytes(path);
  constexpr std::size_t kHeader = 8 + 4 + 8, kHash = 8, kExcludedCount = 8;
  const std::size_t payload = bytes.size() - kHeader - kHash - kExcludedCount;
  std::vector<unsigned char> v1(bytes.begin(), bytes.begin() + kHeader + payload);
  putLittle(v1, 8, 1, 4);
  putLittle(v1, 12, payload, 8);
  v1.resize(v1.size() + kHash);
  putLittle(v1, kHeader + payload, fnv1a64(v1.data() + kHeader, payload), 8);
  writeBytes(path, v1);
  const ModelData r = readModelFile(path);
  EXPECT_TRUE(r.excludedTets.empty());
  EXPECT_EQ(r.examples[0], m.examples[0]);

  // Excluded tets out of range or out of order are refused when writing.
  m.excludedTets = {1};
  EXPECT_THROW(writeModelFile(path, m), InputError);
}

}  // namespace
}  // namespace tetblend
