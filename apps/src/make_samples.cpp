// tetblend-make-samples OUT_DIR: writes the small compatible example sets of
// samples/ from the project's procedural shapes (procedural_shapes.h):
//   bar_rest.obj, bar_twist4pi.obj, bar_bend.obj   a square bar; twisted by 4 pi
//                                                   about its axis (beyond 2 pi:
//                                                   Kaji–Ochiai Fig. 2), bent by pi/2
//   cyl_rest.off, cyl_bend90.off, cyl_bend180.off  a cylinder bent into an L and a U
//   limb_rest.obj, limb_dqs.obj, limb_lbs.obj      a two-bone limb bent 90 degrees at
//                                                   its middle joint by dual-quaternion
//                                                   and by linear-blend skinning
//                                                   (Kavan et al. §4: LBS collapses)
//   limb_lbs170.obj                                 the limb bent 170 degrees by LBS: its
//                                                   elbow folds into itself (a pose whose
//                                                   surface intersects itself)
// Every example shares the triangles of its rest surface (boundary of a
// procedural tet mesh, interior vertices dropped).

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "tetblend/core/constants.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tet_boundary.h"

namespace {

using tetblend::kPi;
using tetblend::SurfaceMesh;
using tetblend::Vertices;

SurfaceMesh surfaceOf(const tetblend::TetMesh& mesh) {
  const SurfaceMesh boundary = tetblend::boundarySurface(mesh);
  return tetblend::removeVertices(boundary, tetblend::unreferencedVertices(boundary));
}

void write(const std::string& dir, const std::string& name, const SurfaceMesh& rest,
           const Vertices& positions) {
  tetblend::writeSurface((std::filesystem::path(dir) / name).string(),
                         SurfaceMesh{positions, rest.triangles});
}

void makeBar(const std::string& dir) {
  constexpr double kLength = 4.0;
  const SurfaceMesh rest =
      surfaceOf(tetblend::boxTetMesh(32, 3, 3, Eigen::Vector3d(kLength, 0.6, 0.6)));
  const Eigen::Vector3d start(-kLength / 2, 0, 0), x = Eigen::Vector3d::UnitX();
  write(dir, "bar_rest.obj", rest, rest.vertices);
  write(dir, "bar_twist4pi.obj", rest,
        tetblend::twistAboutAxis(rest.vertices, start, x, 4 * kPi, kLength));
  write(
      dir, "bar_bend.obj", rest,
      tetblend::bendAboutAxis(rest.vertices, start, x, Eigen::Vector3d::UnitY(), kPi / 2, kLength));
}

void makeCylinder(const std::string& dir) {
  constexpr double kLength = 3.0;
  const SurfaceMesh rest = surfaceOf(tetblend::cylinderTetMesh(2, 12, 0.3, kLength));
  const Eigen::Vector3d start(-kLength / 2, 0, 0), x = Eigen::Vector3d::UnitX();
  write(dir, "cyl_rest.off", rest, rest.vertices);
  write(
      dir, "cyl_bend90.off", rest,
      tetblend::bendAboutAxis(rest.vertices, start, x, Eigen::Vector3d::UnitY(), kPi / 2, kLength));
  write(dir, "cyl_bend180.off", rest,
        tetblend::bendAboutAxis(rest.vertices, start, x, Eigen::Vector3d::UnitY(), kPi, kLength));
}

void makeLimb(const std::string& dir) {
  const SurfaceMesh rest = surfaceOf(tetblend::cylinderTetMesh(2, 16, 0.25, 3.0));
  const Eigen::Vector3d joint = Eigen::Vector3d::Zero();
  const Eigen::MatrixXd weights =
      tetblend::twoBoneWeights(rest.vertices, joint, Eigen::Vector3d::UnitX(), 0.5);
  const std::vector<Eigen::Isometry3d> bones{
      Eigen::Isometry3d::Identity(),
      tetblend::rotationAboutLine(joint, Eigen::Vector3d::UnitZ(), kPi / 2)};
  write(dir, "limb_rest.obj", rest, rest.vertices);
  write(dir, "limb_dqs.obj", rest, tetblend::dualQuaternionSkinning(rest.vertices, weights, bones));
  write(dir, "limb_lbs.obj", rest, tetblend::linearBlendSkinning(rest.vertices, weights, bones));
  const std::vector<Eigen::Isometry3d> folded{
      Eigen::Isometry3d::Identity(),
      tetblend::rotationAboutLine(joint, Eigen::Vector3d::UnitZ(), 170 * kPi / 180)};
  write(dir, "limb_lbs170.obj", rest,
        tetblend::linearBlendSkinning(rest.vertices, weights, folded));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: tetblend-make-samples OUT_DIR\n");
    return 2;
  }
  try {
    std::filesystem::create_directories(argv[1]);
    makeBar(argv[1]);
    makeCylinder(argv[1]);
    makeLimb(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tetblend-make-samples: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
