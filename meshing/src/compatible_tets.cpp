#include "tetblend/meshing/compatible_tets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <tbb/blocked_range.h>
#include <tbb/collaborative_call_once.h>
#include <tbb/parallel_for.h>

#include "interior_ordering.h"
#include "interior_stiffness.h"
#include "local_arap.h"
#include "tet_elements.h"
#include "tetblend/core/blas_threads.h"
#include "tetblend/core/error.h"
#include "tetblend/core/memory_preflight.h"
#include "tetblend/core/openmp_teams.h"
#include "tetblend/core/sym3.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/tet_boundary.h"
#include "untangle.h"
#ifdef TETBLEND_HAVE_CHOLMOD
#include "supernodal_values_ahead.h"
#endif

namespace tetblend {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RotationField = std::vector<Eigen::Matrix3d>;

namespace {

// Tets (or vertices) per TBB task: large enough that scheduling costs little
// against ~1 µs of work per tet.
constexpr int kGrain = 2048;

// CHOLMOD's analysis counts the nonzeros of L; its supernodal storage also
// holds the zeros inside each supernode: xsize / lnz measured 1.39-1.98 on
// TetGen meshes of 1.7k-166k tets (the larger on the smaller meshes).
constexpr double kSupernodalPadding = 2.0;

// Flops of the interior's factorisation (CHOLMOD's count) from which it runs
// on OpenBLAS's thread team. After its work the team spins on the cores that
// the examples' placements need for 2^28 cycles (its THREAD_TIMEOUT, 0.11 s
// here; blas_threads.h). The 1 M row of bench_meshing (6.3e10 flops) took
// 6.5 s of embedding with the team and 7.2 s without; its 100 k row (6.5e8
// flops) embedded in 527-546 ms without, 607-832 ms with it (and with
// OpenBLAS's pool restarted after TetGen's fork).
constexpr double kTeamFactorisationFlops = 1e10;

// A local ARAP search (CompatibleTetBuilder::place's arapRings) runs only
// when its region holds at most this share of the interior vertices: a
// larger one costs about as much as the global search, whose factor is
// already made, and leaves most of the interior where the harmonic map put it.
constexpr double kLocalArapShare = 0.5;

// UntangleEffort::thickenedReference thickens rest tets whose edge matrix
// has a singular value below this fraction of its largest
// (thickenedTetElements). A regular tet's ratio is 1/2; TetGen's
// radius-edge bound keeps slivers, and splits next to a triangle of nearly
// zero area make more.
constexpr double kThickenedSingularRatio = 0.05;

// Runs body(begin, end) on consecutive ranges covering [0, count), on TBB's
// threads.
template <typename Body>
void parallelRanges(Eigen::Index count, const Body& body) {
  tbb::parallel_for(
      tbb::blocked_range<Eigen::Index>(0, count, kGrain),
      [&](const tbb::blocked_range<Eigen::Index>& range) { body(range.begin(), range.end()); });
}

// Runs body(i) for i in [0, count) on TBB's threads.
template <typename Body>
void parallelFor(Eigen::Index count, const Body& body) {
  parallelRanges(count, [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index i = begin; i != end; ++i) body(i);
  });
}

// ‖F − R‖² for the rotation R closest to F (reflection removed, as in
// closestRotation) from the singular values of F, σ_i = sqrt(eig(FᵀF)):
// Σ (σ_i − 1)², with the smallest σ taken negative when det F < 0.
double arapResidual(const Eigen::Matrix3d& f, double det) {
  const Eigen::Vector3d eigenvalues = symEigenvalues(f.transpose() * f);  // descending
  Eigen::Vector3d sigma = eigenvalues.cwiseMax(0.0).cwiseSqrt();
  if (det < 0.0) sigma.z() = -sigma.z();
  return (sigma - Eigen::Vector3d::Ones()).squaredNorm();
}

}  // namespace

struct CompatibleTetBuilder::Impl {
  TetMesh rest;
  int surfaceCount = 0;
  int interiorCount = 0;
  CompatibleTetOptions options;
  std::vector<TetElement> elements;
  Eigen::SparseMatrix<double, Eigen::RowMajor> couplingBlock;  // K_IB
  // K_II is factored once per rest mesh: CHOLMOD's supernodal LL^T when
  // tetblend is built with CHOLMOD (BLAS-3 on the dense supernodes, many times
  // faster than the simplicial factor at 10^5-10^6 tets), else Eigen's
  // SimplicialLDLT. Solves take turns (solveMutex: Eigen's CHOLMOD wrapper
  // keeps one cholmod_common), so examples may be placed on several threads.
#ifdef TETBLEND_HAVE_CHOLMOD
  using InteriorSolver = SupernodalLLTValuesAhead<SparseMatrix>;
#else
  using InteriorSolver = Eigen::SimplicialLDLT<SparseMatrix>;
#endif
  std::optional<InteriorSolver> solver;  // made by requireFactor, freed by releaseFactor
  mutable std::mutex solveMutex;
  // An elimination order handed to the constructor (may still be computing)
  // and, once the factorisation used it, its permutation P (indices: interior
  // vertex -> position), K_II being factored as P K_II Pᵀ.
  std::shared_future<InteriorOrder> interiorOrder;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation;
  // Collaborative: a thread that waits for the first use joins its parallel
  // loops (a std::call_once whose body runs TBB loops can deadlock when the
  // waiting thread stole the caller's outer task).
  std::optional<tbb::collaborative_once_flag> factorOnce{std::in_place};  // anew after a release
  tbb::collaborative_once_flag trianglesOnce;
  tbb::collaborative_once_flag thickenedOnce;
  std::vector<TetElement> thickenedElements;  // on first use by untangleInverted
  Triangles surfaceTriangles;                 // boundary faces, on first use by propagatedRotations
  double diagonal = 0.0;
  double totalVolume = 0.0;  // Σ_t vol_t
  VertexStars stars;

  // Assembles K_II and K_IB and factors K_II, once, on first use.
  void requireFactor() {
    tbb::collaborative_call_once(*factorOnce, [this] {
      InteriorSolver& factor = solver.emplace();
      StiffnessBlocks blocks = assembleStiffnessBlocks(rest.tets, elements, stars, surfaceCount);
      couplingBlock = std::move(blocks.coupling);
      if (interiorCount > 0) {
#ifdef TETBLEND_HAVE_CHOLMOD
        const InteriorOrder order = interiorOrder.valid()
                                        ? extendedInteriorOrder(interiorOrder.get(), interiorCount)
                                        : InteriorOrder{};
        if (!order.empty()) {
          permutation.resize(interiorCount);
          for (int k = 0; k < interiorCount; ++k) permutation.indices()[order[k]] = k;
          SparseMatrix permuted;
          permuted.selfadjointView<Eigen::Lower>() =
              blocks.interiorLower.selfadjointView<Eigen::Lower>().twistedBy(permutation);
          blocks.interiorLower = std::move(permuted);
          factor.cholmod().nmethods = 1;
          factor.cholmod().method[0].ordering = CHOLMOD_NATURAL;
        } else if (interiorCount >= kMetisOnlyInteriorVertices) {
          factor.cholmod().nmethods = 1;
          factor.cholmod().method[0].ordering = CHOLMOD_METIS;
        }
#endif
        factor.analyzePattern(blocks.interiorLower);
#ifdef TETBLEND_HAVE_CHOLMOD
        requireAllocatable(
            static_cast<std::size_t>(kSupernodalPadding * sizeof(double) * factor.cholmod().lnz) +
                blasWorkspaceBytes(),
            "the interior's Cholesky factorisation (" + std::to_string(interiorCount) +
                " interior vertices)");
        // Every other placement waits for this factorisation: a large one
        // may use OpenBLAS's thread team even inside buildCompatibleTetMeshes,
        // but never CHOLMOD's OpenMP team beside it. The two teams' waiting
        // threads take each other's cores: the 1 M row's interior (145 914
        // vertices, 6.3e10 flops) factored alone in a fresh process (then
        // again in the same one), three runs each: 1.50-1.78 s (1.12-1.26 s)
        // with OpenBLAS's team of 2, 2.46 s (1.74-1.80 s) on one thread,
        // 3.11 s (3.01 s) with an OpenMP team of 2 and serial BLAS, 2.05 s
        // (1.94 s) with both teams. Inside bench_meshing both teams took
        // 5.6-8.1 s. OpenMP's dynamic team (openmp_teams.h) has as many
        // threads as cores less the 15-minute load average (libgomp): 2
        // on an idle machine, 1 after a quarter of an hour of work, which is
        // why that row had drifted from one hour to the next.
        const bool team = factor.cholmod().fl >= kTeamFactorisationFlops;
        useOpenMpTeams(false);
        std::optional<ParallelBlas> parallelBlas;
        if (team) parallelBlas.emplace();
#endif
        factor.factorize(blocks.interiorLower);
        if (factor.info() != Eigen::Success) {
          throw NumericalError(
              "CompatibleTetBuilder: Cholesky factorisation of the interior stiffness block "
              "failed (an interior vertex used by no tet?)");
        }
      }
    });
  }

  void requireExampleSurface(const Vertices& positions, Eigen::Index rows) const {
    if (positions.rows() != rows || !positions.allFinite()) {
      throw InputError("CompatibleTetBuilder: the example has " + std::to_string(positions.rows()) +
                       " vertices (need " + std::to_string(rows) + ", all finite)");
    }
  }

  // Interior vertices within `rings` tet-rings of the given tets.
  std::vector<int> interiorRegion(const std::vector<int>& seedTets, int rings) const {
    std::vector<char> inRegion(rest.vertices.rows(), 0);
    std::vector<int> frontier;
    for (int t : seedTets) {
      for (int a = 0; a < 4; ++a) {
        const int v = rest.tets(t, a);
        if (!inRegion[static_cast<size_t>(v)]) frontier.push_back(v);
        inRegion[static_cast<size_t>(v)] = 1;
      }
    }
    for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
      std::vector<int> next;
      for (int v : frontier) {
        for (int k = stars.start[static_cast<size_t>(v)];
             k < stars.start[static_cast<size_t>(v) + 1]; ++k) {
          for (int a = 0; a < 4; ++a) {
            const int w = rest.tets(stars.tets[static_cast<size_t>(k)], a);
            if (!inRegion[static_cast<size_t>(w)]) next.push_back(w);
            inRegion[static_cast<size_t>(w)] = 1;
          }
        }
      }
      frontier = std::move(next);
    }
    std::vector<int> region;
    for (int v = surfaceCount; v < static_cast<int>(inRegion.size()); ++v) {
      if (inRegion[static_cast<size_t>(v)]) region.push_back(v);
    }
    return region;
  }

  // Step 3: untangle growing neighbourhoods of the inverted tets (the ring
  // count doubles) until none is left, the whole interior was free, or the
  // region would pass effort.maxRings rings (0: no bound). It also stops,
  // leaving the rest to refinement, after an attempt that repaired nothing,
  // and before the ring count would pass the int range (a rest of several
  // parts once retried one region forever). The reference shapes are the
  // rest's, or with effort.thickenedReference its slivers thickened
  // (thickenedTetElements, made on first use). Returns the rounds performed.
  // Keeps the attempt with the fewest inverted tets.
  // Stopping after one failed attempt instead of two in a row (measured
  // 2026-11-29 over 12 twisted or harshly skinned meshes, the lion's 48
  // gallop frames, four 48-frame animations, four open and holed rehearsals
  // and the hard-pose corpus): the same inverted and excluded tets in every
  // set, 431 -> 402 s in all; the lion 68 -> 53 s, where 6- and 12-ring
  // attempts of 0.5-1 s each after a 3-ring one that left 1-3 tets repaired
  // none and refinement did. With no limit, the 536 k-tet subdivided
  // armadillo had tried regions of 2 k, 13 k, 29 k and 36 k vertices (46 s),
  // each leaving more tets inverted than its start.
  int untangleInverted(Vertices& positions, const UntangleEffort& effort) {
    if (effort.thickenedReference) {
      tbb::collaborative_call_once(thickenedOnce, [this] {
        thickenedElements = thickenedTetElements(rest, elements, kThickenedSingularRatio);
      });
    }
    const std::vector<TetElement>& reference =
        effort.thickenedReference ? thickenedElements : elements;
    int rounds = 0;
    std::vector<int> inverted = invertedTets(positions, rest.tets);
    bool first = true;
    for (int rings = options.untangleRings; !inverted.empty(); rings *= 2) {
      const std::vector<int> region = interiorRegion(inverted, rings);
      if (region.empty()) break;
      Vertices current = positions;  // every attempt starts from the best state
      UntangleEffort attempt = effort;
      if (first) attempt.stallRounds = effort.firstAttemptStallRounds;
      first = false;
      const FreeRegionAround around = [&](const std::vector<int>& bad) {
        return interiorRegion(bad, rings);
      };
      rounds += untangle(rest.tets, reference, region, attempt, current, around).rounds;
      std::vector<int> now = invertedTets(current, rest.tets);
      if (now.size() >= inverted.size()) break;
      positions = std::move(current);
      inverted = std::move(now);
      if (static_cast<int>(region.size()) == interiorCount) break;
      if (effort.maxRings > 0 && 2 * rings > effort.maxRings) break;
      if (rings > std::numeric_limits<int>::max() / 2) break;
    }
    return rounds;
  }

  // Interior positions X_I = K_II^{-1} (rhs - K_IB X_B), all as #rows by k.
  Eigen::MatrixXd solveInterior(const Eigen::MatrixXd& rhs, const Eigen::MatrixXd& boundary) const {
    const Eigen::MatrixXd shifted = rhs - couplingBlock * boundary;
    const std::lock_guard<std::mutex> lock(solveMutex);
    if (permutation.size() == 0) return solver->solve(shifted);
    return permutation.transpose() * solver->solve(permutation * shifted);
  }

  // Σ_t vol_t R_t g_a over the tets, restricted to interior vertices a (the
  // right-hand side of the ARAP global step), gathered per vertex so the
  // vertices are independent and the sums are in a fixed order.
  void arapRhs(const RotationField& rotations, Eigen::MatrixXd& rhs) const {
    rhs.resize(interiorCount, 3);
    parallelFor(interiorCount, [&](Eigen::Index i) {
      const int v = surfaceCount + static_cast<int>(i);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int k = stars.start[static_cast<size_t>(v)]; k < stars.start[static_cast<size_t>(v) + 1];
           ++k) {
        const int t = stars.tets[static_cast<size_t>(k)];
        const TetElement& element = elements[static_cast<size_t>(t)];
        int a = 0;
        while (rest.tets(t, a) != v) ++a;
        sum += element.volume * (rotations[static_cast<size_t>(t)] * element.gradients.col(a));
      }
      rhs.row(i) = sum.transpose();
    });
  }

  // Local step: the rotation closest to each tet's deformation gradient,
  // written into `rotations` (resized to #T). Returns the ARAP energy
  // Σ_t vol_t ‖F_t − R_t‖² / Σ_t vol_t.
  double localRotations(const Vertices& positions, RotationField& rotations) const {
    rotations.resize(elements.size());
    std::vector<double> residual(elements.size());
    parallelRanges(rest.tets.rows(), [&](Eigen::Index begin, Eigen::Index end) {
      std::vector<Eigen::Matrix3d> f(static_cast<size_t>(end - begin));
      for (Eigen::Index t = begin; t != end; ++t) {
        f[static_cast<size_t>(t - begin)] =
            deformationGradient(positions, rest.tets.row(t), elements[static_cast<size_t>(t)]);
      }
      closestRotations(f.data(), rotations.data() + begin, f.size());
      for (Eigen::Index t = begin; t != end; ++t) {
        residual[static_cast<size_t>(t)] =
            elements[static_cast<size_t>(t)].volume *
            (f[static_cast<size_t>(t - begin)] - rotations[static_cast<size_t>(t)]).squaredNorm();
      }
    });
    return std::accumulate(residual.begin(), residual.end(), 0.0) / totalVolume;
  }

  // ARAP energy (as localRotations, from singular values instead of an SVD
  // per tet) and min_t det F_t of `positions`, stored into `result`.
  void measure(const Vertices& positions, CompatibleTetResult& result) const {
    std::vector<double> residual(elements.size());
    std::vector<double> determinant(elements.size());
    parallelFor(rest.tets.rows(), [&](Eigen::Index t) {
      const TetElement& element = elements[static_cast<size_t>(t)];
      const Eigen::Matrix3d f = deformationGradient(positions, rest.tets.row(t), element);
      const double det = f.determinant();
      determinant[static_cast<size_t>(t)] = det;
      residual[static_cast<size_t>(t)] = element.volume * arapResidual(f, det);
    });
    result.arapEnergy = std::accumulate(residual.begin(), residual.end(), 0.0) / totalVolume;
    result.minVolumeRatio =
        determinant.empty() ? INFINITY : *std::min_element(determinant.begin(), determinant.end());
  }

  // Rotations propagated from the boundary: each surface triangle's rotation
  // (closest rotation to the map of its frame (e1, e2, unit normal)) is
  // averaged at its corners, extended harmonically to the interior (the same
  // factorisation, 9 right-hand sides), averaged over each tet's corners and
  // projected back to SO(3).
  RotationField propagatedRotations(const Vertices& example) {
    tbb::collaborative_call_once(trianglesOnce, [this] {
      surfaceTriangles = surfaceFirstBoundary(rest.tets, surfaceCount);
    });
    Eigen::MatrixXd boundary = Eigen::MatrixXd::Zero(surfaceCount, 9);
    for (Eigen::Index f = 0; f < surfaceTriangles.rows(); ++f) {
      auto frame = [&](const Vertices& positions) {
        const Eigen::Vector3d a = positions.row(surfaceTriangles(f, 0));
        Eigen::Matrix3d m;
        m.col(0) = Eigen::Vector3d(positions.row(surfaceTriangles(f, 1))) - a;
        m.col(1) = Eigen::Vector3d(positions.row(surfaceTriangles(f, 2))) - a;
        m.col(2) = m.col(0).cross(m.col(1)).normalized();
        return m;
      };
      const Eigen::Matrix3d restFrame = frame(rest.vertices);
      const double area = 0.5 * restFrame.col(0).cross(restFrame.col(1)).norm();
      const Eigen::Matrix3d rotation = closestRotation(frame(example) * restFrame.inverse());
      const Eigen::Map<const Eigen::Matrix<double, 1, 9>> flat(rotation.data());
      for (int k = 0; k < 3; ++k) boundary.row(surfaceTriangles(f, k)) += area * flat;
    }
    const Eigen::MatrixXd interior =
        solveInterior(Eigen::MatrixXd::Zero(interiorCount, 9), boundary);
    RotationField rotations(elements.size());
    parallelRanges(rest.tets.rows(), [&](Eigen::Index begin, Eigen::Index end) {
      std::vector<Eigen::Matrix3d> sums(static_cast<size_t>(end - begin));
      for (Eigen::Index t = begin; t != end; ++t) {
        Eigen::Matrix<double, 1, 9> sum = Eigen::Matrix<double, 1, 9>::Zero();
        for (int a = 0; a < 4; ++a) {
          const int v = rest.tets(t, a);
          if (v < surfaceCount) {
            sum += boundary.row(v);
          } else {
            sum += interior.row(v - surfaceCount);
          }
        }
        sums[static_cast<size_t>(t - begin)] = Eigen::Map<Eigen::Matrix3d>(sum.data());
      }
      closestRotations(sums.data(), rotations.data() + begin, sums.size());
    });
    return rotations;
  }

  // Step 2: ARAP from the harmonic extension in `result.vertices` (or from
  // the propagated-rotation start), keeping the candidate with the fewest
  // inverted tets, then the lowest ARAP energy: ARAP can fold strongly
  // compressed regions that harmonic kept valid. With options.stopWhenValid
  // the first candidate without inverted tets ends the search.
  void arapSearch(const Vertices& example, int maxIterations, CompatibleTetResult& result) {
    const Eigen::MatrixXd boundary = example;
    Vertices best;
    std::pair<size_t, double> bestKey(SIZE_MAX, INFINITY);
    auto consider = [&](const Vertices& candidate, double energy) {
      const std::pair<size_t, double> key(invertedTets(candidate, rest.tets).size(), energy);
      if (key < bestKey) {
        best = candidate;
        bestKey = key;
      }
      return options.stopWhenValid && bestKey.first == 0;
    };
    RotationField rotations;
    double energy = localRotations(result.vertices, rotations);
    bool done = consider(result.vertices, energy);
    Vertices current = result.vertices;
    Eigen::MatrixXd rhs;
    if (options.propagateRotations && !done) {
      arapRhs(propagatedRotations(example), rhs);
      Vertices propagated = assemble(example, solveInterior(rhs, boundary));
      RotationField propagatedRotations;
      const double propagatedEnergy = localRotations(propagated, propagatedRotations);
      done = consider(propagated, propagatedEnergy);
      if (propagatedEnergy < energy) {  // warm start from the better of the two
        current = std::move(propagated);
        rotations = std::move(propagatedRotations);
      }
    }
    const double tolerance = options.arapRelativeTolerance * diagonal;
    for (int iteration = 0; iteration < maxIterations && !done; ++iteration) {
      arapRhs(rotations, rhs);
      const Eigen::MatrixXd interior = solveInterior(rhs, boundary);
      const double moved =
          (interior - current.bottomRows(interiorCount)).rowwise().norm().maxCoeff();
      current.bottomRows(interiorCount) = interior;
      ++result.arapIterations;
      const double previousEnergy = energy;
      energy = localRotations(current, rotations);
      done = consider(current, energy) || moved <= tolerance ||
             energy > (1.0 - options.arapStallFall) * previousEnergy;
    }
    result.vertices = std::move(best);
  }

  // Step 2 with arapRings > 0 (examples whose surface intersects itself):
  // ARAP over the interior vertices within `rings` tet-rings of the
  // harmonic map's inverted tets, every other vertex kept (local_arap.h),
  // when they are at most kLocalArapShare of the interior; false, changing
  // nothing, otherwise.
  bool localArapSearch(int iterations, int rings, CompatibleTetResult& result) const {
    if (rings <= 0) return false;
    const std::vector<int> region = interiorRegion(result.invertedTets, rings);
    if (static_cast<double>(region.size()) > kLocalArapShare * interiorCount) return false;
    LocalArapStops stops;
    stops.maxIterations = iterations;
    stops.tolerance = options.arapRelativeTolerance * diagonal;
    stops.stallFall = options.arapStallFall;
    stops.stopWhenValid = options.stopWhenValid;
    result.arapIterations += localArap(rest.tets, elements, stars, region, stops, result.vertices);
    return true;
  }

  Vertices assemble(const Vertices& example, const Eigen::MatrixXd& interior) const {
    Vertices positions(surfaceCount + interiorCount, 3);
    positions.topRows(surfaceCount) = example;
    positions.bottomRows(interiorCount) = interior;
    return positions;
  }
};

CompatibleTetBuilder::CompatibleTetBuilder(const TetMesh& rest, int surfaceVertexCount,
                                           const CompatibleTetOptions& options,
                                           std::shared_future<std::vector<int>> interiorOrder)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const int vertexCount = static_cast<int>(rest.vertices.rows());
  if (surfaceVertexCount < 1 || surfaceVertexCount > vertexCount) {
    throw InputError("CompatibleTetBuilder: surface vertex count " +
                     std::to_string(surfaceVertexCount) + " is outside [1, " +
                     std::to_string(vertexCount) + "]");
  }
  m.rest = rest;
  m.surfaceCount = surfaceVertexCount;
  m.interiorCount = vertexCount - surfaceVertexCount;
  m.options = options;
  m.interiorOrder = std::move(interiorOrder);
  m.elements = buildTetElements(rest);
  for (const TetElement& element : m.elements) m.totalVolume += element.volume;
  m.diagonal = boundingBoxDiagonal(rest.vertices);
  m.stars = vertexStars(rest.tets, vertexCount);
  requireInteriorVerticesInside(rest.tets, m.stars, surfaceVertexCount);
}

CompatibleTetBuilder::~CompatibleTetBuilder() = default;
CompatibleTetBuilder::CompatibleTetBuilder(CompatibleTetBuilder&&) noexcept = default;
CompatibleTetBuilder& CompatibleTetBuilder::operator=(CompatibleTetBuilder&&) noexcept = default;

int CompatibleTetBuilder::surfaceVertexCount() const { return impl_->surfaceCount; }
const TetMesh& CompatibleTetBuilder::restMesh() const { return impl_->rest; }

void CompatibleTetBuilder::factor() const {
  if (impl_->interiorCount > 0) impl_->requireFactor();
}

void CompatibleTetBuilder::releaseFactor() const {
  impl_->solver.reset();
  impl_->factorOnce.emplace();
}

Vertices CompatibleTetBuilder::harmonicExtension(const Vertices& exampleSurface) const {
  Impl& m = *impl_;
  m.requireExampleSurface(exampleSurface, m.surfaceCount);
  if (m.interiorCount == 0) return exampleSurface;
  m.requireFactor();
  const Eigen::MatrixXd boundary = exampleSurface;
  return m.assemble(exampleSurface,
                    m.solveInterior(Eigen::MatrixXd::Zero(m.interiorCount, 3), boundary));
}

CompatibleTetResult CompatibleTetBuilder::place(const Vertices& exampleSurface) const {
  return place(exampleSurface, impl_->options.arapIterations);
}

CompatibleTetResult CompatibleTetBuilder::place(const Vertices& exampleSurface, int arapIterations,
                                                int arapRings) const {
  Impl& m = *impl_;
  CompatibleTetResult result;
  result.vertices = harmonicExtension(exampleSurface);
  result.invertedTets = invertedTets(result.vertices, m.rest.tets);
  result.harmonicInvertedCount = static_cast<int>(result.invertedTets.size());
  const bool harmonicAccepted = m.options.stopWhenValid && result.invertedTets.empty();
  if (m.interiorCount > 0 && !harmonicAccepted) {
    if (!m.localArapSearch(arapIterations, arapRings, result)) {
      m.arapSearch(exampleSurface, arapIterations, result);
    }
    if (m.options.untangle) {
      result.untangleRounds = m.untangleInverted(result.vertices, m.options.untangleEffort);
    }
    result.invertedTets = invertedTets(result.vertices, m.rest.tets);
  }
  m.measure(result.vertices, result);
  for (int t : result.invertedTets) {
    result.invertedVolumes.push_back(tetSignedVolume(result.vertices, m.rest.tets.row(t)));
  }
  return result;
}

CompatibleTetResult CompatibleTetBuilder::repair(const Vertices& start,
                                                 const UntangleEffort& effort) const {
  Impl& m = *impl_;
  m.requireExampleSurface(start, m.rest.vertices.rows());
  CompatibleTetResult result;
  result.vertices = start;
  result.untangleRounds = m.untangleInverted(result.vertices, effort);
  CompatibleTetResult measured = evaluate(result.vertices);
  measured.untangleRounds = result.untangleRounds;
  return measured;
}

CompatibleTetResult CompatibleTetBuilder::evaluate(const Vertices& positions) const {
  const Impl& m = *impl_;
  m.requireExampleSurface(positions, m.rest.vertices.rows());
  CompatibleTetResult result;
  result.vertices = positions;
  result.invertedTets = invertedTets(positions, m.rest.tets);
  m.measure(positions, result);
  for (int t : result.invertedTets) {
    result.invertedVolumes.push_back(tetSignedVolume(positions, m.rest.tets.row(t)));
  }
  return result;
}

std::vector<int> invertedTets(const Vertices& vertices, const Tets& tets) {
  // The volumes on TBB's threads (ARAP measures every candidate: ~15 calls
  // per example at 1 M tets), the indices gathered in order.
  std::vector<char> inverted(static_cast<std::size_t>(tets.rows()));
  parallelFor(tets.rows(), [&](Eigen::Index t) {
    inverted[static_cast<std::size_t>(t)] = !(tetSignedVolume(vertices, tets.row(t)) > 0.0);
  });
  std::vector<int> result;
  for (std::size_t t = 0; t < inverted.size(); ++t) {
    if (inverted[t]) result.push_back(static_cast<int>(t));
  }
  return result;
}

}  // namespace tetblend
