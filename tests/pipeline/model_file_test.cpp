// The model file (pipeline/model_file.h): exact round trips, the hash, the
// version 1 and 2 layouts.

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

// Rewrites the model file at `path` as format `version`: its payload without
// the last `dropped` bytes (the lists later versions appended, empty here),
// header and hash adjusted by hand after the layout in model_file.h.
void rewriteAsVersion(const std::string& path, std::uint32_t version, std::size_t dropped) {
  std::vector<unsigned char> bytes = fileBytes(path);
  constexpr std::size_t kHeader = 8 + 4 + 8, kHash = 8;
  const std::size_t payload = bytes.size() - kHeader - kHash - dropped;
  bytes.resize(kHeader + payload + kHash);
  putLittle(bytes, 8, version, 4);
  putLittle(bytes, 12, payload, 8);
  putLittle(bytes, kHeader + payload, fnv1a64(bytes.data() + kHeader, payload), 8);
  writeBytes(path, bytes);
}

// Each list a version added is an u64 count followed by its entries.
constexpr std::size_t kEmptyListBytes = 8;

TEST(ModelFile, ExcludedTetsRoundTripAndVersionsOneAndTwoStillRead) {
  ModelData m = oneTetModel();
  m.excludedTets = {0};
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "excluded.tbm").string();
  writeModelFile(path, m);
  EXPECT_EQ(readModelFile(path).excludedTets, m.excludedTets);

  // Version 2 (before input vertex rows) and version 1 (before excluded tets).
  m.excludedTets.clear();
  for (const std::uint32_t version : {2u, 1u}) {
    writeModelFile(path, m);
    rewriteAsVersion(path, version, (kModelFormatVersion - version) * kEmptyListBytes);
    const ModelData r = readModelFile(path);
    EXPECT_TRUE(r.excludedTets.empty()) << version;
    EXPECT_TRUE(r.inputVertexRows.empty()) << version;
    EXPECT_EQ(r.examples[0], m.examples[0]) << version;
  }

  // Excluded tets out of range or out of order are refused when writing.
  m.excludedTets = {1};
  EXPECT_THROW(writeModelFile(path, m), InputError);
}

// A rest exported with a seam: input vertices 4 and 5 are copies of surface
// vertices 1 and 2, and the input's faces use them.
TEST(ModelFile, InputVertexRowsRoundTripAndGiveTheInputsVertices) {
  ModelData m = oneTetModel();
  m.inputVertexRows = {0, 1, 2, 3, 1, 2};
  m.surfaceTriangles << 0, 5, 4;
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "rows.tbm").string();
  writeModelFile(path, m);
  const ModelData r = readModelFile(path);
  EXPECT_EQ(r.inputVertexRows, m.inputVertexRows);
  EXPECT_EQ(r.surfaceTriangles, m.surfaceTriangles);
  EXPECT_EQ(r.inputVertexCount(), 6);
  const Vertices input = r.inputVertices(r.examples[0]);
  ASSERT_EQ(input.rows(), 6);
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(input.row(i) == r.examples[0].row(m.inputVertexRows[i])) << i;
  }
  EXPECT_TRUE(oneTetModel().inputVertices(r.examples[0]) == r.examples[0]);

  m.inputVertexRows[4] = 4;  // not a surface vertex (there are 4)
  EXPECT_THROW(writeModelFile(path, m), InputError);
  m.inputVertexRows = {0, 1, 2, 3, 1};  // a triangle then refers to input vertex 5 of 5
  EXPECT_THROW(writeModelFile(path, m), InputError);
}

}  // namespace
}  // namespace tetblend
