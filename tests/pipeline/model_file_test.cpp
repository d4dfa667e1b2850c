// The model file (pipeline/model_file.h): exact round trips, the hashes, the
// version 1 to 3 layouts, the blend cache.

#include "tetblend/pipeline/model_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "tetblend/core/error.h"
#include "tetblend/pipeline/make_blender.h"

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
  putLittle(bytes, kHeader + payload, modelChecksum(bytes.data() + kHeader, payload, version), 8);
  writeBytes(path, bytes);
}

// Each list a version added is an u64 count followed by its entries.
constexpr std::size_t kEmptyListBytes = 8;

TEST(ModelFile, ExcludedTetsRoundTripAndVersionsOneToThreeStillRead) {
  ModelData m = oneTetModel();
  m.excludedTets = {0};
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "excluded.tbm").string();
  writeModelFile(path, m);
  EXPECT_EQ(readModelFile(path).excludedTets, m.excludedTets);

  // Version 3 (before the blend cache), 2 (before input vertex rows) and 1
  // (before excluded tets).
  m.excludedTets.clear();
  for (const std::uint32_t version : {3u, 2u, 1u}) {
    writeModelFile(path, m);
    rewriteAsVersion(path, version, (kModelFormatVersion - version) * kEmptyListBytes);
    const ModelData r = readModelFile(path);
    EXPECT_EQ(r.formatVersion, version);
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

  m.inputVertexRows[4] = 4;  // not a row (there are 4)
  EXPECT_THROW(writeModelFile(path, m), InputError);
  m.inputVertexRows = {0, 1, 2, 3, 1};  // a triangle then refers to input vertex 5 of 5
  EXPECT_THROW(writeModelFile(path, m), InputError);
}

TEST(ModelFile, WordChecksumMatchesFnv1aStepsOverLittleEndianWords) {
  // By hand: (basis ^ word) * prime mod 2^64 for the word of "abcdefgh" read
  // little-endian, then FNV-1a's byte step for the tail "i".
  const std::string text = "abcdefghi";
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  EXPECT_EQ(fnv1a64Words(bytes, 0), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64Words(bytes, 8), 0x3919eeb00ee1e68cULL);
  EXPECT_EQ(fnv1a64Words(bytes, 9), 0xe8f77a2949db571fULL);
  EXPECT_EQ(modelChecksum(bytes, 9, 3), fnv1a64(bytes, 9));
  EXPECT_EQ(modelChecksum(bytes, 9, 4), fnv1a64Words(bytes, 9));
}

// A five-tet model keeps its blend cache bit for bit, and a blender of the
// model read back gives the blends of one that factors afresh.
TEST(ModelFile, BlendCacheRoundTripsAndGivesTheSameBlends) {
  ModelData m = oneTetModel();
  m.rest.vertices.conservativeResize(5, 3);
  m.rest.vertices.row(4) << 1, 1, 1;
  m.rest.tets.conservativeResize(2, 4);
  m.rest.tets.row(1) << 1, 2, 3, 4;  // positive: (1,1,1) is beyond the face 1 2 3
  m.examples = {m.rest.vertices * 2.0};
  m.examples[0](4, 0) += 0.25;
  m.blendCache = blendCacheOf(m);
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "cache.tbm").string();
  writeModelFile(path, m);
  const ModelData r = readModelFile(path);
  ASSERT_TRUE(r.blendCache.has_value());
  EXPECT_EQ(r.blendCache->factor.perm, m.blendCache->factor.perm);
  EXPECT_EQ(r.blendCache->factor.values, m.blendCache->factor.values);
  EXPECT_EQ(r.blendCache->factor.valueStart, m.blendCache->factor.valueStart);
  EXPECT_EQ(r.blendCache->kaji.params, m.blendCache->kaji.params);
  EXPECT_EQ(r.blendCache->kaji.tets, 2);
  EXPECT_TRUE(r.blendCache->kaji.rotationConsistency);
  ModelData plain = r;
  plain.blendCache.reset();
  const std::vector<double> w{0.4};
  EXPECT_TRUE(makeBlender(r, {BlendMethod::kKaji}, true, false).blend(w).vertices ==
              makeBlender(plain, {BlendMethod::kKaji}, true, false).blend(w).vertices);

  // The cache flag is 0 or 1; anything else is damage.
  writeModelFile(path, plain);
  std::vector<unsigned char> bytes = fileBytes(path);
  constexpr std::size_t kHeader = 8 + 4 + 8, kHash = 8;
  const std::size_t flagAt = bytes.size() - kHash - 8;
  ASSERT_EQ(bytes[flagAt], 0);
  bytes[flagAt] = 2;
  const std::size_t payload = bytes.size() - kHeader - kHash;
  putLittle(bytes, kHeader + payload, modelChecksum(bytes.data() + kHeader, payload, 4), 8);
  writeBytes(path, bytes);
  try {
    readModelFile(path);
    ADD_FAILURE() << "a cache flag of 2 was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("blend cache flag = 2"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace tetblend
