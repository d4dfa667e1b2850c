#include "tetblend/blending/stitch_solver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

#ifdef TETBLEND_HAVE_CHOLMOD
#include "supernodal_factor.h"
#endif

namespace tetblend {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RowMatrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Clock = std::chrono::steady_clock;

// Fixed number of tet chunks of the right-hand side (a constant, not the
// thread count, so the summation order never changes).
constexpr int kRhsChunks = 8;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Gradient coefficients g_i (Sumner–Popović): grad_j(x) = sum_i x_i g_i^T,
// with g_i = row i-1 of D_rest^-1 for i = 1..3 and g_0 = -(g_1 + g_2 + g_3).
Eigen::Vector3d cornerGradient(const Eigen::Matrix3d& inverseEdges, int corner) {
  if (corner == 0) return -inverseEdges.colwise().sum().transpose();
  return inverseEdges.row(corner - 1).transpose();
}

int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

}  // namespace

struct StitchSolver::Impl {
  Tets tets;
  RestTetData rest;
  std::vector<int> component;      // #V labels
  std::vector<int> componentSize;  // #C vertex counts
  std::vector<int> reducedIndex;   // #V, -1 for pinned vertices
  std::vector<int> freeVertices;   // reduced index -> vertex
  // The tets in kRhsChunks contiguous ranges [chunkTet[c], chunkTet[c + 1]),
  // whose corners lie in the vertex ranges [chunkLow[c], chunkHigh[c]).
  std::vector<int> chunkTet, chunkLow, chunkHigh;
  std::vector<Eigen::Index> chunkOffset;  // chunk c's rows in the summing buffer
  StitchBackend backend = StitchBackend::kEigenSimplicialLdlt;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
#ifdef TETBLEND_HAVE_CHOLMOD
  std::unique_ptr<stitch_detail::SupernodalFactor> supernodal;
  std::vector<int> factorRow;     // free vertex r -> row of the permuted system
  std::vector<int> factorVertex;  // row of the permuted system -> vertex

  void factorCholmod(SparseMatrix& matrix) {
    supernodal = std::make_unique<stitch_detail::SupernodalFactor>(matrix);
    const int* perm = supernodal->perm();
    factorRow.resize(freeVertices.size());
    factorVertex.resize(freeVertices.size());
    for (size_t k = 0; k < freeVertices.size(); ++k) {
      factorRow[perm[k]] = static_cast<int>(k);
      factorVertex[k] = freeVertices[perm[k]];
    }
  }
#endif

  void buildComponents(int vertexCount) {
    std::vector<int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    for (Eigen::Index j = 0; j < tets.rows(); ++j) {
      const int a = findRoot(parent, tets(j, 0));
      for (int c = 1; c < 4; ++c) {
        const int b = findRoot(parent, tets(j, c));
        if (a != b) parent[b] = a;
      }
    }
    component.assign(vertexCount, -1);
    reducedIndex.assign(vertexCount, -1);
    std::vector<int> rootLabel(vertexCount, -1);
    int count = 0;
    for (int v = 0; v < vertexCount; ++v) {
      const int root = findRoot(parent, v);
      if (rootLabel[root] < 0) {
        // The first (lowest-index) vertex of a component is its pinned vertex.
        rootLabel[root] = count++;
        componentSize.push_back(0);
      } else {
        reducedIndex[v] = static_cast<int>(freeVertices.size());
        freeVertices.push_back(v);
      }
      component[v] = rootLabel[root];
      ++componentSize[component[v]];
    }
  }

  void buildChunks() {
    const auto tetCount = static_cast<int>(tets.rows());
    chunkTet.resize(kRhsChunks + 1);
    chunkLow.assign(kRhsChunks, 0);
    chunkHigh.assign(kRhsChunks, 0);
    chunkOffset.assign(kRhsChunks + 1, 0);
    for (int c = 0; c <= kRhsChunks; ++c) {
      chunkTet[c] = static_cast<int>(static_cast<int64_t>(tetCount) * c / kRhsChunks);
    }
    for (int c = 0; c < kRhsChunks; ++c) {
      if (chunkTet[c] < chunkTet[c + 1]) {
        const auto block = tets.middleRows(chunkTet[c], chunkTet[c + 1] - chunkTet[c]);
        chunkLow[c] = block.minCoeff();
        chunkHigh[c] = block.maxCoeff() + 1;
      }
      chunkOffset[c + 1] = chunkOffset[c] + (chunkHigh[c] - chunkLow[c]);
    }
  }

  // rhs(r, :) = sum over the tets j of free vertex r (corner c) of
  // vol_j B_j g_c (Sumner-Popovic eq. 6's right-hand side), rows in reduced
  // order; row rowOf[r] receives free vertex r (identity when rowOf is empty).
  // Each tet is visited once: C = vol_j B_j D_rest,j^-T holds vol_j B_j g_c
  // for corners 1..3 in its columns, and corner 0 gets minus their sum. The
  // chunks of tets are summed in parallel, each sequentially into its own
  // vertex-range buffer; every vertex then adds the buffers in chunk order,
  // so the result does not depend on the schedule or the thread count.
  template <typename Rhs>
  void assembleRhs(const std::vector<Eigen::Matrix3d>& targets, const std::vector<int>& rowOf,
                   RowMatrix3& buffer, Rhs& rhs) const {
    buffer.resize(chunkOffset[kRhsChunks], 3);
    tbb::parallel_for(0, kRhsChunks, [&](int c) {
      auto sums = buffer.middleRows(chunkOffset[c], chunkHigh[c] - chunkLow[c]);
      sums.setZero();
      const int low = chunkLow[c];
      for (int j = chunkTet[c]; j < chunkTet[c + 1]; ++j) {
        const Eigen::Matrix3d columns =
            rest.volumes[j] * (targets[j] * rest.inverseEdges[j].transpose());
        sums.row(tets(j, 0) - low) -= columns.rowwise().sum().transpose();
        for (int corner = 1; corner < 4; ++corner) {
          sums.row(tets(j, corner) - low) += columns.col(corner - 1).transpose();
        }
      }
    });
    const auto freeCount = static_cast<Eigen::Index>(freeVertices.size());
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, freeCount, 4096),
                      [&](const tbb::blocked_range<Eigen::Index>& range) {
                        for (Eigen::Index r = range.begin(); r != range.end(); ++r) {
                          const int v = freeVertices[r];
                          Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
                          for (int c = 0; c < kRhsChunks; ++c) {
                            if (v >= chunkLow[c] && v < chunkHigh[c]) {
                              sum += buffer.row(chunkOffset[c] + v - chunkLow[c]);
                            }
                          }
                          rhs.row(rowOf.empty() ? r : rowOf[r]) = sum;
                        }
                      });
  }

  SparseMatrix reducedNormalMatrix() const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(10 * static_cast<size_t>(tets.rows()));
    for (Eigen::Index j = 0; j < tets.rows(); ++j) {
      Eigen::Vector3d g[4];
      for (int c = 0; c < 4; ++c) g[c] = cornerGradient(rest.inverseEdges[j], c);
      for (int a = 0; a < 4; ++a) {
        const int ra = reducedIndex[tets(j, a)];
        if (ra < 0) continue;
        for (int b = 0; b < 4; ++b) {
          const int rb = reducedIndex[tets(j, b)];
          if (rb < 0 || rb < ra) continue;  // lower triangle (row >= column) only
          triplets.emplace_back(rb, ra, rest.volumes[j] * g[a].dot(g[b]));
        }
      }
    }
    const auto n = static_cast<Eigen::Index>(freeVertices.size());
    SparseMatrix matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
  }

  template <typename Solver>
  void factor(Solver& solver, const SparseMatrix& matrix) {
    solver.compute(matrix);
    if (solver.info() != Eigen::Success) {
      throw NumericalError(
          "stitch: factoring G^T W G failed (the rest mesh may have near-degenerate tets)");
    }
  }
};

struct StitchWorkspace::Impl {
  // Right-hand side, then solution, of the reduced system, one row of x, y, z
  // per free vertex: in the factor's (permuted) order for CHOLMOD, in
  // reduced order for SimplicialLDLT.
  RowMatrix3 values;
  RowMatrix3 chunkSums;  // per-chunk right-hand-side sums (see assembleRhs)
#ifdef TETBLEND_HAVE_CHOLMOD
  stitch_detail::SupernodalWorkspace workspace;
#endif
  Eigen::Matrix<double, Eigen::Dynamic, 3> solution;  // SimplicialLDLT backend only
};

StitchWorkspace::StitchWorkspace() : impl_(std::make_unique<Impl>()) {}
StitchWorkspace::~StitchWorkspace() = default;
StitchWorkspace::StitchWorkspace(StitchWorkspace&&) noexcept = default;
StitchWorkspace& StitchWorkspace::operator=(StitchWorkspace&&) noexcept = default;

StitchSolver::StitchSolver(const TetMesh& rest, const StitchOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.tets = rest.tets;
  m.rest = restTetData(rest);
  const int vertexCount = static_cast<int>(rest.vertices.rows());
  m.buildComponents(vertexCount);
  m.buildChunks();
  SparseMatrix matrix = m.reducedNormalMatrix();
#ifdef TETBLEND_HAVE_CHOLMOD
  if (options.backend == StitchBackend::kCholmodSupernodal && matrix.rows() > 0) {
    m.backend = StitchBackend::kCholmodSupernodal;
    m.factorCholmod(matrix);
    return;
  }
#else
  (void)options;
#endif
  m.backend = StitchBackend::kEigenSimplicialLdlt;
  m.factor(m.ldlt, matrix);
}

StitchSolver::~StitchSolver() = default;
StitchSolver::StitchSolver(StitchSolver&&) noexcept = default;
StitchSolver& StitchSolver::operator=(StitchSolver&&) noexcept = default;

int StitchSolver::vertexCount() const { return static_cast<int>(impl_->component.size()); }
int StitchSolver::tetCount() const { return static_cast<int>(impl_->tets.rows()); }
int StitchSolver::componentCount() const { return static_cast<int>(impl_->componentSize.size()); }
const std::vector<int>& StitchSolver::vertexComponent() const { return impl_->component; }
const RestTetData& StitchSolver::restData() const { return impl_->rest; }
const Tets& StitchSolver::tets() const { return impl_->tets; }
StitchBackend StitchSolver::backend() const { return impl_->backend; }

double StitchSolver::factorNonzeros() const {
#ifdef TETBLEND_HAVE_CHOLMOD
  if (impl_->supernodal) return impl_->supernodal->nonzeros();
#endif
  return static_cast<double>(impl_->ldlt.matrixL().nestedExpression().nonZeros());
}

Centroids StitchSolver::componentCentroids(const Vertices& vertices) const {
  if (vertices.rows() != vertexCount()) {
    std::ostringstream message;
    message << "stitch: " << vertices.rows() << " vertices given, the rest mesh has "
            << vertexCount();
    throw InputError(message.str());
  }
  Centroids centroids = Centroids::Zero(componentCount(), 3);
  for (int v = 0; v < vertexCount(); ++v) centroids.row(impl_->component[v]) += vertices.row(v);
  for (int c = 0; c < componentCount(); ++c) centroids.row(c) /= impl_->componentSize[c];
  return centroids;
}

Vertices StitchSolver::solve(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids) const {
  Vertices result;
  solveInto(targets, centroids, result);
  return result;
}

void StitchSolver::solveInto(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids, Vertices& result,
                             StitchTimings* timings) const {
  StitchWorkspace workspace;
  solveInto(targets, centroids, result, workspace, timings);
}

void StitchSolver::solveInto(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids, Vertices& result,
                             StitchWorkspace& workspace, StitchTimings* timings) const {
  const Impl& m = *impl_;
  StitchWorkspace::Impl& w = *workspace.impl_;
  if (static_cast<int>(targets.size()) != tetCount() || centroids.rows() != componentCount()) {
    std::ostringstream message;
    message << "stitch: got " << targets.size() << " target maps and " << centroids.rows()
            << " centroids for a mesh with " << tetCount() << " tets and " << componentCount()
            << " components";
    throw InputError(message.str());
  }
  auto start = Clock::now();
  const auto freeCount = static_cast<Eigen::Index>(m.freeVertices.size());
  result.setZero(vertexCount(), 3);
#ifdef TETBLEND_HAVE_CHOLMOD
  if (m.backend == StitchBackend::kCholmodSupernodal) {
    w.values.resize(freeCount, 3);
    m.assembleRhs(targets, m.factorRow, w.chunkSums, w.values);
    if (timings != nullptr) timings->rhsSeconds = secondsSince(start);
    start = Clock::now();
    m.supernodal->solve(w.values, w.workspace);
    for (Eigen::Index k = 0; k < freeCount; ++k) result.row(m.factorVertex[k]) = w.values.row(k);
  }
#endif
  if (m.backend == StitchBackend::kEigenSimplicialLdlt) {
    w.values.resize(freeCount, 3);
    m.assembleRhs(targets, {}, w.chunkSums, w.values);
    if (timings != nullptr) timings->rhsSeconds = secondsSince(start);
    start = Clock::now();
    w.solution = m.ldlt.solve(w.values);
    for (Eigen::Index r = 0; r < freeCount; ++r) result.row(m.freeVertices[r]) = w.solution.row(r);
  }
  const Centroids shift = centroids - componentCentroids(result);
  for (int v = 0; v < vertexCount(); ++v) result.row(v) += shift.row(m.component[v]);
  if (timings != nullptr) timings->solveSeconds = secondsSince(start);
}

Eigen::Matrix3d StitchSolver::gradient(const Vertices& x, int tet) const {
  return tetEdgeMatrix(x, impl_->tets.row(tet)) * impl_->rest.inverseEdges[tet];
}

double StitchSolver::energy(const Vertices& x, const std::vector<Eigen::Matrix3d>& targets) const {
  double sum = 0.0;
  for (int j = 0; j < tetCount(); ++j) {
    sum += impl_->rest.volumes[j] * (gradient(x, j) - targets[j]).squaredNorm();
  }
  return sum;
}

}  // namespace tetblend
