#include "tetblend/meshing/surface_validation.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "test_surfaces.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_orientation.h"

namespace tetblend {
namespace {

// The flap's relative area against h / 4: the dropped second-order term is
// h^2 / 2 relative (~1e-23) and the flap's cross product has one nonzero
// product (1 * h), so its area is exact up to a few roundings relative.
constexpr double kFirstOrderRelative = 1e-6;
// Signed volumes of cubes with small integer corners: sums of exact integer
// products over 6, exact or within an ulp of the volume.
constexpr double kUnitCubeVolume = 1e-15;
// 27 - 1 summed over 24 triangles of corners -1 to 2: a few ulps of 27 (ulp
// 3.6e-15).
constexpr double kCavityVolume = 1e-13;

using testing_surfaces::cube;
using testing_surfaces::join;
using testing_surfaces::reversed;
using Kind = SurfaceProblemKind;

const std::string kFile = "model.off";

// First problem of `kind`, or nullptr.
const SurfaceProblem* find(const SurfaceValidation& v, Kind kind) {
  for (const SurfaceProblem& p : v.problems) {
    if (p.kind == kind) return &p;
  }
  return nullptr;
}

int count(const SurfaceValidation& v, Kind kind) {
  int n = 0;
  for (const SurfaceProblem& p : v.problems) n += p.kind == kind ? 1 : 0;
  return n;
}

// The problem exists, names the file and the element as "<what> <index>".
void expectProblem(const SurfaceValidation& v, Kind kind, long long element,
                   const std::string& what) {
  const SurfaceProblem* p = find(v, kind);
  ASSERT_NE(p, nullptr) << problemKindName(kind);
  EXPECT_EQ(p->element, element) << p->message;
  EXPECT_NE(p->message.find(kFile), std::string::npos) << p->message;
  EXPECT_NE(p->message.find(what + " " + std::to_string(element)), std::string::npos) << p->message;
}

SurfaceValidationOptions openOptions() {
  SurfaceValidationOptions options;
  options.requireClosed = false;
  return options;
}

TEST(SurfaceValidation, CleanCubeHasNoProblemAtAnyScale) {
  for (double scale : {1e-8, 1.0, 1e8}) {
    SCOPED_TRACE(scale);
    const SurfaceValidation v = validateSurface(cube(Eigen::Vector3d(3, -2, 1), scale), kFile);
    EXPECT_TRUE(v.ok()) << v.problems.front().message;
    EXPECT_EQ(v.componentCount, 1);
  }
}

TEST(SurfaceValidation, EmptySurface) {
  const SurfaceValidation v = validateSurface(SurfaceMesh{}, kFile);
  ASSERT_EQ(v.problems.size(), 1u);
  EXPECT_EQ(v.problems[0].kind, Kind::kEmpty);
}

TEST(SurfaceValidation, NonFiniteCoordinatesNameTheVertex) {
  SurfaceMesh m = cube();
  m.vertices(3, 1) = std::numeric_limits<double>::quiet_NaN();
  m.vertices(6, 2) = -std::numeric_limits<double>::infinity();
  const SurfaceValidation v = validateSurface(m, kFile);
  EXPECT_EQ(count(v, Kind::kNonFiniteCoordinate), 2);
  expectProblem(v, Kind::kNonFiniteCoordinate, 3, "vertex");
  EXPECT_TRUE(std::isinf(v.problems[1].value));
  EXPECT_EQ(v.problems[1].element, 6);
}

TEST(SurfaceValidation, IndexOutOfRangeStopsFurtherChecks) {
  SurfaceMesh m = cube();
  m.triangles(5, 2) = 8;
  const SurfaceValidation v = validateSurface(m, kFile);
  ASSERT_EQ(v.problems.size(), 1u);
  expectProblem(v, Kind::kIndexOutOfRange, 5, "face");
  EXPECT_EQ(v.problems[0].value, 8);
}

TEST(SurfaceValidation, RepeatedIndex) {
  SurfaceMesh m = cube();
  m.triangles.row(7) << 3, 6, 3;
  const SurfaceValidation v = validateSurface(m, kFile);
  expectProblem(v, Kind::kRepeatedIndex, 7, "face");
  EXPECT_EQ(find(v, Kind::kRepeatedIndex)->value, 3);
}

// Faces (0,1,2) (area 1/2) and (1,0,3) with p3 = (0.5, 0, h): area h/2 and
// bounding-box diagonal^2 = 2 + h^2, so the relative area is h / (4 + 2 h^2).
SurfaceMesh flap(double h) {
  SurfaceMesh m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0, h;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 1, 0, 3;
  return m;
}

TEST(SurfaceValidation, ZeroAreaBothSidesOfTheTolerance) {
  const double tol = kDefaultZeroAreaRelTol;
  const double hAt = 4.0 * tol;  // relative area h/(4 + 2h^2) = tol to first order
  const SurfaceValidation below = validateSurface(flap(0.9 * hAt), kFile, openOptions());
  expectProblem(below, Kind::kZeroAreaFace, 1, "face");
  EXPECT_NEAR(find(below, Kind::kZeroAreaFace)->value, 0.9 * hAt / 4.0, kFirstOrderRelative * tol);
  const SurfaceValidation above = validateSurface(flap(1.1 * hAt), kFile, openOptions());
  EXPECT_TRUE(above.ok()) << above.problems.front().message;
  const SurfaceValidation flat = validateSurface(flap(0.0), kFile, openOptions());
  expectProblem(flat, Kind::kZeroAreaFace, 1, "face");
  EXPECT_EQ(count(flat, Kind::kSelfIntersection), 0);
}

TEST(SurfaceValidation, DuplicateFaceNamesTheOriginal) {
  SurfaceMesh m = cube();
  m.triangles.conservativeResize(13, 3);
  m.triangles.row(12) << 6, 2, 3;  // face 7 (3, 6, 2), reversed
  const SurfaceValidation v = validateSurface(m, kFile);
  expectProblem(v, Kind::kDuplicateFace, 12, "face");
  EXPECT_EQ(find(v, Kind::kDuplicateFace)->value, 7);
}

TEST(SurfaceValidation, UnreferencedVerticesAreReportedListedAndDroppedExplicitly) {
  SurfaceMesh m = cube();
  m.vertices.conservativeResize(10, 3);
  m.vertices.bottomRows(2) << 5, 5, 5, 6, 6, 6;
  m.vertices.row(2).swap(m.vertices.row(8));  // unused vertex 2 in the middle
  for (Eigen::Index i = 0; i < m.triangles.size(); ++i) {
    if (m.triangles.data()[i] == 2) m.triangles.data()[i] = 8;
  }
  const SurfaceValidation v = validateSurface(m, kFile);
  EXPECT_EQ(count(v, Kind::kUnreferencedVertex), 2);
  expectProblem(v, Kind::kUnreferencedVertex, 2, "vertex");
  const std::vector<int> unused = unreferencedVertices(m);
  EXPECT_EQ(unused, (std::vector<int>{2, 9}));
  const SurfaceMesh dropped = removeVertices(m, unused);
  EXPECT_TRUE(validateSurface(dropped, kFile).ok());
  EXPECT_EQ(dropped.vertices.rows(), 8);
  // Same positions per face corner before and after renumbering.
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(dropped.vertices.row(dropped.triangles(f, k)), m.vertices.row(m.triangles(f, k)));
    }
  }
  EXPECT_THROW(removeVertices(m, {3}), InputError);
}

TEST(SurfaceValidation, NonManifoldEdge) {
  SurfaceMesh m = cube();
  m.vertices.conservativeResize(9, 3);
  m.vertices.row(8) << 0.5, -1, -1;
  m.triangles.conservativeResize(13, 3);
  m.triangles.row(12) << 1, 0, 8;  // a fin on edge (0, 1)
  const SurfaceValidation v = validateSurface(m, kFile);
  const SurfaceProblem* p = find(v, Kind::kNonManifoldEdge);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->value, 3);
  EXPECT_NE(p->message.find("edge (0, 1)"), std::string::npos) << p->message;
  EXPECT_THROW(orientConsistently(m), InputError);
}

TEST(SurfaceValidation, NonManifoldVertexOfTwoCubesTouchingAtACorner) {
  SurfaceMesh m = join(cube(), cube(Eigen::Vector3d(1, 1, 1)));
  // Merge the second cube's corner 0 (vertex 8) with the first's corner 6.
  for (Eigen::Index i = 0; i < m.triangles.size(); ++i) {
    if (m.triangles.data()[i] == 8) m.triangles.data()[i] = 6;
  }
  m = removeVertices(m, {8});
  const SurfaceValidation v = validateSurface(m, kFile);
  ASSERT_EQ(v.problems.size(), 1u) << v.problems.front().message;
  expectProblem(v, Kind::kNonManifoldVertex, 6, "vertex");
  EXPECT_EQ(v.problems[0].value, 2);
  EXPECT_EQ(v.componentCount, 2);
}

// The per-face tetrisation needs valid faces only: a fin, a pinched vertex,
// a face against its neighbours and an inward component are no problems
// there, but a zero-area face still is.
TEST(SurfaceValidation, WithoutRequireSolidOnlyTheFacesAreChecked) {
  SurfaceMesh m = join(cube(), reversed(cube(Eigen::Vector3d(1, 1, 1))));
  for (Eigen::Index i = 0; i < m.triangles.size(); ++i) {
    if (m.triangles.data()[i] == 8) m.triangles.data()[i] = 6;  // pinch the corners
  }
  m = removeVertices(m, {8});
  std::swap(m.triangles(3, 1), m.triangles(3, 2));
  m.vertices.conservativeResize(m.vertices.rows() + 1, 3);
  m.vertices.bottomRows(1) << 0.5, -1, -1;
  m.triangles.conservativeResize(m.triangles.rows() + 1, 3);
  m.triangles.bottomRows(1) << 1, 0, static_cast<int>(m.vertices.rows() - 1);  // a fin
  for (Kind kind : {Kind::kNonManifoldEdge, Kind::kNonManifoldVertex,
                    Kind::kInconsistentOrientation, Kind::kInwardOrientation}) {
    EXPECT_NE(find(validateSurface(m, kFile), kind), nullptr) << problemKindName(kind);
  }
  SurfaceValidationOptions faces = openOptions();
  faces.requireSolid = false;
  const SurfaceValidation v = validateSurface(m, kFile, faces);
  EXPECT_TRUE(v.ok()) << v.problems.front().message;
  EXPECT_EQ(v.componentCount, 2);
  m.vertices.bottomRows(1) << 0.5, 0, 0;  // the fin flat on its edge
  expectProblem(validateSurface(m, kFile, faces), Kind::kZeroAreaFace, m.triangles.rows() - 1,
                "face");
}

TEST(SurfaceValidation, OpenBoundaryOnlyInVolumetricMode) {
  SurfaceMesh m = cube();
  m.triangles.conservativeResize(11, 3);  // drop face 11 (1, 6, 5)
  const SurfaceValidation v = validateSurface(m, kFile);
  EXPECT_EQ(count(v, Kind::kBoundaryEdge), 3);
  EXPECT_EQ(find(v, Kind::kBoundaryEdge)->value, 3);
  EXPECT_NE(find(v, Kind::kBoundaryEdge)->message.find("face "), std::string::npos);
  EXPECT_TRUE(validateSurface(m, kFile, openOptions()).ok());
}

TEST(SurfaceValidation, InconsistentOrientationIsFoundAndFixed) {
  const SurfaceMesh good = cube();
  SurfaceMesh m = good;
  std::swap(m.triangles(3, 1), m.triangles(3, 2));
  const SurfaceValidation v = validateSurface(m, kFile);
  ASSERT_NE(find(v, Kind::kInconsistentOrientation), nullptr);
  EXPECT_NE(find(v, Kind::kInconsistentOrientation)->message.find("face"), std::string::npos);
  const OrientationFix fix = orientConsistently(m);
  EXPECT_EQ(fix.flippedFaces, std::vector<int>{3});
  EXPECT_TRUE(fix.reversedComponents.empty());
  EXPECT_EQ(m.triangles, good.triangles);
}

TEST(SurfaceValidation, InwardCubeIsFoundAndReversed) {
  SurfaceMesh m = reversed(cube());
  const SurfaceValidation v = validateSurface(m, kFile);
  ASSERT_EQ(v.problems.size(), 1u);
  expectProblem(v, Kind::kInwardOrientation, 0, "first face");
  EXPECT_NEAR(v.problems[0].value, -1.0, kUnitCubeVolume);  // volume of the unit cube, reversed
  const OrientationFix fix = orientConsistently(m);
  EXPECT_EQ(fix.reversedComponents, std::vector<int>{0});
  EXPECT_EQ(fix.flippedFaces.size(), 12u);
  EXPECT_EQ(m.triangles, cube().triangles);
}

TEST(SurfaceValidation, CavityMustFaceIntoTheCavity) {
  const SurfaceMesh outer = cube(Eigen::Vector3d(-1, -1, -1), 3.0);
  const SurfaceMesh goodCavity = join(outer, reversed(cube()));
  const SurfaceValidation good = validateSurface(goodCavity, kFile);
  EXPECT_TRUE(good.ok()) << good.problems.front().message;
  EXPECT_EQ(good.componentCount, 2);
  EXPECT_NEAR(enclosedVolume(goodCavity), 27.0 - 1.0, kCavityVolume);
  const std::vector<SurfaceComponent> parts = surfaceComponents(goodCavity);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].nestingDepth, 0);
  EXPECT_EQ(parts[1].nestingDepth, 1);

  SurfaceMesh bad = join(outer, cube());
  const SurfaceValidation v = validateSurface(bad, kFile);
  ASSERT_EQ(v.problems.size(), 1u);
  expectProblem(v, Kind::kInwardOrientation, 12, "first face");
  EXPECT_NEAR(v.problems[0].value, 1.0, kUnitCubeVolume);
  const OrientationFix fix = orientConsistently(bad);
  EXPECT_EQ(fix.reversedComponents, std::vector<int>{1});
  EXPECT_EQ(bad.triangles, goodCavity.triangles);
}

// A cube inside a cube, both facing outward: a cavity facing the wrong way
// for one solid, but right when every component is a solid of its own.
TEST(SurfaceValidation, ComponentsAreSolidsAcceptsANestedSolidFacingOutward) {
  const SurfaceMesh nested = join(cube(Eigen::Vector3d(-1, -1, -1), 3.0), cube());
  expectProblem(validateSurface(nested, kFile), Kind::kInwardOrientation, 12, "first face");
  SurfaceValidationOptions solids;
  solids.componentsAreSolids = true;
  EXPECT_TRUE(validateSurface(nested, kFile, solids).ok());
  const SurfaceMesh cavity = join(cube(Eigen::Vector3d(-1, -1, -1), 3.0), reversed(cube()));
  EXPECT_TRUE(validateSurface(cavity, kFile).ok());
  expectProblem(validateSurface(cavity, kFile, solids), Kind::kInwardOrientation, 12, "first face");
}

TEST(SurfaceValidation, MoebiusStripCannotBeOriented) {
  // Four quads around a loop with a half twist: (a_i, b_i) -> (a_i+1, b_i+1),
  // last joined to the first swapped.
  SurfaceMesh m;
  m.vertices.resize(8, 3);
  for (int i = 0; i < 4; ++i) {
    const double angle = i * 3.14159265358979 / 2.0;
    const double tilt = i * 3.14159265358979 / 4.0;
    const Eigen::Vector3d c(2 * std::cos(angle), 2 * std::sin(angle), 0);
    const Eigen::Vector3d w =
        std::cos(tilt) * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0) +
        std::sin(tilt) * Eigen::Vector3d::UnitZ();
    m.vertices.row(2 * i) = (c - 0.5 * w).transpose();
    m.vertices.row(2 * i + 1) = (c + 0.5 * w).transpose();
  }
  m.triangles.resize(8, 3);
  for (int i = 0; i < 3; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    m.triangles.row(2 * i) << a, c, b;
    m.triangles.row(2 * i + 1) << b, c, d;
  }
  m.triangles.row(6) << 6, 1, 7;  // joins (6, 7) to (1, 0): the half twist
  m.triangles.row(7) << 7, 1, 0;
  EXPECT_NE(find(validateSurface(m, kFile, openOptions()), Kind::kInconsistentOrientation),
            nullptr);
  EXPECT_THROW(orientConsistently(m), InputError);
}

TEST(SurfaceValidation, RandomFlipsAreUndone) {
  std::mt19937_64 rng(testing_surfaces::testSeed());
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(trial);
    const SurfaceMesh good = testing_surfaces::randomStarShape(rng);
    SurfaceMesh m = good;
    std::vector<int> expected;
    std::bernoulli_distribution coin(trial % 2 == 0 ? 0.3 : 0.7);
    for (int f = 0; f < static_cast<int>(m.triangles.rows()); ++f) {
      if (!coin(rng)) continue;
      std::swap(m.triangles(f, 1), m.triangles(f, 2));
      expected.push_back(f);
    }
    orientConsistently(m);
    EXPECT_EQ(m.triangles, good.triangles);
    EXPECT_TRUE(validateSurface(m, kFile).ok());
  }
}

TEST(SurfaceValidation, SelfIntersectionOfOverlappingCubes) {
  const SurfaceMesh m = join(cube(), cube(Eigen::Vector3d(0.5, 0.25, 0.125)));
  const SurfaceValidation v = validateSurface(m, kFile);
  ASSERT_GT(count(v, Kind::kSelfIntersection), 0);
  for (const SurfaceProblem& p : v.problems) {
    ASSERT_EQ(p.kind, Kind::kSelfIntersection) << p.message;
    EXPECT_LT(p.element, 12);  // one face of each cube
    EXPECT_GE(p.value, 12);
    EXPECT_NE(p.message.find("faces " + std::to_string(p.element)), std::string::npos);
  }
  SurfaceValidationOptions options;
  options.checkSelfIntersections = false;
  EXPECT_TRUE(validateSurface(m, kFile, options).ok());
}

TEST(SurfaceValidation, FacesSharingAnEdgeIntersectOnlyWhenFolded) {
  // flap() with p3 rotated about edge (0,1) into the plane z = 0: on p2's
  // side (y > 0) the faces overlap; on the other side they do not.
  SurfaceMesh m = flap(0.0);
  m.vertices.row(3) << 0.5, 0.25, 0;
  expectProblem(validateSurface(m, kFile, openOptions()), Kind::kSelfIntersection, 0, "faces");
  m.vertices.row(3) << 0.5, -0.25, 0;
  EXPECT_TRUE(validateSurface(m, kFile, openOptions()).ok());
}

TEST(SurfaceValidation, FacesSharingAVertexIntersectWhenOneCrossesTheOther) {
  // Face 0 in z = 0; face 1 hinges on vertex 0 and its far edge either pierces
  // face 0 (z from -1 to 1 at x = y = 0.2) or stays above it (z from 0.5 to 1),
  // touching face 0 only at the shared vertex.
  SurfaceMesh m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.2, -1, 0.2, 0.2, 1;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 3, 4;
  expectProblem(validateSurface(m, kFile, openOptions()), Kind::kSelfIntersection, 0, "faces");
  m.vertices.row(3) << 0.2, 0.2, 0.5;
  // (The bow tie at vertex 0 stays a non-manifold vertex, but no intersection.)
  EXPECT_EQ(count(validateSurface(m, kFile, openOptions()), Kind::kSelfIntersection), 0);
}

TEST(SurfaceValidation, DisjointComponentsAreCounted) {
  const SurfaceMesh m =
      join(join(cube(), cube(Eigen::Vector3d(2, 0, 0))), cube(Eigen::Vector3d(0, 3, 0), 0.5));
  const SurfaceValidation v = validateSurface(m, kFile);
  EXPECT_TRUE(v.ok());
  EXPECT_EQ(v.componentCount, 3);
}

TEST(SurfaceValidation, RequireValidRestThrowsTheFirstProblemAndACount) {
  SurfaceMesh m = cube();
  m.triangles.conservativeResize(11, 3);
  try {
    requireValidRest(m, kFile);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(kFile), std::string::npos) << what;
    EXPECT_NE(what.find("boundary edge"), std::string::npos) << what;
    EXPECT_NE(what.find("(and 2 other problems)"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(requireValidRest(cube(), kFile));
}

TEST(SurfaceValidation, ExampleWithDifferentConnectivityNamesTheFirstFace) {
  const SurfaceMesh rest = cube();
  SurfaceMesh example = cube(Eigen::Vector3d(1, 2, 3), 2.0);
  EXPECT_TRUE(validateExample(rest, example, "pose.off").empty());
  example.triangles.row(5) << 0, 4, 5;  // rotated: still different row by row
  example.triangles.row(9) << 0, 3, 7;
  const std::vector<SurfaceProblem> problems = validateExample(rest, example, "pose.off");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, Kind::kConnectivityMismatch);
  EXPECT_EQ(problems[0].element, 5);
  EXPECT_NE(problems[0].message.find("pose.off"), std::string::npos);
  EXPECT_NE(problems[0].message.find("face 5 is (0, 4, 5)"), std::string::npos)
      << problems[0].message;
  EXPECT_NE(problems[0].message.find("(0, 5, 4)"), std::string::npos) << problems[0].message;
  EXPECT_THROW(requireCompatibleExample(rest, example, "pose.off"), InputError);
}

// The cube's square faces are quads of two triangles. An exporter that
// splits each frame's quads by its shape may pick the other diagonal, list
// the triangles in another order and start them at another corner: the same
// surface, accepted. Triangle f = (u, v, a) and its neighbour (v, u, b)
// across u-v become (a, u, b) and (b, v, a).
Triangles withFlippedDiagonal(const Triangles& triangles, Eigen::Index f) {
  const int u = triangles(f, 0), v = triangles(f, 1), a = triangles(f, 2);
  for (Eigen::Index g = 0; g < triangles.rows(); ++g) {
    for (int k = 0; k < 3; ++k) {
      if (triangles(g, k) != v || triangles(g, (k + 1) % 3) != u) continue;
      const int b = triangles(g, (k + 2) % 3);
      Triangles flipped = triangles;
      flipped.row(f) << a, u, b;
      flipped.row(g) << b, v, a;
      return flipped;
    }
  }
  ADD_FAILURE() << "triangle " << f << " has no neighbour across (" << u << ", " << v << ")";
  return triangles;
}

TEST(SurfaceValidation, ExampleWithQuadsSplitAlongTheOtherDiagonalIsTheSameSurface) {
  const SurfaceMesh rest = cube();
  SurfaceMesh example = cube(Eigen::Vector3d(1, 2, 3), 2.0);
  const Triangles once = withFlippedDiagonal(rest.triangles, 0);
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, once), 1);
  // A second quad, through a triangle with none of the first quad's corners
  // (so the two flips share no triangle).
  std::vector<int> firstQuad;
  for (Eigen::Index f = 0; f < once.rows(); ++f) {
    if (once.row(f) == rest.triangles.row(f)) continue;
    for (int k = 0; k < 3; ++k) firstQuad.push_back(once(f, k));
  }
  Eigen::Index apart = 0;
  while ((once.row(apart).array() == firstQuad[0] || once.row(apart).array() == firstQuad[1] ||
          once.row(apart).array() == firstQuad[2] || once.row(apart).array() == firstQuad[3] ||
          once.row(apart).array() == firstQuad[4] || once.row(apart).array() == firstQuad[5])
             .any()) {
    ++apart;
  }
  ASSERT_LT(apart, once.rows());
  const Triangles twice = withFlippedDiagonal(once, apart);
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, twice), 2);
  // Then the rows reordered and every triangle's corners rotated.
  Triangles shuffled(twice.rows(), 3);
  for (Eigen::Index f = 0; f < shuffled.rows(); ++f) {
    const Eigen::Index from = (5 * f + 3) % shuffled.rows();  // 5 is coprime to 12
    shuffled.row(f) << twice(from, 1), twice(from, 2), twice(from, 0);
  }
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, shuffled), 2);
  example.triangles = shuffled;
  EXPECT_TRUE(validateExample(rest, example, "pose.off").empty());
  // Same rows in another order only: no flip.
  Triangles reordered = rest.triangles;
  reordered.row(0).swap(reordered.row(11));
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, reordered), 0);
  // Not the same surface: a face turned over, or a quad's triangles rebuilt
  // with a wrong orientation.
  Triangles turned = rest.triangles;
  turned.row(3) << rest.triangles(3, 0), rest.triangles(3, 2), rest.triangles(3, 1);
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, turned), -1);
  Triangles wrong = withFlippedDiagonal(rest.triangles, 0);
  wrong.row(0) << wrong(0, 0), wrong(0, 2), wrong(0, 1);
  EXPECT_EQ(flippedQuadDiagonals(rest.triangles, wrong), -1);
  EXPECT_FALSE(validateExample(rest, SurfaceMesh{example.vertices, wrong}, "pose.off").empty());
}

TEST(SurfaceValidation, ExampleWithDifferentVertexCountOrNonFiniteCoordinates) {
  const SurfaceMesh rest = cube();
  SurfaceMesh example = rest;
  example.vertices.conservativeResize(9, 3);
  example.vertices.row(8) << 1, 1, 1;
  std::vector<SurfaceProblem> problems = validateExample(rest, example, "pose.off");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, Kind::kVertexCountMismatch);
  EXPECT_EQ(problems[0].value, 9);
  EXPECT_NE(problems[0].message.find("9 vertices"), std::string::npos);

  example = rest;
  example.vertices(4, 0) = std::numeric_limits<double>::quiet_NaN();
  problems = validateExample(rest, example, "pose.off");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, Kind::kNonFiniteCoordinate);
  EXPECT_EQ(problems[0].element, 4);
}

}  // namespace
}  // namespace tetblend
