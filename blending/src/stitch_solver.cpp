#include "tetblend/blending/stitch_solver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

#ifdef TETBLEND_HAVE_CHOLMOD
#include <cholmod.h>
#endif

namespace tetblend {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RowMatrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Clock = std::chrono::steady_clock;

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
  // Vertex -> incident (tet * 4 + corner), in CSR form, ascending tet order.
  std::vector<int> incidenceStart;
  std::vector<int> incidence;
  StitchBackend backend = StitchBackend::kEigenSimplicialLdlt;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
#ifdef TETBLEND_HAVE_CHOLMOD
  // Supernodal LL^T of the reduced matrix; CHOLMOD's default ordering
  // strategy (AMD, and METIS as well when AMD's fill is high, keeping the
  // sparser factor). Only read after construction.
  cholmod_common common{};
  cholmod_factor* cholmodFactor = nullptr;
  bool commonStarted = false;
  std::vector<int> factorRow;      // free vertex r -> row of the permuted system
  std::vector<int> factorVertex;   // row of the permuted system -> vertex
  Eigen::Index maxUpdateRows = 0;  // largest off-diagonal block of a supernode
  int top = 0;                     // see findSplit
  int low = 0;
  int split = 0;

  // Solves L L^T y = b in place on `y` (permuted order, #free by 3) from the
  // supernodal factor's blocks, reading L only: each supernode's diagonal
  // block is a dense triangular solve and its off-diagonal block one
  // column-by-column update of the three right-hand sides, reading L once per
  // pass. (CHOLMOD's own solve goes through the
  // BLAS, whose narrow three-column kernels were the bottleneck here, and
  // writes its cholmod_common, which would make concurrent solves race.)
  // Forward substitution L y = b over supernodes [begin, end); updates of
  // rows >= sharedRow go to `shared` (rows relative to sharedRow) instead.
  void forward(int begin, int end, double* yv, double* u, int sharedRow, double* shared) const {
    const cholmod_factor& f = *cholmodFactor;
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    const auto* rowIndex = static_cast<const int*>(f.s);
    const auto* values = static_cast<const double*>(f.x);
    for (int s = begin; s < end; ++s) {
      const int first = super[s], columns = super[s + 1] - first;
      const int height = pi[s + 1] - pi[s], below = height - columns;
      const double* block = values + px[s];  // column-major, height by columns
      double* x = yv + 3 * static_cast<Eigen::Index>(first);
      std::fill(u, u + 3 * below, 0.0);
      for (int c = 0; c < columns; ++c) {
        const double* column = block + static_cast<Eigen::Index>(c) * height;
        const double inverse = 1.0 / column[c];
        const double x0 = x[3 * c] *= inverse, x1 = x[3 * c + 1] *= inverse,
                     x2 = x[3 * c + 2] *= inverse;
        for (int i = c + 1; i < columns; ++i) {
          x[3 * i] -= column[i] * x0;
          x[3 * i + 1] -= column[i] * x1;
          x[3 * i + 2] -= column[i] * x2;
        }
        const double* lower = column + columns;
        for (int i = 0; i < below; ++i) {
          u[3 * i] += lower[i] * x0;
          u[3 * i + 1] += lower[i] * x1;
          u[3 * i + 2] += lower[i] * x2;
        }
      }
      const int* target = rowIndex + pi[s] + columns;
      for (int i = 0; i < below; ++i) {
        double* row = target[i] < sharedRow
                          ? yv + 3 * static_cast<Eigen::Index>(target[i])
                          : shared + 3 * static_cast<Eigen::Index>(target[i] - sharedRow);
        row[0] -= u[3 * i];
        row[1] -= u[3 * i + 1];
        row[2] -= u[3 * i + 2];
      }
    }
  }

  // Back substitution L^T x = y over supernodes [begin, end), in reverse.
  void backward(int begin, int end, double* yv, double* u) const {
    const cholmod_factor& f = *cholmodFactor;
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    const auto* rowIndex = static_cast<const int*>(f.s);
    const auto* values = static_cast<const double*>(f.x);
    for (int s = end - 1; s >= begin; --s) {
      const int first = super[s], columns = super[s + 1] - first;
      const int height = pi[s + 1] - pi[s], below = height - columns;
      const double* block = values + px[s];
      double* x = yv + 3 * static_cast<Eigen::Index>(first);
      const int* source = rowIndex + pi[s] + columns;
      for (int i = 0; i < below; ++i) {
        const double* row = yv + 3 * static_cast<Eigen::Index>(source[i]);
        u[3 * i] = row[0];
        u[3 * i + 1] = row[1];
        u[3 * i + 2] = row[2];
      }
      for (int c = columns - 1; c >= 0; --c) {
        const double* column = block + static_cast<Eigen::Index>(c) * height;
        double x0 = x[3 * c], x1 = x[3 * c + 1], x2 = x[3 * c + 2];
        for (int i = c + 1; i < columns; ++i) {
          x0 -= column[i] * x[3 * i];
          x1 -= column[i] * x[3 * i + 1];
          x2 -= column[i] * x[3 * i + 2];
        }
        const double* lower = column + columns;
        for (int i = 0; i < below; ++i) {
          x0 -= lower[i] * u[3 * i];
          x1 -= lower[i] * u[3 * i + 1];
          x2 -= lower[i] * u[3 * i + 2];
        }
        const double inverse = 1.0 / column[c];
        x[3 * c] = x0 * inverse;
        x[3 * c + 1] = x1 * inverse;
        x[3 * c + 2] = x2 * inverse;
      }
    }
  }

  // Solves L L^T y = b in place on `y` (permuted order, #free by 3). Below
  // the split supernode `top` (found by findSplit) the elimination tree's
  // postordered supernodes [low, split) and [split, top) are disjoint
  // subtrees that share only the rows of top and its ancestors, so they run
  // on two threads; the forward pass sends their updates of rows >= the
  // first column of `top` to per-half buffers, added in a fixed order after
  // (deterministic). Supernodes outside top's subtree run sequentially.
  void supernodalSolve(RowMatrix3& y, RowMatrix3 (&update)[2], RowMatrix3 (&shared)[2]) const {
    const auto nsuper = static_cast<int>(cholmodFactor->nsuper);
    const auto* super = static_cast<const int*>(cholmodFactor->super);
    for (auto& u : update) u.resize(maxUpdateRows, 3);
    double* yv = y.data();
    const auto n = static_cast<int>(y.rows());
    if (split <= 0) {
      forward(0, nsuper, yv, update[0].data(), n, nullptr);
      backward(0, nsuper, yv, update[0].data());
      return;
    }
    const int topRow = super[top];
    for (auto& b : shared) b.setZero(n - topRow, 3);
    forward(0, low, yv, update[0].data(), n, nullptr);
    tbb::parallel_invoke(
        [&] { forward(low, split, yv, update[0].data(), topRow, shared[0].data()); },
        [&] { forward(split, top, yv, update[1].data(), topRow, shared[1].data()); });
    y.bottomRows(n - topRow) += shared[0];
    y.bottomRows(n - topRow) += shared[1];
    forward(top, nsuper, yv, update[0].data(), n, nullptr);
    backward(top, nsuper, yv, update[0].data());
    tbb::parallel_invoke([&] { backward(low, split, yv, update[0].data()); },
                         [&] { backward(split, top, yv, update[1].data()); });
    backward(0, low, yv, update[0].data());
  }

  // Chooses `top`, `low` and `split`: from the last root, descend into the
  // largest child subtree while it holds more than 2/3 of the entries, then
  // split top's child subtrees [low, top) at the boundary closest to half of
  // their entries. split = 0 (sequential) when no balanced split exists.
  void findSplit() {
    const cholmod_factor& f = *cholmodFactor;
    const auto nsuper = static_cast<int>(f.nsuper);
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    const auto* rowIndex = static_cast<const int*>(f.s);
    if (nsuper < 3) return;
    std::vector<int> column(f.n), parent(nsuper, -1), first(nsuper);
    for (int s = 0; s < nsuper; ++s) {
      first[s] = s;
      for (int c = super[s]; c < super[s + 1]; ++c) column[c] = s;
    }
    for (int s = 0; s < nsuper; ++s) {
      const int columns = super[s + 1] - super[s];
      if (pi[s + 1] - pi[s] == columns) continue;
      parent[s] = column[rowIndex[pi[s] + columns]];
      if (parent[s] <= s) return;  // not postordered: stay sequential
      first[parent[s]] = std::min(first[parent[s]], first[s]);
    }
    const auto entries = [&](int s) { return double(px[s + 1]) - px[first[s]]; };
    int node = nsuper - 1;
    for (;;) {
      int largest = -1;
      for (int s = first[node]; s < node; ++s) {
        if (parent[s] == node && (largest < 0 || entries(s) > entries(largest))) largest = s;
      }
      if (largest < 0) return;
      if (entries(largest) * 3.0 <= entries(node) * 2.0) break;
      node = largest;
    }
    const double half = 0.5 * (double(px[node]) + px[first[node]]);
    int best = 0;
    for (int s = first[node]; s + 1 < node; ++s) {
      if (parent[s] != node) continue;
      if (best == 0 || std::abs(px[s + 1] - half) < std::abs(px[best] - half)) best = s + 1;
    }
    if (best <= first[node] || best >= node) return;
    top = node;
    low = first[node];
    split = best;
  }

  void factorCholmod(SparseMatrix& matrix) {
    cholmod_start(&common);
    commonStarted = true;
    common.print = 0;  // library code never prints; failures are thrown below
    common.supernodal = CHOLMOD_SUPERNODAL;
    cholmod_sparse view{};
    view.nrow = view.ncol = static_cast<size_t>(matrix.rows());
    view.nzmax = static_cast<size_t>(matrix.nonZeros());
    view.p = matrix.outerIndexPtr();
    view.i = matrix.innerIndexPtr();
    view.x = matrix.valuePtr();
    view.stype = -1;  // lower triangle stored
    view.itype = CHOLMOD_INT;
    view.xtype = CHOLMOD_REAL;
    view.dtype = CHOLMOD_DOUBLE;
    view.sorted = 1;
    view.packed = 1;
    cholmodFactor = cholmod_analyze(&view, &common);
    if (cholmodFactor == nullptr || !cholmod_factorize(&view, cholmodFactor, &common) ||
        common.status != CHOLMOD_OK || cholmodFactor->minor < cholmodFactor->n) {
      throw NumericalError(
          "stitch: CHOLMOD could not factor G^T W G (the rest mesh may have near-degenerate "
          "tets)");
    }
    if (!cholmodFactor->is_super || !cholmodFactor->is_ll) {
      throw NumericalError("stitch: CHOLMOD did not return a supernodal LL^T factor");
    }
    const auto* perm = static_cast<const int*>(cholmodFactor->Perm);
    factorRow.resize(freeVertices.size());
    factorVertex.resize(freeVertices.size());
    for (size_t k = 0; k < freeVertices.size(); ++k) {
      factorRow[perm[k]] = static_cast<int>(k);
      factorVertex[k] = freeVertices[perm[k]];
    }
    findSplit();
    const auto* super = static_cast<const int*>(cholmodFactor->super);
    const auto* pi = static_cast<const int*>(cholmodFactor->pi);
    for (size_t s = 0; s < cholmodFactor->nsuper; ++s) {
      maxUpdateRows =
          std::max<Eigen::Index>(maxUpdateRows, (pi[s + 1] - pi[s]) - (super[s + 1] - super[s]));
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

  void buildIncidence(int vertexCount) {
    incidenceStart.assign(vertexCount + 1, 0);
    for (Eigen::Index j = 0; j < tets.rows(); ++j) {
      for (int c = 0; c < 4; ++c) ++incidenceStart[tets(j, c) + 1];
    }
    std::partial_sum(incidenceStart.begin(), incidenceStart.end(), incidenceStart.begin());
    incidence.resize(4 * static_cast<size_t>(tets.rows()));
    std::vector<int> fill(incidenceStart.begin(), incidenceStart.end() - 1);
    for (Eigen::Index j = 0; j < tets.rows(); ++j) {
      for (int c = 0; c < 4; ++c) incidence[fill[tets(j, c)]++] = static_cast<int>(4 * j + c);
    }
  }

  // rhs(r, :) = sum over the tets j of free vertex r (corner c) of
  // vol_j B_j g_c (Sumner-Popovic eq. 6's right-hand side), rows in reduced order.
  // Row rowOf[r] receives free vertex r (identity when rowOf is empty).
  template <typename Rhs>
  void assembleRhs(const std::vector<Eigen::Matrix3d>& targets, const std::vector<int>& rowOf,
                   Rhs& rhs) const {
    const auto freeCount = static_cast<Eigen::Index>(freeVertices.size());
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, freeCount, 2048),
                      [&](const tbb::blocked_range<Eigen::Index>& range) {
                        for (Eigen::Index r = range.begin(); r != range.end(); ++r) {
                          const int v = freeVertices[r];
                          Eigen::Vector3d sum = Eigen::Vector3d::Zero();
                          for (int k = incidenceStart[v]; k < incidenceStart[v + 1]; ++k) {
                            const int tet = incidence[k] >> 2;
                            const int corner = incidence[k] & 3;
                            sum.noalias() +=
                                rest.volumes[tet] *
                                (targets[tet] * cornerGradient(rest.inverseEdges[tet], corner));
                          }
                          rhs.row(rowOf.empty() ? r : rowOf[r]) = sum.transpose();
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
  RowMatrix3 update[2];  // one supernode's L21 * X, per half of the tree
  RowMatrix3 shared[2];  // each half's forward updates of the top rows
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
  m.buildIncidence(vertexCount);
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
  if (impl_->cholmodFactor != nullptr) return static_cast<double>(impl_->cholmodFactor->xsize);
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
    m.assembleRhs(targets, m.factorRow, w.values);
    if (timings != nullptr) timings->rhsSeconds = secondsSince(start);
    start = Clock::now();
    m.supernodalSolve(w.values, w.update, w.shared);
    for (Eigen::Index k = 0; k < freeCount; ++k) result.row(m.factorVertex[k]) = w.values.row(k);
  }
#endif
  if (m.backend == StitchBackend::kEigenSimplicialLdlt) {
    w.values.resize(freeCount, 3);
    m.assembleRhs(targets, {}, w.values);
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
