// Unit tests of the command line's own numerics: weight sampling, splines,
// the model file round trip and the PCA in weight space.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tetblend/core/error.h"
#include "tetblend/pipeline/model_file.h"
#include "tetblend/pipeline/parameter_pca.h"
#include "tetblend/pipeline/weight_sampling.h"
#include "weight_spline.h"

namespace tetblend::cli {
namespace {

std::uint64_t testSeed() {
  const char* env = std::getenv("TETBLEND_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 10) : 20240611ULL;
  std::cout << "TETBLEND_SEED=" << seed << "\n";
  return seed;
}

TEST(WeightSampling, UniformOnTheSimplexWithTheDocumentedWidening) {
  const std::uint64_t seed = testSeed();
  constexpr int kSamples = 20000;
  // Mean of a Dirichlet(1,1,1) coordinate is 1/3 with standard deviation
  // sqrt(2/36); over 20000 samples the standard error is ~1.7e-3: 5 sigma.
  constexpr double kMeanTolerance = 5 * 1.7e-3;
  const auto w = sampleSimplexWeights(kSamples, 2, seed, 0.0);
  double mean0 = 0.0;
  for (const auto& v : w) {
    ASSERT_GE(v[0], 0.0);
    ASSERT_GE(v[1], 0.0);
    ASSERT_LE(v[0] + v[1], 1.0 + 1e-15);
    mean0 += v[0] / kSamples;
  }
  EXPECT_NEAR(mean0, 1.0 / 3.0, kMeanTolerance);
  // Widening by X maps b to (1+X) b - X/3: same seed, exact relation.
  const auto wide = sampleSimplexWeights(kSamples, 2, seed, 1.5);
  for (int s = 0; s < kSamples; s += 97)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(wide[s][k], 2.5 * w[s][k] - 1.5 / 3.0, 1e-14);
  EXPECT_EQ(sampleSimplexWeights(5, 3, seed, 0.0), sampleSimplexWeights(5, 3, seed, 0.0));
  EXPECT_THROW(sampleSimplexWeights(1, 2, seed, -1.0), InputError);
}

TEST(WeightSpline, InterpolatingSplinesHitTheKeysAndBSplineTheEnds) {
  const std::vector<std::vector<double>> keys{{0, 0}, {1, 0}, {0, 1}, {2, 2}};
  // 7 frames over 3 segments: frames 0, 2, 4, 6 sit on the keys.
  for (SplineKind kind : {SplineKind::kLinear, SplineKind::kCatmullRom}) {
    const auto f = splineFrames(keys, 7, kind);
    ASSERT_EQ(f.size(), 7u);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(f[2 * k][c], keys[k][c], 1e-15);
  }
  const auto b = splineFrames(keys, 11, SplineKind::kBSpline);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(b.front()[c], keys.front()[c], 1e-15);
    EXPECT_NEAR(b.back()[c], keys.back()[c], 1e-15);
  }
  // Catmull–Rom midpoint of the inner segment: (-p0 + 9 p1 + 9 p2 - p3) / 16.
  const auto m = splineFrames(keys, 7, SplineKind::kCatmullRom)[3];
  EXPECT_NEAR(m[0], (-0 + 9 * 1 + 9 * 0 - 2) / 16.0, 1e-15);
  EXPECT_NEAR(m[1], (-0 + 9 * 0 + 9 * 1 - 2) / 16.0, 1e-15);
  EXPECT_THROW(parseSplineKind("cubic"), InputError);
}

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

TEST(ParameterPca, WeightStepsReproduceThePrincipalDirections) {
  // Oracle: build the PCA of random vectors directly (covariance of the n+1
  // shapes in parameter space) and compare with the weight-space answer.
  const std::uint64_t seed = testSeed();
  std::srand(static_cast<unsigned>(seed));
  const int n = 3, dim = 12;
  std::vector<Eigen::VectorXd> p;
  for (int k = 0; k < n; ++k) p.push_back(Eigen::VectorXd::Random(dim));
  const ParameterPca pca = parameterPca(p);
  ASSERT_EQ(pca.steps.size(), static_cast<std::size_t>(n));
  Eigen::MatrixXd shapes = Eigen::MatrixXd::Zero(dim, n + 1);
  for (int k = 0; k < n; ++k) shapes.col(k + 1) = p[k];
  const Eigen::VectorXd mean = shapes.rowwise().mean();
  const Eigen::MatrixXd centred = shapes.colwise() - mean;
  const Eigen::MatrixXd cov = centred * centred.transpose() / (n + 1);
  Eigen::MatrixXd basis(dim, n);
  for (int k = 0; k < n; ++k) basis.col(k) = p[k];
  for (std::size_t i = 0; i < pca.steps.size(); ++i) {
    const Eigen::VectorXd d = basis * pca.steps[i];  // +1 sigma in parameter space
    EXPECT_NEAR(d.norm(), pca.sigmas[i], 1e-12);
    // d is an eigenvector of the covariance with eigenvalue sigma^2.
    EXPECT_LT((cov * d - pca.sigmas[i] * pca.sigmas[i] * d).norm(), 1e-12);
  }
  EXPECT_LT((basis * pca.meanWeights - mean).norm(), 1e-14);
}

}  // namespace
}  // namespace tetblend::cli
