// The OpenBLAS thread scopes (core/blas_threads.h). They are tested here, not
// in core's suite, because this binary loads OpenBLAS (through CHOLMOD).
#include "tetblend/core/blas_threads.h"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <memory>
#include <thread>

#include "tetblend/meshing/example_aware_tets.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tet_boundary.h"
#include "tetblend/meshing/tetgen_mesher.h"

namespace tetblend {
namespace {

using SetThreads = void (*)(int);

// Gives OpenBLAS `threads` threads for one test and its own count back after.
class OpenBlasThreads {
 public:
  explicit OpenBlasThreads(int threads)
      : set_(reinterpret_cast<SetThreads>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))),
        own_(openBlasThreads()) {
    if (set_ != nullptr) set_(threads);
  }
  ~OpenBlasThreads() {
    if (set_ != nullptr) set_(own_);
  }
  bool present() const { return set_ != nullptr && own_ > 0; }

 private:
  SetThreads set_;
  int own_;
};

// Three threads, so that one is seen to differ from the serial count (1)
// on any machine.
constexpr int kTeam = 3;

TEST(BlasThreads, SerialScopesRunOpenBlasOnOneThreadUntilTheLastEnds) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  ASSERT_EQ(openBlasThreads(), kTeam);
  {
    const SerialBlas outer;
    EXPECT_EQ(openBlasThreads(), 1);
    { const SerialBlas inner; }
    EXPECT_EQ(openBlasThreads(), 1) << "an inner scope's end must not end the outer one";
  }
  EXPECT_EQ(openBlasThreads(), kTeam);
}

TEST(BlasThreads, AParallelScopeGivesTheTeamBackInsideASerialOne) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  const SerialBlas serial;
  {
    const ParallelBlas parallel;
    EXPECT_EQ(openBlasThreads(), kTeam);
  }
  EXPECT_EQ(openBlasThreads(), 1);
}

TEST(BlasThreads, ScopesOnTwoThreadsEndSerialOnlyWhenBothHaveEnded) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  auto first = std::make_unique<SerialBlas>();
  std::thread([] { const SerialBlas second; }).join();
  EXPECT_EQ(openBlasThreads(), 1);
  first.reset();
  EXPECT_EQ(openBlasThreads(), kTeam);
}

// OpenBLAS stops its thread pool before a fork (tetblend forks for TetGen).
// A serial scope after one must not start it again: openblas_set_num_threads
// would, and the new workers spin for 0.1 s of a core (blas_threads.cpp).
TEST(BlasThreads, ASerialScopeAfterAForkLeavesOpenBlasPoolStopped) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  const auto* poolRunning = static_cast<const int*>(::dlsym(RTLD_DEFAULT, "blas_server_avail"));
  if (poolRunning == nullptr) GTEST_SKIP() << "this OpenBLAS does not export blas_server_avail";
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);
  if (*poolRunning != 0) GTEST_SKIP() << "this OpenBLAS keeps its pool through a fork";
  {
    const SerialBlas serial;
    EXPECT_EQ(openBlasThreads(), 1);
    EXPECT_EQ(*poolRunning, 0) << "the serial scope started OpenBLAS's pool";
  }
  EXPECT_EQ(openBlasThreads(), kTeam);
  EXPECT_EQ(*poolRunning, 0) << "the scope's end started OpenBLAS's pool";
}

TEST(BlasThreads, AParallelScopeOutsideSerialOnesChangesNothing) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  const ParallelBlas parallel;
  EXPECT_EQ(openBlasThreads(), kTeam);
}

TEST(BlasThreads, PlacingExamplesGivesOpenBlasItsThreadsBack) {
  const OpenBlasThreads team(kTeam);
  if (!team.present()) GTEST_SKIP() << "the BLAS this binary loaded is not OpenBLAS";
  const SurfaceMesh boundary = boundarySurface(boxTetMesh(8, 2, 2, Eigen::Vector3d(2, 0.5, 0.5)));
  const SurfaceMesh surface = removeVertices(boundary, unreferencedVertices(boundary));
  Vertices stretched = surface.vertices;
  stretched.col(0) *= 1.5;
  buildCompatibleTetMeshes(tetrahedralize(surface), static_cast<int>(surface.vertices.rows()),
                           {stretched});
  EXPECT_EQ(openBlasThreads(), kTeam);
}

}  // namespace
}  // namespace tetblend
