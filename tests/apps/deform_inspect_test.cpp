// tetblend deform (probe deformer, Kaji–Ochiai §6.1) and tetblend inspect.

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "apps_test_support.h"
#include "tetblend/core/constants.h"

namespace tetblend::apps_test {
namespace {

using nlohmann::json;
// Rigid maps of unit-size coordinates evaluated in closed form: ~10 ulps.
constexpr double kRigidTolerance = 1e-12;
// Weights 1/2 on a fixed probe and one turned by 2 pi: kaji's half-turn is
// exp(pi x), with sin(pi) rounded to 1.2e-16 instead of 0, and dqs sees the
// 2 pi turn as the quaternion -1 up to the rounding of cos(pi) and sin(pi):
// a few ulps of the bar's O(1) coordinates; 1e-9 is generous.
constexpr double kFullTurnTolerance = 1e-9;

class DeformCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    makeSamples(dir_);
    rest_ = readSurface((dir_ / "bar_rest.obj").string());
  }
  fs::path deform(const json& handles, const std::string& method) {
    std::ofstream(dir_ / "h.json") << handles.dump();
    const fs::path out = dir_ / (method + ".vtp");
    const RunResult r =
        tetblend({"deform", (dir_ / "bar_rest.obj").string(), "--handles",
                  (dir_ / "h.json").string(), "--method", method, "-o", out.string()},
                 dir_);
    EXPECT_EQ(r.code, 0) << r.err;
    return out;
  }
  fs::path dir_;
  SurfaceMesh rest_;
};

TEST_F(DeformCommand, OneHandleMovesEverythingRigidlyWithEveryMethod) {
  const json handles{{"handles",
                      {{{"name", "h"},
                        {"centre", {0, 0, 0}},
                        {"rotation", {0, 0, kPi / 2}},
                        {"translation", {1, 2, 3}}}}}};
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).matrix();
  Vertices expected = (rest_.vertices * rot.transpose()).rowwise() + Eigen::RowVector3d(1, 2, 3);
  for (const std::string method : {"lbs", "dqs", "kaji", "kaji-frechet"}) {
    SCOPED_TRACE(method);
    const auto vtp = readVtp(deform(handles, method));
    EXPECT_LT(maxDistance(pointsOf(vtp), expected), kRigidTolerance);
    ASSERT_NE(vtp->GetPointData()->GetArray("displacement"), nullptr);
  }
}

TEST_F(DeformCommand, HalfOfAFullTurnIsAHalfTurnForKajiAndNothingForDqs) {
  // Kaji–Ochiai §6.1 Fig. 2: a probe turned by 2 pi next to a fixed one.
  // Weight 1/2 each: kaji blends rotation vectors, giving a turn by pi about
  // x ((x, y, z) -> (x, -y, -z)); dual quaternions see the 2 pi turn as the
  // identity and do not deform at all.
  json handles{
      {"handles", {{{"name", "fixed"}}, {{"name", "turned"}, {"rotation", {2 * kPi, 0, 0}}}}}};
  handles["weights"] = json::array();
  for (Eigen::Index v = 0; v < rest_.vertices.rows(); ++v) handles["weights"].push_back({0.5, 0.5});
  Vertices flipped = rest_.vertices;
  flipped.col(1) *= -1.0;
  flipped.col(2) *= -1.0;
  EXPECT_LT(maxDistance(pointsOf(readVtp(deform(handles, "kaji"))), flipped), kFullTurnTolerance);
  EXPECT_LT(maxDistance(pointsOf(readVtp(deform(handles, "dqs"))), rest_.vertices),
            kFullTurnTolerance);
}

// blend's name for dual quaternions, dq, is deform's too; dqs stays an alias.
TEST_F(DeformCommand, DqAndItsAliasDqsAreOneMethod) {
  const json handles{
      {"handles", {{{"name", "fixed"}}, {{"name", "turned"}, {"rotation", {0, 0, 1}}}}}};
  const std::string dq = slurp(deform(handles, "dq"));
  ASSERT_FALSE(dq.empty());
  EXPECT_TRUE(dq == slurp(deform(handles, "dqs")));
  const RunResult r =
      tetblend({"deform", (dir_ / "bar_rest.obj").string(), "--handles", (dir_ / "h.json").string(),
                "--method", "dual", "-o", (dir_ / "o.vtp").string()},
               dir_);
  expectOneLineError(r);
  EXPECT_NE(r.err.find("use lbs, dq, kaji, kaji-frechet (dqs = dq)"), std::string::npos) << r.err;
}

TEST_F(DeformCommand, BadHandleFilesAreOneLineErrors) {
  std::ofstream(dir_ / "h.json") << R"({"handles": [{"matrix": [[1,0,0]]}]})";
  expectOneLineError(tetblend({"deform", (dir_ / "bar_rest.obj").string(), "--handles",
                               (dir_ / "h.json").string(), "-o", (dir_ / "o.vtp").string()},
                              dir_));
  std::ofstream(dir_ / "h2.json") << R"({"handles": [{"rotation": [0,0,1]}], "weights": [[1]]})";
  expectOneLineError(tetblend({"deform", (dir_ / "bar_rest.obj").string(), "--handles",
                               (dir_ / "h2.json").string(), "-o", (dir_ / "o.vtp").string()},
                              dir_));
  EXPECT_FALSE(fs::exists(dir_ / "o.vtp"));
}

TEST(InspectCommand, ReportsCountsAndProblems) {
  const fs::path dir = scratchDir();
  const fs::path model = prepareBar(dir);
  const SurfaceMesh rest = readSurface((dir / "bar_rest.obj").string());
  RunResult r = tetblend({"inspect", (dir / "bar_rest.obj").string(), model.string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(std::to_string(rest.vertices.rows()) + " vertices, " +
                       std::to_string(rest.triangles.rows()) + " triangles"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("validation: ok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tetblend model"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("inverted tets 0"), std::string::npos) << r.out;

  // An open surface: drop the last face.
  writeSurface((dir / "open.obj").string(),
               SurfaceMesh{rest.vertices, rest.triangles.topRows(rest.triangles.rows() - 1)});
  r = tetblend({"inspect", (dir / "open.obj").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("problem"), std::string::npos) << r.out;

  expectOneLineError(tetblend({"inspect", (dir / "missing.obj").string()}, dir));
}

}  // namespace
}  // namespace tetblend::apps_test
