// The hard-pose corpus on real meshes (issue "prepare every pose users
// bring"): CGAL demo meshes with thin parts and genus > 0, each posed by every
// deformation of hardPoses, tetrahedralised with the default options and
// made compatible by buildCompatibleTetMeshes. Every pose whose surface does
// not intersect itself must come out with no inverted tet (but for the known
// failures below); the surface must stay bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "cgal_meshes.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/pose_corpus.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {
namespace {

// Clean poses that may still keep inverted tets (issue "prepare every pose
// users bring"), with the most they may keep. knot1's 1080° twist is chaotic
// in the untangler's arithmetic: before stage 3 split the inverted tets'
// neighbours too (inverted_tet_splits.h), changes at the level of rounding
// gave 6 to 196 tets, and one commit 21 on one machine and 35 on another (an
// AMD EPYC). Since then it keeps none here, and 0 or 1 over six TetGen
// quality bounds from 1.8 to 3 (`tetblend prepare` of its twist720 and
// twist1080, 2026-12-02; 32 to 201 before): the ceiling, 3, allows that
// spread on other machines and fails for the old behaviour. dino's 720°
// twist, which kept 1, keeps none at four quality bounds from 1.8 to 2.6 and
// is held to zero. prepare succeeds either way and leaves such tets out of
// the stitch. The test fails when a count grows past its ceiling and says
// when one reaches zero.
const std::map<std::pair<std::string, std::string>, std::size_t> kKnownInvertedCeiling = {
    {{"knot1", "twist1080"}, 3}};

// Untangling a clean example that came back untangled once more, from where
// it ended, may still remove a tet or two (the attempt restarts with a larger
// ε: knot1's posed-rest twist1080 kept 244 either way before stage 3 split
// the inverted tets' neighbours too, and none since); one whose tets were
// split after its untangling loses more (see PoseCorpusPosedRest).
constexpr std::size_t kUntangleAgainSlack = 2;

class PoseCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(PoseCorpus, EveryCleanPoseEmbedsWithoutInvertedTets) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the corpus runs about 20 times slower under AddressSanitizer; the release "
                  "suite runs it, and ExampleAwareTets covers the same code under the sanitizers";
#endif
  const std::string tarball = testing_cgal::cgalDataTarball();
  if (tarball.empty()) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  const std::string name = GetParam() + ".off";
  const std::filesystem::path meshes = testing_cgal::extractCgalMeshes(tarball, {name}, GetParam());
  ASSERT_FALSE(meshes.empty());
  const SurfaceMesh surface = readSurface((meshes / name).string());
  std::filesystem::remove_all(meshes.parent_path().parent_path());

  const auto start = std::chrono::steady_clock::now();
  const TetMesh rest = tetrahedralize(surface);
  const double tetgenSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int surfaceCount = static_cast<int>(surface.vertices.rows());
  const std::vector<NamedPose> poses = hardPoses(surface.vertices, surface.triangles);
  std::vector<Vertices> exampleSurfaces;
  for (const NamedPose& pose : poses) exampleSurfaces.push_back(pose.vertices);
  const CompatibleTetMeshes built = buildCompatibleTetMeshes(rest, surfaceCount, exampleSurfaces);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
      tetgenSeconds;
  std::cout << name << ": " << rest.tets.rows() << " tets from TetGen (" << tetgenSeconds << " s), "
            << built.rest.tets.rows() << " after " << built.rounds << " rounds, "
            << built.steinerPoints << " Steiner points, " << built.allSurfaceTetsInverted
            << " all-surface tets inverted up front, " << built.rigidSimplicesOutside
            << " rigid edges and faces outside an example; embedding " << seconds << " s\n";

  ASSERT_EQ(built.examples.size(), poses.size());
  ASSERT_GE(built.rest.vertices.rows(), surfaceCount);
  EXPECT_TRUE(built.rest.vertices.topRows(surfaceCount) == surface.vertices);
  for (Eigen::Index t = 0; t < built.rest.tets.rows(); ++t) {
    ASSERT_GT(tetSignedVolume(built.rest.vertices, built.rest.tets.row(t)), 0.0)
        << "rest tet " << t;
  }
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const CompatibleTetResult& placed = built.examples[k];
    const bool selfIntersecting =
        findSelfIntersections(poses[k].vertices, surface.triangles, 1).pairCount > 0;
    std::cout << "  " << poses[k].name << (selfIntersecting ? " (self-intersecting)" : "") << ": "
              << placed.invertedTets.size() << " inverted, min volume ratio "
              << placed.minVolumeRatio << ", harmonic inverted " << placed.harmonicInvertedCount
              << ", ARAP iterations " << placed.arapIterations << ", untangle rounds "
              << placed.untangleRounds << "\n";
    EXPECT_TRUE(placed.vertices.topRows(surfaceCount) == poses[k].vertices) << poses[k].name;
    if (selfIntersecting) continue;
    const auto known = kKnownInvertedCeiling.find({GetParam(), poses[k].name});
    if (known == kKnownInvertedCeiling.end()) {
      EXPECT_TRUE(placed.invertedTets.empty())
          << name << " " << poses[k].name << ": " << placed.invertedTets.size()
          << " tets inverted although the pose's surface does not intersect itself";
    } else {
      EXPECT_LE(placed.invertedTets.size(), known->second)
          << name << " " << poses[k].name << ": a known failure got worse";
      if (placed.invertedTets.empty()) {
        std::cout << "  " << poses[k].name << " embeds (kKnownInvertedCeiling allows "
                  << known->second << ")\n";
      }
    }
  }
}

// CGAL's demo mesh `mesh` (without ".off"), extracted into a folder named by
// `tag` and read; nothing when Debian's libcgal-demo is missing (a failed
// extraction is a test failure).
std::optional<SurfaceMesh> cgalSurface(const std::string& mesh, const std::string& tag) {
  const std::string tarball = testing_cgal::cgalDataTarball();
  if (tarball.empty()) return std::nullopt;
  const std::filesystem::path meshes =
      testing_cgal::extractCgalMeshes(tarball, {mesh + ".off"}, tag);
  if (meshes.empty()) {
    ADD_FAILURE() << "cannot extract " << mesh << ".off from " << tarball;
    return std::nullopt;
  }
  SurfaceMesh surface = readSurface((meshes / (mesh + ".off")).string());
  std::filesystem::remove_all(meshes.parent_path().parent_path());
  return surface;
}

// Issue "prepare every pose users bring", failure class "an interior edge
// or face between surface vertices leaves the example": a valid tet mesh of a
// clean example covers exactly its solid, so when some rigid edge or face
// leaves it (found with exact predicates), placement alone must keep inverted
// tets; splitting those simplices up front repairs the pose. On the cactus
// (thin arms) several clean poses of the corpus are of this class.
TEST(PoseCorpusRigidSimplices, PlacementAloneFailsWhereARigidSimplexLeavesTheExample) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "slow under AddressSanitizer; ExampleAwareTets covers the code there";
#endif
  const std::optional<SurfaceMesh> cactus = cgalSurface("cactus", "cactus_rigid");
  if (!cactus) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  const SurfaceMesh& surface = *cactus;
  const TetMesh rest = tetrahedralize(surface);
  const int surfaceCount = static_cast<int>(surface.vertices.rows());
  ExampleAwareOptions placementOnly;
  placementOnly.maxRounds = 0;
  int posesOfTheClass = 0;
  for (const NamedPose& pose : hardPoses(surface.vertices, surface.triangles)) {
    if (findSelfIntersections(pose.vertices, surface.triangles, 1).pairCount > 0) continue;
    const CompatibleTetMeshes built = buildCompatibleTetMeshes(rest, surfaceCount, {pose.vertices});
    if (built.rigidSimplicesOutside == 0) continue;
    ++posesOfTheClass;
    EXPECT_FALSE(buildCompatibleTetMeshes(rest, surfaceCount, {pose.vertices}, placementOnly)
                     .examples[0]
                     .invertedTets.empty())
        << pose.name << ": " << built.rigidSimplicesOutside
        << " rigid simplices leave the pose, yet placement alone embedded it";
    EXPECT_TRUE(built.examples[0].invertedTets.empty())
        << pose.name << ": " << built.examples[0].invertedTets.size() << " tets stay inverted";
  }
  EXPECT_GE(posesOfTheClass, 2);
}

// Stage 3's refinement rounds are budgeted per example: with a budget shared
// by all examples, the first frames of a long animation spent it and later
// clean frames kept inverted tets that their own rounds repair (on 48
// harshly skinned dino frames of the prepare rehearsal, 8 clean frames kept
// some, 6 with a budget per example). Here the cactus's clean poses with a
// budget of one round: with the shared budget twist720 spent it and
// twist1080 kept 28 inverted tets.
TEST(PoseCorpusRefinementBudget, EveryCleanExampleGetsItsOwnRounds) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "slow under AddressSanitizer; ExampleAwareTets covers the code there";
#endif
  const std::optional<SurfaceMesh> cactus = cgalSurface("cactus", "cactus_budget");
  if (!cactus) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  const SurfaceMesh& surface = *cactus;
  const TetMesh rest = tetrahedralize(surface);
  const int surfaceCount = static_cast<int>(surface.vertices.rows());
  ExampleAwareOptions small;
  small.maxRounds = 1;
  std::vector<Vertices> clean;
  std::vector<std::string> names;
  for (const NamedPose& pose : hardPoses(surface.vertices, surface.triangles)) {
    if (findSelfIntersections(pose.vertices, surface.triangles, 1).pairCount > 0) continue;
    clean.push_back(pose.vertices);
    names.push_back(pose.name);
  }
  const CompatibleTetMeshes built = buildCompatibleTetMeshes(rest, surfaceCount, clean, small);
  for (std::size_t k = 0; k < clean.size(); ++k) {
    std::cout << "  " << names[k] << ": " << built.examples[k].invertedTets.size() << " inverted\n";
    EXPECT_TRUE(built.examples[k].invertedTets.empty()) << names[k];
  }
}

// A posed rest (an animation's frame chosen as the rest): the other poses
// then differ from it by up to twice their own turns, and stage 3 refines
// the mesh for several clean examples in turn. Those splits also split the
// other examples' inverted tets, each into more inverted tets, so every
// clean example must come back untangled on the final mesh: untangling it
// once more there finds (almost) nothing left to repair. Before, knot1's
// 720° twist came back with 11 inverted tets of which 6 untangled again; on
// the dino's 48 rehearsal frames with frame 5 as the rest, one frame grew
// from 19 inverted tets to 6336 while the others were refined, and its own
// refinement then split all of them (82 k tets, 58 k excluded, 10 minutes).
// Examples whose surface intersects itself are untangled briefly by design
// (ExampleAwareOptions::intersectingUntangle); their counts are printed.
TEST(PoseCorpusPosedRest, EveryCleanExampleComesBackUntangledOnTheFinalMesh) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "slow under AddressSanitizer; ExampleAwareTets covers the code there";
#endif
  const std::optional<SurfaceMesh> knot = cgalSurface("knot1", "knot_posed_rest");
  if (!knot) GTEST_SKIP() << testing_cgal::kMissingCgalDemo;
  const std::vector<NamedPose> poses = hardPoses(knot->vertices, knot->triangles);
  const auto restPose = std::find_if(
      poses.begin(), poses.end(), [](const NamedPose& pose) { return pose.name == "dqsTwist300"; });
  ASSERT_NE(restPose, poses.end());
  SurfaceMesh posed = *knot;
  posed.vertices = restPose->vertices;
  const TetMesh rest = tetrahedralize(posed);
  const int surfaceCount = static_cast<int>(posed.vertices.rows());
  std::vector<Vertices> examples{knot->vertices};
  std::vector<std::string> names{"neutral"};
  for (const NamedPose& pose : poses) {
    if (pose.name == restPose->name) continue;
    examples.push_back(pose.vertices);
    names.push_back(pose.name);
  }
  const ExampleAwareOptions options;
  const CompatibleTetMeshes built = buildCompatibleTetMeshes(rest, surfaceCount, examples, options);
  std::cout << "  rest " << restPose->name << ": " << rest.tets.rows() << " tets from TetGen, "
            << built.rest.tets.rows() << " after " << built.rounds << " rounds\n";
  const CompatibleTetBuilder again(built.rest, surfaceCount, options.placement);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    const std::size_t returned = built.examples[k].invertedTets.size();
    if (returned == 0) continue;
    const bool clean = built.selfIntersections[k].pairCount == 0;
    const std::size_t repaired =
        again
            .repair(built.examples[k].vertices,
                    clean ? options.placement.untangleEffort : options.intersectingUntangle)
            .invertedTets.size();
    std::cout << "  " << names[k] << (clean ? "" : " (self-intersecting)") << ": " << returned
              << " inverted, " << repaired << " after untangling again\n";
    if (clean) {
      EXPECT_LE(returned, repaired + kUntangleAgainSlack) << names[k];
    }
  }
}

// Thin parts (cactus arms, elephant legs and trunk, fingers), genus 1 (knot,
// handle) and 2 (eight); a few hundred to a few thousand surface vertices so
// the whole corpus runs in CI.
INSTANTIATE_TEST_SUITE_P(CgalDemoMeshes, PoseCorpus,
                         ::testing::Values("cactus", "eight", "knot1", "elephant", "hand", "handle",
                                           "dino", "femur"));

}  // namespace
}  // namespace tetblend
