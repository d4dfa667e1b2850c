#pragma once
// The fixture of the end-to-end tests of rests made of several parts: a
// rest 4 long along x (from x = -2) written with two poses, a twist by π
// and a bend by 90° about y, then prepared and blended at the keys.

#include <string>
#include <utility>
#include <vector>

#include "apps_test_support.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend::apps_test {

// The promise: unit weights reproduce each example at the surface to
// 1e-9 of the bounding-box diagonal (round-off is ~1e-13 on these meshes).
constexpr double kPosedRestInterpolationRelTol = 1e-9;

class PosedRest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratchDir(); }

  /// Writes `rest` as rest.obj, its twist as twist.obj and its bend as
  /// bend.obj.
  void writePoses(const SurfaceMesh& rest) {
    rest_ = rest;
    const Eigen::Vector3d origin(-2.0, 0.0, 0.0), axis = Eigen::Vector3d::UnitX();
    write("rest.obj", rest_.vertices);
    write("twist.obj", twistAboutAxis(rest_.vertices, origin, axis, kPi, 4.0));
    write("bend.obj",
          bendAboutAxis(rest_.vertices, origin, axis, Eigen::Vector3d::UnitY(), 0.5 * kPi, 4.0));
  }
  void write(const std::string& name, const Vertices& vertices) const {
    writeSurface(path(name), SurfaceMesh{vertices, rest_.triangles});
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> prepareArgs(const std::string& model) const {
    return {"prepare", path("rest.obj"), path("twist.obj"), path("bend.obj"), "-o", path(model)};
  }

  /// Blends of `model` with kaji, liebodies and dq give the rest at weights
  /// 0,0 and each pose at its unit weights, at every input vertex.
  void expectTheKeysBack(const std::string& model) const {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"0,0", "rest.obj"}, {"1,0", "twist.obj"}, {"0,1", "bend.obj"}};
    for (const std::string method : {"kaji", "liebodies", "dq"}) {
      for (const auto& [weights, expected] : cases) {
        SCOPED_TRACE(method + " at " + weights);
        const std::string out = path(method + weights.substr(0, 1) + weights.substr(2) + ".vtp");
        const RunResult r =
            tetblend({"blend", path(model), "-w", weights, "--method", method, "-o", out}, dir_);
        ASSERT_EQ(r.code, 0) << r.err;
        const SurfaceMesh target = readSurface(path(expected));
        EXPECT_LT(maxDistance(pointsOf(readVtp(out)), target.vertices),
                  kPosedRestInterpolationRelTol * boundingBoxDiagonal(target.vertices));
      }
    }
  }

  fs::path dir_;
  SurfaceMesh rest_;
};

}  // namespace tetblend::apps_test
