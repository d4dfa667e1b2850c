// tetblend variations and animate: file sets, .pvd collections, weights,
// reproducibility, key interpolation.

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

// Different seeds give different weights: shapes differ by a fair fraction of
// the bar (size ~4), 1e-3 is far above any round-off.
constexpr double kDifferentSeedsGap = 1e-3;
// weights.csv holds shortest round-trip numbers, so the mean weight 1/(n+1)
// comes back as computed: within an ulp of 1/3 (5.6e-17).
constexpr double kMeanWeightTolerance = 1e-15;
// A PCA sweep is mean + t step with t = -range, 0, range (a product and a
// sum, each rounded to ~1 ulp of O(1) weights), so the two ends sum to twice
// the mean within a few ulps.
constexpr double kSweepSymmetryTolerance = 1e-12;

std::vector<std::vector<double>> readWeightsCsv(const fs::path& p) {
  std::istringstream in(slurp(p));
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    std::getline(cells, cell, ',');  // name
    std::getline(cells, cell, ',');  // time
    std::vector<double> w;
    while (std::getline(cells, cell, ',')) w.push_back(std::stod(cell));
    rows.push_back(w);
  }
  return rows;
}

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class SeriesCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
  }
  fs::path dir_;
  fs::path model_;
};

TEST_F(SeriesCommands, VariationsAreReproducibleAndInsideTheSimplex) {
  for (const char* out : {"v1", "v2"})
    ASSERT_EQ(tetblend({"variations", model_.string(), "-n", "3", "--seed", "7", "-o",
                        (dir_ / out).string()},
                       dir_)
                  .code,
              0);
  ASSERT_EQ(tetblend({"variations", model_.string(), "-n", "3", "--seed", "8", "-o",
                      (dir_ / "v3").string()},
                     dir_)
                .code,
            0);
  EXPECT_EQ(countOf(slurp(dir_ / "v1" / "variations.pvd"), "<DataSet"), 3u);
  for (int i = 0; i < 3; ++i) {
    const std::string name = "variation_00" + std::to_string(i) + ".vtp";
    EXPECT_EQ(
        maxDistance(pointsOf(readVtp(dir_ / "v1" / name)), pointsOf(readVtp(dir_ / "v2" / name))),
        0.0);
    EXPECT_GT(
        maxDistance(pointsOf(readVtp(dir_ / "v1" / name)), pointsOf(readVtp(dir_ / "v3" / name))),
        kDifferentSeedsGap);
  }
  for (const auto& w : readWeightsCsv(dir_ / "v1" / "weights.csv")) {
    ASSERT_EQ(w.size(), 2u);
    EXPECT_GE(w[0], 0.0);
    EXPECT_GE(w[1], 0.0);
    EXPECT_LE(w[0] + w[1], 1.0);
  }
}

TEST_F(SeriesCommands, PcaMeanIsTheCentreOfEachComponentSweep) {
  ASSERT_EQ(tetblend({"variations", model_.string(), "--pca", "-n", "3", "--components", "1", "-o",
                      (dir_ / "pca").string()},
                     dir_)
                .code,
            0);
  const auto weights = readWeightsCsv(dir_ / "pca" / "weights.csv");
  ASSERT_EQ(weights.size(), 4u);  // mean + 3 along component 1
  EXPECT_NEAR(weights[0][0], 1.0 / 3.0, kMeanWeightTolerance);
  EXPECT_NEAR(weights[0][1], 1.0 / 3.0, kMeanWeightTolerance);
  // The middle of an odd sweep is t = 0: the mean itself.
  EXPECT_LT(maxDistance(pointsOf(readVtp(dir_ / "pca" / "pc1_001.vtp")),
                        pointsOf(readVtp(dir_ / "pca" / "pca_mean.vtp"))),
            kInterpolationTolerance);
  // The sweep is symmetric about the mean in weight space.
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(weights[1][k] + weights[3][k], 2.0 * weights[0][k], kSweepSymmetryTolerance);
}

TEST_F(SeriesCommands, LinearAnimationPassesThroughTheKeys) {
  ASSERT_EQ(tetblend({"animate", model_.string(), "--keys", "0,0;1,0;0,1", "--frames", "5",
                      "--spline", "linear", "-o", (dir_ / "anim").string()},
                     dir_)
                .code,
            0);
  const std::string pvd = slurp(dir_ / "anim" / "animation.pvd");
  EXPECT_EQ(countOf(pvd, "<DataSet"), 5u);
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos) << pvd;
  const struct {
    const char* frame;
    const char* sample;
  } keys[] = {{"frame_0000.vtp", "bar_rest.obj"},
              {"frame_0002.vtp", "bar_twist4pi.obj"},
              {"frame_0004.vtp", "bar_bend.obj"}};
  for (const auto& k : keys) {
    SCOPED_TRACE(k.frame);
    EXPECT_LT(maxDistance(pointsOf(readVtp(dir_ / "anim" / k.frame)),
                          readSurface((dir_ / k.sample).string()).vertices),
              kInterpolationTolerance);
  }
}

}  // namespace
}  // namespace tetblend::apps_test
