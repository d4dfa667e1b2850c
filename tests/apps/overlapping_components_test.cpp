// End to end: a rest whose closed components go through one another (a
// character's eye and tooth through its head, bones through bones) is
// prepared by meshing each component on its own. Nothing is excluded, and
// blends give the rest at zero weights and each example at unit weights.
// --strict accepts it (nothing is inexact) but still refuses a component
// that intersects itself.

#include <cmath>

#include "posed_rest_fixture.h"
#include "test_surfaces.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_orientation.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::apps_test {
namespace {

// A sum of ~10^4 positive tet volumes against a total of ~2: round-off
// ~1e-14 relative; a missing tet is > 1e-5 of it.
constexpr double kVolumeRelTol = 1e-10;

SurfaceMesh sphereAt(const Eigen::RowVector3d& centre, const Eigen::RowVector3d& radii) {
  SurfaceMesh s = testing_surfaces::icosphere(3);
  s.vertices = (s.vertices.array().rowwise() * radii.array()).matrix();
  s.vertices.rowwise() += centre;
  return s;
}

// A body 4 long (x from -2 to 2) and 1 thick; an eye of radius 0.3
// centred on its surface near one end; a tooth of radius 0.2 through the
// eye and into the body.
class OverlappingComponents : public PosedRest {
 protected:
  void SetUp() override {
    PosedRest::SetUp();
    const std::vector<SurfaceMesh> parts = {sphereAt({0, 0, 0}, {2.0, 0.5, 0.5}),
                                            sphereAt({1.6, 0.3, 0}, {0.3, 0.3, 0.3}),
                                            sphereAt({1.6, 0.1, 0.2}, {0.2, 0.2, 0.2})};
    for (const SurfaceMesh& part : parts) componentVolumes_ += enclosedVolume(part);
    writePoses(testing_surfaces::join(testing_surfaces::join(parts[0], parts[1]), parts[2]));
  }
  double componentVolumes_ = 0.0;
};

TEST_F(OverlappingComponents, EachIsMeshedOnItsOwnAndNothingIsExcluded) {
  ASSERT_GT(findSelfIntersections(rest_.vertices, rest_.triangles, 1).pairCount, 0u);
  const RunResult r = tetblend(prepareArgs("head.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("rest.obj: its 3 closed components intersect one another"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const ModelData m = readModelFile(path("head.tbm"));
  EXPECT_TRUE(m.excludedTets.empty());
  EXPECT_TRUE(m.rest.vertices.topRows(rest_.vertices.rows()) == rest_.vertices);
  // Every component's solid is filled whole: the tet volumes add up to the
  // sum of the three enclosed volumes (a mesh of the union holds less), and
  // every tet is positive in the rest and in both examples.
  double volume = 0.0;
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    const double v = tetSignedVolume(m.rest.vertices, m.rest.tets.row(t));
    EXPECT_GT(v, 0.0) << "tet " << t;
    volume += v;
    for (const Vertices& example : m.examples) {
      EXPECT_GT(tetSignedVolume(example, m.rest.tets.row(t)), 0.0) << "tet " << t;
    }
  }
  EXPECT_NEAR(volume, componentVolumes_, kVolumeRelTol * componentVolumes_);
}

TEST_F(OverlappingComponents, BlendsGiveTheRestAndEveryExample) {
  ASSERT_EQ(tetblend(prepareArgs("head.tbm"), dir_).code, 0);
  expectTheKeysBack("head.tbm");
}

TEST_F(OverlappingComponents, StrictAcceptsThemButNotAComponentThatIntersectsItself) {
  std::vector<std::string> args = prepareArgs("strict.tbm");
  args.push_back("--strict");
  const RunResult accepted = tetblend(args, dir_);
  ASSERT_EQ(accepted.code, 0) << accepted.err;

  // The eye's far cap (x > 1.75) pushed 0.4 along -x, through the eye's
  // own near side.
  Vertices folded = rest_.vertices;
  const Eigen::Index eyeBegin = rest_.vertices.rows() / 3, eyeEnd = 2 * eyeBegin;
  for (Eigen::Index v = eyeBegin; v < eyeEnd; ++v) {
    if (folded(v, 0) > 1.75) folded(v, 0) -= 0.4;
  }
  write("rest.obj", folded);
  const std::vector<std::string> before = listDir(dir_);
  args[args.size() - 2] = path("refused.tbm");
  const RunResult refused = tetblend(args, dir_);
  expectOneLineError(refused);
  EXPECT_NE(refused.err.find("rest.obj: faces "), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("of one closed component intersect"), std::string::npos)
      << refused.err;
  EXPECT_EQ(listDir(dir_), before);
}

// Two eyes (radii 0.2 and 0.12) wholly inside a body (4 by 1 by 1), touching
// nothing. Faced outward, as the user's solids, they are meshed on their
// own (the tet volumes add up to the three solids'); faced inward, they are
// cavities, left empty (the body's volume less theirs).
class NestedComponents : public PosedRest {
 protected:
  SurfaceMesh headWithEyes(bool eyesFaceOutward) {
    SurfaceMesh left = sphereAt({0.8, 0.12, 0}, {0.2, 0.2, 0.2});
    SurfaceMesh right = sphereAt({0.8, -0.22, 0}, {0.12, 0.12, 0.12});
    if (!eyesFaceOutward) {
      left = testing_surfaces::reversed(left);
      right = testing_surfaces::reversed(right);
    }
    const SurfaceMesh body = sphereAt({0, 0, 0}, {2.0, 0.5, 0.5});
    bodyVolume_ = enclosedVolume(body);
    eyeVolumes_ = std::abs(enclosedVolume(left)) + std::abs(enclosedVolume(right));
    return testing_surfaces::join(testing_surfaces::join(body, left), right);
  }
  double tetVolume(const std::string& model) const {
    const ModelData m = readModelFile(path(model));
    double volume = 0.0;
    for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
      volume += tetSignedVolume(m.rest.vertices, m.rest.tets.row(t));
    }
    return volume;
  }
  double bodyVolume_ = 0.0, eyeVolumes_ = 0.0;
};

TEST_F(NestedComponents, EyesFacingOutwardAreSolidsOfTheirOwn) {
  writePoses(headWithEyes(true));
  ASSERT_EQ(findSelfIntersections(rest_.vertices, rest_.triangles, 1).pairCount, 0u);
  const RunResult r = tetblend(prepareArgs("eyes.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("rest.obj: 2 closed components inside others face outward"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const double expected = bodyVolume_ + eyeVolumes_;
  EXPECT_NEAR(tetVolume("eyes.tbm"), expected, kVolumeRelTol * expected);
  expectTheKeysBack("eyes.tbm");
}

TEST_F(NestedComponents, EyesFacingInwardAreCavities) {
  writePoses(headWithEyes(false));
  const RunResult r = tetblend(prepareArgs("cavities.tbm"), dir_);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("inside others face outward"), std::string::npos) << r.err;
  const double expected = bodyVolume_ - eyeVolumes_;
  EXPECT_NEAR(tetVolume("cavities.tbm"), expected, kVolumeRelTol * expected);
}

}  // namespace
}  // namespace tetblend::apps_test
