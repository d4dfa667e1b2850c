#pragma once
// The linear stitch of the shape blender (Kaji–Ochiai §6.2, "patching" the
// blended per-tet maps; the Poisson-type solve of Sumner–Popović deformation
// transfer): given a target linear map B_j for every tet, find vertex
// positions x minimising
//     E(x) = sum_j vol_j ||grad_j(x) - B_j||_F^2,
// where grad_j(x) = D_j(x) D_rest,j^-1 is the deformation gradient of tet j.
// The normal matrix G^T W G (a cotangent Laplacian, the same for x, y and z)
// depends only on the rest mesh, so it is factored once and every weight
// vector costs one right-hand side and one back-substitution.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "tetblend/blending/blend_cache.h"
#include "tetblend/blending/blend_method.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Sparse Cholesky used for G^T W G.
enum class StitchBackend {
  kCholmodSupernodal,    ///< CHOLMOD supernodal LL^T (fastest; needs CHOLMOD at build)
  kEigenSimplicialLdlt,  ///< Eigen's SimplicialLDLT with AMD ordering (always available)
};

/// Options of the stitch solver.
struct StitchOptions {
  /// Factorisation; kCholmodSupernodal silently becomes kEigenSimplicialLdlt
  /// when tetblend was built without CHOLMOD (see StitchSolver::backend()).
  StitchBackend backend = StitchBackend::kCholmodSupernodal;
};

/// Per-component centroids, #C by 3 (one row per vertex component).
using Centroids = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Seconds spent in the two halves of StitchSolver::solveInto.
struct StitchTimings {
  /// Producing the target maps inside the right-hand-side pass (the fused
  /// solveInto; about 0 when the maps are given as a vector). The pass's wall
  /// time is split between this and rhsSeconds in the ratio of thread times.
  double targetSeconds = 0.0;
  double rhsSeconds = 0.0;    ///< assembling G^T W B (parallel)
  double solveSeconds = 0.0;  ///< back-substitution and centroid placement
};

class StitchSolver;

/// Dense buffers of one stitch solve (right-hand side and solution in the
/// factor's row order, the supernodal solve's scratch). Reusing one across solves of the same
/// solver avoids reallocating them; one workspace must not be used by two threads at once.
class StitchWorkspace {
 public:
  StitchWorkspace();
  ~StitchWorkspace();
  StitchWorkspace(StitchWorkspace&&) noexcept;
  StitchWorkspace& operator=(StitchWorkspace&&) noexcept;

 private:
  friend class StitchSolver;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Factors the stitch once for a rest mesh, then solves for any target field.
/// Vertex components are the classes of "shares a tet" (a vertex in no tet is
/// its own component); each component's lowest-index vertex is pinned to
/// remove the translation null space, and after the solve each component is
/// translated so that its vertex centroid (mean of its vertices) equals the
/// centroid the caller asks for. solveInto is deterministic (the right-hand
/// side visits each tet once, in a fixed number of tet chunks summed
/// sequentially and then added per vertex in chunk order, whatever the thread
/// count) and safe to call concurrently on one solver: the factor is only
/// read (the supernodal solve is tetblend's own, not cholmod_solve, which
/// writes its cholmod_common), and every call solves in its own
/// StitchWorkspace, so no lock is taken. The factor is CHOLMOD's supernodal
/// LL^T, ordered by METIS or AMD (whichever CHOLMOD finds cheaper; METIS on
/// the box grids), repacked without explicit zeros above the diagonal; one x/y/z solve reads it
/// once forward and once backward, with the two halves of the elimination tree below a balanced
/// split, and the large dense blocks above it, on two threads (TBB).
class StitchSolver {
 public:
  /// Builds the gradient operator of `rest` (#V by 3 vertices, #T by 4 tets)
  /// and factors G^T W G. Throws InputError for a rest tet with volume <= 0
  /// and NumericalError if the factorisation fails.
  explicit StitchSolver(const TetMesh& rest, const StitchOptions& options = {});
  /// The solver of `rest` with the factor another solver of the same rest
  /// gave by factorData() (supernodal backend; nothing is factored). Throws
  /// InputError for a rest tet with volume <= 0, a factor whose structure
  /// does not fit the rest's free vertices, or a build without CHOLMOD.
  StitchSolver(const TetMesh& rest, StitchFactorData factor);
  ~StitchSolver();
  StitchSolver(StitchSolver&&) noexcept;
  StitchSolver& operator=(StitchSolver&&) noexcept;

  int vertexCount() const;
  int tetCount() const;
  /// Number of vertex components C.
  int componentCount() const;
  /// Component label (0..C-1) of each of the #V vertices.
  const std::vector<int>& vertexComponent() const;
  /// The rest per-tet data (inverse edge matrices, volumes), computed on
  /// each call (the solver keeps only the rest mesh: 80 bytes per tet less).
  RestTetData restData() const;
  /// The rest mesh (#V by 3 vertices, #T by 4 tets) the solver was built for.
  const TetMesh& rest() const;
  /// The rest tets (#T by 4).
  const Tets& tets() const;
  /// The backend actually used.
  StitchBackend backend() const;
  /// Stored entries of the Cholesky factor (8 bytes each, plus a few percent
  /// of indices; each solve reads them twice).
  double factorNonzeros() const;
  /// The factor's arrays, for the constructor above. Throws InputError for
  /// the SimplicialLDLT backend.
  StitchFactorData factorData() const;
  /// Heap bytes the solver holds between solves: the factor (values and
  /// indices), the rest mesh and the per-vertex index arrays (exact for the
  /// supernodal backend, the stored arrays' sizes for SimplicialLDLT).
  double memoryBytes() const;

  /// Mean of the vertices of each component (#C by 3) of `vertices` (#V by 3).
  Centroids componentCentroids(const Vertices& vertices) const;

  /// Minimises E for `targets` (#T linear maps B_j, 3 by 3) and places each
  /// component's centroid at the matching row of `centroids` (#C by 3).
  /// Returns #V by 3 positions. Throws InputError on size mismatches.
  Vertices solve(const std::vector<Eigen::Matrix3d>& targets, const Centroids& centroids) const;

  /// As solve, writing into `result` (resized if needed, reused otherwise) and
  /// optionally reporting the time of each half in `timings`. Uses a
  /// workspace local to the call.
  void solveInto(const std::vector<Eigen::Matrix3d>& targets, const Centroids& centroids,
                 Vertices& result, StitchTimings* timings = nullptr) const;

  /// As solveInto, solving in the caller's `workspace` (x, y and z as one
  /// three-column solve of the reduced system, pinned vertices eliminated;
  /// the right-hand side is assembled directly in the factor's row order).
  void solveInto(const std::vector<Eigen::Matrix3d>& targets, const Centroids& centroids,
                 Vertices& result, StitchWorkspace& workspace,
                 StitchTimings* timings = nullptr) const;

  /// Writes the target maps B_j of tets [begin, end) into out[0 .. end -
  /// begin), for the fused solveInto.
  using TargetRangeFunction = std::function<void(int begin, int end, Eigen::Matrix3d* out)>;

  /// As solveInto, without a stored target field: the right-hand-side pass
  /// asks `targets` for the maps of each range of at most kTetMapChunk tets
  /// (each starting at a multiple of kTetMapChunk: the chunks of
  /// TetMapBlender::blendTargets), from several threads at once on disjoint
  /// ranges, and adds them in at once, so only kTetMapChunk maps per thread
  /// exist at a time. Gives bitwise the solution of solveInto on the field
  /// the same function would fill. timings->targetSeconds is the share of
  /// the pass spent in `targets`.
  void solveInto(const TargetRangeFunction& targets, const Centroids& centroids, Vertices& result,
                 StitchWorkspace& workspace, StitchTimings* timings = nullptr) const;

  /// Deformation gradient grad_j(x) (3 by 3) of tet j for positions `x`.
  Eigen::Matrix3d gradient(const Vertices& x, int tet) const;

  /// The stitch energy E(x) = sum_j vol_j ||grad_j(x) - B_j||_F^2.
  double energy(const Vertices& x, const std::vector<Eigen::Matrix3d>& targets) const;

 private:
  template <typename Targets>
  void solveImpl(const Targets& targets, const Centroids& centroids, Vertices& result,
                 StitchWorkspace& workspace, StitchTimings* timings) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetblend
