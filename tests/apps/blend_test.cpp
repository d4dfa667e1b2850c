// End to end: prepare the bar samples, blend at the rest, at each example and
// straight from surface files; outputs read back with VTK's readers.

#include "apps_test_support.h"

namespace tetblend::apps_test {
namespace {

class BlendCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir();
    model_ = prepareBar(dir_);
  }
  SurfaceMesh sample(const std::string& name) const { return readSurface((dir_ / name).string()); }
  fs::path dir_;
  fs::path model_;
};

TEST_F(BlendCommand, ZeroWeightsGiveTheRestWithQualityArrays) {
  const RunResult r = tetblend(
      {"blend", model_.string(), "--weights", "0,0", "-o", (dir_ / "b.vtu").string()}, dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  const SurfaceMesh rest = sample("bar_rest.obj");
  const auto vtp = readVtp(dir_ / "b.vtp");
  EXPECT_LT(maxDistance(pointsOf(vtp), rest.vertices), kInterpolationTolerance);
  EXPECT_EQ(vtp->GetNumberOfPolys(), rest.triangles.rows());
  vtkDataArray* inputIndex = vtp->GetPointData()->GetArray("input_vertex_index");
  ASSERT_NE(inputIndex, nullptr);
  ASSERT_EQ(inputIndex->GetNumberOfTuples(), rest.vertices.rows());
  for (vtkIdType i = 0; i < inputIndex->GetNumberOfTuples(); ++i) {
    ASSERT_EQ(inputIndex->GetTuple1(i), static_cast<double>(i));
  }

  const auto vtu = readVtu(dir_ / "b.vtu");
  ASSERT_GT(vtu->GetNumberOfCells(), 0);
  EXPECT_GE(vtu->GetNumberOfPoints(), rest.vertices.rows());
  EXPECT_LT(maxDistance(pointsOf(vtu).topRows(rest.vertices.rows()), rest.vertices),
            kInterpolationTolerance);
  vtkDataArray* displacement = vtu->GetPointData()->GetArray("displacement");
  ASSERT_NE(displacement, nullptr);
  EXPECT_EQ(displacement->GetNumberOfComponents(), 3);
  for (const char* name :
       {"volume_ratio", "inverted", "target_residual", "distortion", "rotation_angle"}) {
    vtkDataArray* a = vtu->GetCellData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->GetNumberOfTuples(), vtu->GetNumberOfCells()) << name;
  }
  vtkDataArray* ratio = vtu->GetCellData()->GetArray("volume_ratio");
  for (vtkIdType j = 0; j < ratio->GetNumberOfTuples(); ++j) {
    // The rest keeps volumes.
    ASSERT_NEAR(ratio->GetTuple1(j), 1.0, kRestQualityTolerance) << "tet " << j;
  }
  // The rest is the identity map of every tet: no distortion, no rotation.
  vtkDataArray* distortion = vtu->GetCellData()->GetArray("distortion");
  vtkDataArray* angle = vtu->GetCellData()->GetArray("rotation_angle");
  for (vtkIdType j = 0; j < distortion->GetNumberOfTuples(); ++j) {
    ASSERT_NEAR(distortion->GetTuple1(j), 1.0, kRestQualityTolerance) << "tet " << j;
    ASSERT_NEAR(angle->GetTuple1(j), 0.0, kRestQualityTolerance) << "tet " << j;
  }
  for (vtkIdType i = 0; i < displacement->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(displacement->GetComponent(i, c), 0.0, kInterpolationTolerance);
}

TEST_F(BlendCommand, UnitWeightsGiveEachExampleForEveryMapMethod) {
  for (const std::string method : {"kaji", "dq", "linear", "vertex-linear"}) {
    SCOPED_TRACE(method);
    const fs::path twist = dir_ / (method + "_twist.vtu"), bend = dir_ / (method + "_bend.vtu");
    ASSERT_EQ(
        tetblend({"blend", model_.string(), "-w", "1,0", "--method", method, "-o", twist.string()},
                 dir_)
            .code,
        0);
    ASSERT_EQ(tetblend({"blend", model_.string(), "-w", "0,1", "--method", method, "-o",
                        bend.string(), "--surface-format", "obj"},
                       dir_)
                  .code,
              0);
    EXPECT_LT(maxDistance(pointsOf(readVtp(fs::path(twist).replace_extension(".vtp"))),
                          sample("bar_twist4pi.obj").vertices),
              kInterpolationTolerance);
    EXPECT_LT(maxDistance(pointsOf(readVtp(fs::path(bend).replace_extension(".vtp"))),
                          sample("bar_bend.obj").vertices),
              kInterpolationTolerance);
    const SurfaceMesh obj = readSurface(fs::path(bend).replace_extension(".obj").string());
    EXPECT_LT(maxDistance(obj.vertices, sample("bar_bend.obj").vertices), kInterpolationTolerance);
  }
}

// deform's name for dual quaternions, dqs, is an alias of blend's dq.
TEST_F(BlendCommand, MethodAliasDqsIsDq) {
  for (const std::string method : {"dq", "dqs"}) {
    const RunResult r = tetblend({"blend", model_.string(), "-w", "0.3,0.4", "--method", method,
                                  "-o", (dir_ / (method + ".vtu")).string()},
                                 dir_);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  EXPECT_TRUE(slurp(dir_ / "dq.vtu") == slurp(dir_ / "dqs.vtu"));
  EXPECT_TRUE(slurp(dir_ / "dq.vtp") == slurp(dir_ / "dqs.vtp"));
}

TEST_F(BlendCommand, InvertedTetsAreWarnedAboutAndOverflowIsAWeightsError) {
  // Far extrapolation (the 5,-4) turns tets inside out: the blend is
  // written, with one warning line counting them.
  const RunResult far =
      tetblend({"blend", model_.string(), "-w", "5,-4", "-o", (dir_ / "far.vtu").string()}, dir_);
  ASSERT_EQ(far.code, 0) << far.err;
  EXPECT_EQ(far.err.rfind("tetblend: warning: ", 0), 0u) << far.err;
  EXPECT_NE(far.err.find("tets are inverted at weights 5,-4"), std::string::npos) << far.err;
  EXPECT_EQ(std::count(far.err.begin(), far.err.end(), '\n'), 1) << far.err;
  // Weights of 1e300 overflow: refused as a weights problem, nothing written.
  const std::vector<std::string> before = listDir(dir_);
  const RunResult huge = tetblend(
      {"blend", model_.string(), "-w", "1e300,0", "-o", (dir_ / "huge.vtu").string()}, dir_);
  expectOneLineError(huge);
  EXPECT_NE(huge.err.find("weights 1e+300,0: "), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("overflow"), std::string::npos) << huge.err;
  EXPECT_EQ(listDir(dir_), before);
}

TEST_F(BlendCommand, StraightFromSurfacesMatchesTheModel) {
  const RunResult r =
      tetblend({"blend", "--rest", (dir_ / "bar_rest.obj").string(), "--example",
                (dir_ / "bar_twist4pi.obj").string(), "--example", (dir_ / "bar_bend.obj").string(),
                "-w", "0.3,0.4", "-o", (dir_ / "direct.vtu").string(), "--quiet"},
               dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(
      tetblend({"blend", model_.string(), "-w", "0.3,0.4", "-o", (dir_ / "via_model.vtu").string()},
               dir_)
          .code,
      0);
  // Same surfaces, same TetGen run and placement: the same shape to round-off.
  EXPECT_LT(maxDistance(pointsOf(readVtp(dir_ / "direct.vtp")),
                        pointsOf(readVtp(dir_ / "via_model.vtp"))),
            kInterpolationTolerance);
}

// A model prepared with --fast-load keeps the factor and the kaji
// parameters: it is larger, and its blends are those of the plain model byte
// for byte (the same computation, done at prepare instead of at load).
TEST_F(BlendCommand, FastLoadModelBlendsByteForByteAsThePlainOne) {
  const fs::path fast = dir_ / "fast.tbm";
  const RunResult prepared =
      tetblend({"prepare", (dir_ / "bar_rest.obj").string(), (dir_ / "bar_twist4pi.obj").string(),
                (dir_ / "bar_bend.obj").string(), "-o", fast.string(), "--fast-load"},
               dir_);
  ASSERT_EQ(prepared.code, 0) << prepared.err;
  EXPECT_NE(prepared.err.find("fast load: the model keeps the stitch factor"), std::string::npos)
      << prepared.err;
  EXPECT_GT(fs::file_size(fast), fs::file_size(model_));
  const RunResult inspected = tetblend({"inspect", fast.string()}, dir_);
  ASSERT_EQ(inspected.code, 0) << inspected.err;
  EXPECT_NE(inspected.out.find("format version 4"), std::string::npos) << inspected.out;
  EXPECT_NE(inspected.out.find("fast load: the stitch factor"), std::string::npos) << inspected.out;
  for (const std::string method : {"kaji", "dq"}) {
    for (const auto& [model, name] : {std::pair{model_, "plain"}, std::pair{fast, "fast"}}) {
      const RunResult r = tetblend({"blend", model.string(), "-w", "0.3,0.4", "--method", method,
                                    "-o", (dir_ / (method + name + ".vtu")).string(), "--quiet"},
                                   dir_);
      ASSERT_EQ(r.code, 0) << r.err;
    }
    EXPECT_EQ(slurp(dir_ / (method + "plain.vtu")), slurp(dir_ / (method + "fast.vtu"))) << method;
    EXPECT_EQ(slurp(dir_ / (method + "plain.vtp")), slurp(dir_ / (method + "fast.vtp"))) << method;
  }
}

}  // namespace
}  // namespace tetblend::apps_test
