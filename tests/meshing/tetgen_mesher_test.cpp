#include "tetblend/meshing/tetgen_mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "cgal_meshes.h"
#include "test_surfaces.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

using testing_surfaces::cube;
using testing_surfaces::join;
using testing_surfaces::reversed;

// Sum of ~1e4 tet volumes against the divergence-theorem sum over the
// surface: each term carries a few ulps of relative round-off.
constexpr double kVolumeRelTol = 1e-12;

using Face = std::array<int, 3>;

// Face with its smallest index first, orientation kept.
Face rotated(int a, int b, int c) {
  Face f{a, b, c};
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

// Oracle: faces used by exactly one tet, outward for positive tets.
std::vector<Face> boundaryFaces(const Tets& tets) {
  std::map<Face, std::vector<Face>> bySet;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    const int a = tets(t, 0), b = tets(t, 1), c = tets(t, 2), d = tets(t, 3);
    for (const Face& f : {Face{b, c, d}, Face{a, d, c}, Face{a, b, d}, Face{a, c, b}}) {
      Face key = f;
      std::sort(key.begin(), key.end());
      bySet[key].push_back(rotated(f[0], f[1], f[2]));
    }
  }
  std::vector<Face> boundary;
  for (const auto& [key, faces] : bySet) {
    if (faces.size() == 1) boundary.push_back(faces[0]);
  }
  std::sort(boundary.begin(), boundary.end());
  return boundary;
}

// Divergence theorem: volume enclosed by an outward surface.
double surfaceVolume(const SurfaceMesh& s) {
  double v = 0.0;
  for (Eigen::Index f = 0; f < s.triangles.rows(); ++f) {
    const Eigen::Vector3d a = s.vertices.row(s.triangles(f, 0));
    const Eigen::Vector3d b = s.vertices.row(s.triangles(f, 1));
    const Eigen::Vector3d c = s.vertices.row(s.triangles(f, 2));
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

// The contract of tetrahedralize, checked with independent oracles.
void expectBoundaryPreserved(const SurfaceMesh& surface, const TetMesh& mesh) {
  const Eigen::Index nv = surface.vertices.rows();
  ASSERT_GE(mesh.vertices.rows(), nv);
  EXPECT_EQ(std::memcmp(mesh.vertices.data(), surface.vertices.data(), sizeof(double) * 3 * nv), 0)
      << "surface vertices changed";
  std::vector<Face> input;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    input.push_back(
        rotated(surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2)));
  }
  std::sort(input.begin(), input.end());
  EXPECT_EQ(boundaryFaces(mesh.tets), input);
  double total = 0.0;
  int nonPositive = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const double v = tetSignedVolume(mesh.vertices, mesh.tets.row(t));
    nonPositive += v > 0.0 ? 0 : 1;
    total += v;
  }
  EXPECT_EQ(nonPositive, 0);
  const double expected = surfaceVolume(surface);
  EXPECT_NEAR(total, expected, kVolumeRelTol * std::abs(expected));
}

TEST(TetGenMesher, CubeKeepsItsSurface) {
  const SurfaceMesh surface = cube(Eigen::Vector3d(0.25, -1, 2), 2.0);
  const TetMesh mesh = tetrahedralize(surface);
  expectBoundaryPreserved(surface, mesh);
  // Steiner points strictly inside the box.
  for (Eigen::Index v = 8; v < mesh.vertices.rows(); ++v) {
    const Eigen::RowVector3d local = mesh.vertices.row(v) - Eigen::RowVector3d(0.25, -1, 2);
    EXPECT_GT(local.minCoeff(), 0.0);
    EXPECT_LT(local.maxCoeff(), 2.0);
  }
}

double largestTet(const TetMesh& mesh) {
  double largest = 0.0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    largest = std::max(largest, tetSignedVolume(mesh.vertices, mesh.tets.row(t)));
  }
  return largest;
}

// With the surface kept (switch Y) TetGen cannot split tets whose refinement
// point would encroach on the boundary, so the volume bound is pursued, not
// guaranteed: it must refine (more tets, smaller largest tet), not be exact.
TEST(TetGenMesher, RandomStarShapesWithAndWithoutAVolumeBound) {
  std::mt19937_64 rng(testing_surfaces::testSeed());
  TetGenOptions bounded;
  bounded.maxTetVolumeRelative = 1e-3;
  for (int trial = 0; trial < 5; ++trial) {
    SCOPED_TRACE(trial);
    const SurfaceMesh surface = testing_surfaces::randomStarShape(rng);
    const TetMesh coarse = tetrahedralize(surface);
    const TetMesh fine = tetrahedralize(surface, bounded);
    expectBoundaryPreserved(surface, coarse);
    expectBoundaryPreserved(surface, fine);
    EXPECT_GT(fine.tets.rows(), coarse.tets.rows());
    EXPECT_LT(largestTet(fine), largestTet(coarse));
  }
}

TEST(TetGenMesher, SeveralComponents) {
  const SurfaceMesh surface = join(cube(), cube(Eigen::Vector3d(1.5, 0.5, 0), 0.5));
  expectBoundaryPreserved(surface, tetrahedralize(surface));
}

TEST(TetGenMesher, CavityStaysEmpty) {
  const SurfaceMesh surface = join(cube(Eigen::Vector3d(-1, -1, -1), 3.0), reversed(cube()));
  const TetMesh mesh = tetrahedralize(surface);
  expectBoundaryPreserved(surface, mesh);  // volume 27 - 1
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.vertices.row(mesh.tets(t, k)) / 4.0;
    EXPECT_FALSE(c.minCoeff() > 0.0 && c.maxCoeff() < 1.0) << "tet " << t << " in the cavity";
  }
}

void expectRefused(const SurfaceMesh& surface, const std::string& needle) {
  TetGenOptions options;
  options.sourceName = "bad.off";
  try {
    tetrahedralize(surface, options);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.off"), std::string::npos) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << what;
    EXPECT_EQ(what.find("TetGen"), std::string::npos) << "reached TetGen: " << what;
  }
}

TEST(TetGenMesher, BadSurfacesAreRefusedBeforeTetGen) {
  expectRefused(join(cube(), cube(Eigen::Vector3d(0.5, 0.25, 0.125))), "intersect");
  SurfaceMesh open = cube();
  open.triangles.conservativeResize(10, 3);
  expectRefused(open, "boundary edge");
  expectRefused(reversed(cube()), "point inwards");
}

// Refused by TetGen itself (validation passes): an InputError naming the
// file and the cause, and this process survives (Debian's TetGen 1.5.0 would
// abort it in-process by freeing its mesh twice).
void expectTetGenRefuses(const SurfaceMesh& surface, const std::string& needle) {
  ASSERT_TRUE(validateSurface(surface, "close.off").ok());
  TetGenOptions options;
  options.sourceName = "close.off";
  try {
    tetrahedralize(surface, options);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("close.off"), std::string::npos) << what;
    EXPECT_NE(what.find("TetGen failed (code"), std::string::npos) << what;
    EXPECT_NE(what.find(needle), std::string::npos) << what;
  }
}

TEST(TetGenMesher, TetGenErrorsBecomeInputErrorsNotCrashes) {
  // Gap 1e-9 between faces of unit cubes: far below TetGen's relative
  // tolerance (1e-8 of the bounding box), so it reports facets too close.
  constexpr double kTinyGap = 1e-9;
  expectTetGenRefuses(join(cube(), cube(Eigen::Vector3d(1.0 + kTinyGap, 0, 0))), "close");
  // The same gap well above that tolerance is meshed normally (other side of
  // the threshold).
  constexpr double kSafeGap = 1e-3;
  const SurfaceMesh apart = join(cube(), cube(Eigen::Vector3d(1.0 + kSafeGap, 0, 0)));
  expectBoundaryPreserved(apart, tetrahedralize(apart));
  // The mesher still works after a refused surface.
  expectBoundaryPreserved(cube(), tetrahedralize(cube()));
}

TEST(TetGenMesher, InvalidOptions) {
  TetGenOptions options;
  options.maxRadiusEdgeRatio = 0.9;
  EXPECT_THROW(tetrahedralize(cube(), options), InputError);
  options.maxRadiusEdgeRatio = 0.0;  // no refinement: valid
  expectBoundaryPreserved(cube(), tetrahedralize(cube(), options));
  options.maxTetVolume = -1.0;
  EXPECT_THROW(tetrahedralize(cube(), options), InputError);
}

// A quality refinement stopped at its time limit (here one that no child
// process can meet) gives TetGen's plain tetrahedralisation, bit for bit,
// and one notice; within its limit the refinement adds Steiner points.
TEST(TetGenMesher, QualityRefinementPastItsTimeLimitGivesThePlainTetrahedralisation) {
  std::mt19937_64 rng(testing_surfaces::testSeed());
  const SurfaceMesh surface = testing_surfaces::randomStarShape(rng);
  TetGenOptions plain;
  plain.maxRadiusEdgeRatio = 0.0;
  const TetMesh unrefined = tetrahedralize(surface, plain);
  TetGenOptions options;
  options.maxTetVolumeRelative = 1e-3;
  options.sourceName = "star.off";
  std::vector<std::string> notices;
  options.notice = [&](const std::string& line) { notices.push_back(line); };
  const TetMesh refined = tetrahedralize(surface, options);
  EXPECT_TRUE(notices.empty());
  EXPECT_GT(refined.vertices.rows(), unrefined.vertices.rows());

  options.qualityTimeLimitSeconds = 1e-9;
  const TetMesh stopped = tetrahedralize(surface, options);
  expectBoundaryPreserved(surface, stopped);
  EXPECT_TRUE(stopped.tets == unrefined.tets);
  EXPECT_TRUE(stopped.vertices == unrefined.vertices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0].rfind("star.off: TetGen's quality refinement had not finished", 0), 0u)
      << notices[0];
}

TEST(TetGenMesher, ATimeLimitThatIsNotANumberIsRefused) {
  TetGenOptions options;
  options.qualityTimeLimitSeconds = std::nan("");
  EXPECT_THROW(tetrahedralize(cube(), options), InputError);
  options.qualityTimeLimitSeconds = -1.0;  // no limit: valid
  expectBoundaryPreserved(cube(), tetrahedralize(cube(), options));
}

TEST(TetGenMesher, SilentUnlessVerbosityIsAsked) {
  ::testing::internal::CaptureStdout();
  tetrahedralize(cube());
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  TetGenOptions options;
  options.verbosity = 1;
  ::testing::internal::CaptureStdout();
  tetrahedralize(cube(), options);
  EXPECT_NE(::testing::internal::GetCapturedStdout(), "");
}

TEST(TetGenMesher, RealMeshesFromCgalDemo) {
  const std::string tarball = testing_cgal::cgalDataTarball();
  if (tarball.empty()) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  const std::vector<std::string> names = {"sphere.off", "elephant.off"};
  const std::filesystem::path meshes = testing_cgal::extractCgalMeshes(
      tarball, {"sphere.off", "elephant.off", "camel.off"}, "tetgen");
  ASSERT_FALSE(meshes.empty());
  const std::filesystem::path dir = meshes.parent_path().parent_path();
  for (const std::string& n : names) {
    SCOPED_TRACE(n);
    const std::string path = (meshes / n).string();
    const SurfaceMesh surface = readSurface(path);
    const SurfaceValidation v = validateSurface(surface, path);
    ASSERT_TRUE(v.ok()) << v.problems.front().message;
    TetGenOptions options;
    options.sourceName = path;
    expectBoundaryPreserved(surface, tetrahedralize(surface, options));
  }
  // camel.off intersects itself: named by validation, refused before TetGen
  // (which would fail on it).
  const std::string camel = (meshes / "camel.off").string();
  const SurfaceMesh surface = readSurface(camel);
  const SurfaceValidation v = validateSurface(surface, camel);
  ASSERT_FALSE(v.problems.empty());
  EXPECT_EQ(v.problems.front().kind, SurfaceProblemKind::kSelfIntersection);
  EXPECT_THROW(tetrahedralize(surface), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tetblend
