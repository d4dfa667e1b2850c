#include "supernodal_factor.h"

#include <cholmod.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "supernodal_kernels.h"
#include "tetblend/core/cholmod_values_ahead.h"
#include "tetblend/core/error.h"
#include "tetblend/core/memory_preflight.h"
#include "tetblend/core/openmp_teams.h"

namespace tetblend {
namespace stitch_detail {

namespace {

using UpdateMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3>;

// Off-diagonal blocks with at least this many entries are split over two
// threads in the sequential top of the elimination tree (below it, the two
// halves of the tree already run concurrently).
constexpr int64_t kParallelEntries = 1 << 15;

// Analyses and factors `view` with CHOLMOD; returns the factor or throws.
// Between the two, the memory of the peak is checked (memory_preflight.h):
// CHOLMOD's values (xsize doubles), their copy in SupernodalFactor, and the
// BLAS buffers.
cholmod_factor* cholmodFactor(cholmod_sparse& view, cholmod_common& common) {
  cholmod_factor* factor = cholmod_analyze(&view, &common);
  if (factor != nullptr) {
    try {
      requireAllocatable(
          2 * sizeof(double) * factor->xsize + blasWorkspaceBytes(),
          "the stitch's Cholesky factorisation (" + std::to_string(view.nrow) + " free vertices)");
    } catch (const ResourceError&) {
      cholmod_free_factor(&factor, &common);
      cholmod_finish(&common);
      throw;
    }
  }
  useOpenMpTeams(true);
  bool factored = false;
  {
    const SupernodalValuesAhead ahead(factor, &common);
    factored = factor != nullptr && cholmod_factorize(&view, factor, &common) &&
               common.status == CHOLMOD_OK && factor->minor >= factor->n;
  }
  if (!factored || !factor->is_super || !factor->is_ll) {
    if (factor != nullptr) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
    throw NumericalError(
        "stitch: CHOLMOD could not factor G^T W G as supernodal LL^T (the rest mesh may have "
        "near-degenerate tets)");
  }
  return factor;
}

}  // namespace

SupernodalFactor::SupernodalFactor(Eigen::SparseMatrix<double>& lower) {
  cholmod_common common{};
  cholmod_start(&common);
  common.print = 0;  // library code never prints; failures are thrown below
  common.supernodal = CHOLMOD_SUPERNODAL;
  // METIS and AMD, keeping the one of fewer flops. CHOLMOD's default tries
  // METIS only when AMD's fill is high, but on the benchmark's box grids
  // METIS gives fewer entries at every size: 187k against AMD's 212k (2.4k
  // vertices), 599k / 707k (5.4k), 4.9M / 7.3M (23k); NESDIS is within 2% of
  // METIS.
  common.nmethods = 2;
  common.method[0].ordering = CHOLMOD_METIS;
  common.method[1].ordering = CHOLMOD_AMD;
  common.postorder = 1;  // findSplit needs each subtree to be a contiguous range
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<size_t>(lower.rows());
  view.nzmax = static_cast<size_t>(lower.nonZeros());
  view.p = lower.outerIndexPtr();
  view.i = lower.innerIndexPtr();
  view.x = lower.valuePtr();
  view.stype = -1;  // lower triangle stored
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  cholmod_factor* factor = cholmodFactor(view, common);
  const auto nsuper = static_cast<int>(factor->nsuper);
  const auto* super = static_cast<const int*>(factor->super);
  const auto* pi = static_cast<const int*>(factor->pi);
  const auto* px = static_cast<const int*>(factor->px);
  const auto* rowIndex = static_cast<const int*>(factor->s);
  const auto* values = static_cast<const double*>(factor->x);
  const auto* perm = static_cast<const int*>(factor->Perm);
  perm_.assign(perm, perm + factor->n);
  super_.assign(super, super + nsuper + 1);
  rowStart_.assign(nsuper + 1, 0);
  valueStart_.assign(nsuper + 1, 0);
  for (int s = 0; s < nsuper; ++s) {
    const int columns = super[s + 1] - super[s], below = (pi[s + 1] - pi[s]) - columns;
    rowStart_[s + 1] = rowStart_[s] + below;
    valueStart_[s + 1] =
        valueStart_[s] + triangleSize(columns) + static_cast<int64_t>(below) * columns;
  }
  rows_.resize(rowStart_[nsuper]);
  values_.resize(valueStart_[nsuper]);
  for (int s = 0; s < nsuper; ++s) {
    const int columns = super[s + 1] - super[s], height = pi[s + 1] - pi[s];
    const int below = height - columns;
    std::copy(rowIndex + pi[s] + columns, rowIndex + pi[s + 1], rows_.begin() + rowStart_[s]);
    const double* block = values + px[s];  // column-major, height by columns
    double* triangle = values_.data() + valueStart_[s];
    double* offDiagonal = triangle + triangleSize(columns);
    for (int c = 0; c < columns; ++c) {
      const double* column = block + static_cast<int64_t>(c) * height;
      std::copy(column + c, column + columns, triangle + triangleOffset(c, columns));
      std::copy(column + columns, column + height, offDiagonal + static_cast<int64_t>(c) * below);
    }
  }
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  finish();
}

SupernodalFactor::SupernodalFactor(StitchFactorData data, int unknowns)
    : perm_(std::move(data.perm)),
      super_(std::move(data.super)),
      rowStart_(std::move(data.rowStart)),
      rows_(std::move(data.rows)),
      valueStart_(std::move(data.valueStart)),
      values_(std::move(data.values)) {
  const auto fail = [](const std::string& what) {
    throw InputError("stored stitch factor: " + what);
  };
  const auto n = static_cast<size_t>(unknowns);
  if (perm_.size() != n)
    fail("its permutation has " + std::to_string(perm_.size()) + " entries for " +
         std::to_string(n) + " unknowns");
  std::vector<char> seen(n, 0);
  for (int p : perm_) {
    if (p < 0 || static_cast<size_t>(p) >= n || seen[p])
      fail("its permutation repeats or skips " + std::to_string(p));
    seen[p] = 1;
  }
  if (super_.empty() || super_.front() != 0 || static_cast<size_t>(super_.back()) != n) {
    fail("its supernodes do not cover the " + std::to_string(n) + " unknowns");
  }
  const size_t nsuper = super_.size() - 1;
  if (rowStart_.size() != nsuper + 1 || valueStart_.size() != nsuper + 1 || rowStart_[0] != 0 ||
      valueStart_[0] != 0) {
    fail("its block starts do not match its " + std::to_string(nsuper) + " supernodes");
  }
  for (size_t s = 0; s < nsuper; ++s) {
    // 64-bit differences: the entries are not yet known to be in range.
    const int64_t columns = int64_t{super_[s + 1]} - super_[s];
    const int64_t below = int64_t{rowStart_[s + 1]} - rowStart_[s];
    if (columns <= 0 || below < 0 || static_cast<uint64_t>(rowStart_[s + 1]) > rows_.size()) {
      fail("supernode " + std::to_string(s) + " has an empty or out-of-range block");
    }
    int previous = super_[s + 1] - 1;  // the rows lie below the supernode, ascending
    for (int i = rowStart_[s]; i < rowStart_[s + 1]; ++i) {
      if (rows_[i] <= previous || static_cast<size_t>(rows_[i]) >= n) {
        fail("supernode " + std::to_string(s) + " has row " + std::to_string(rows_[i]) +
             " out of order or range");
      }
      previous = rows_[i];
    }
    const int64_t values = triangleSize(static_cast<int>(columns)) + below * columns;
    if (valueStart_[s] < 0 || valueStart_[s + 1] < valueStart_[s] ||
        valueStart_[s + 1] - valueStart_[s] != values) {
      fail("supernode " + std::to_string(s) + " has the wrong number of values");
    }
  }
  if (static_cast<size_t>(rowStart_.back()) != rows_.size() ||
      static_cast<size_t>(valueStart_.back()) != values_.size()) {
    fail("its row or value count does not match its supernodes");
  }
  finish();
}

StitchFactorData SupernodalFactor::data() const {
  return {perm_, super_, rowStart_, rows_, valueStart_, values_};
}

void SupernodalFactor::finish() {
  for (size_t s = 0; s + 1 < super_.size(); ++s) {
    maxUpdateRows_ = std::max<Eigen::Index>(maxUpdateRows_, rowStart_[s + 1] - rowStart_[s]);
    maxColumns_ = std::max<Eigen::Index>(maxColumns_, super_[s + 1] - super_[s]);
  }
  findSplit();
}

double SupernodalFactor::bytes() const {
  return static_cast<double>(sizeof(double) * values_.size() +
                             sizeof(int) *
                                 (perm_.size() + super_.size() + rowStart_.size() + rows_.size()) +
                             sizeof(int64_t) * valueStart_.size());
}

// Forward substitution L y = b over supernodes [begin, end); updates of
// rows >= sharedRow go to `shared` (rows relative to sharedRow) instead.
// Per supernode: the triangle by columns, then u = L21 X four columns at a
// time (x, y and z of u as separate arrays, so the row loop vectorises).
void SupernodalFactor::forward(int begin, int end, double* yv, UpdateMatrix& u, UpdateMatrix& t,
                               int sharedRow, double* shared, bool parallel) const {
  const Eigen::Index ld = u.rows(), tld = t.rows();
  double* ux = u.data();
  double* uy = ux + ld;
  double* uz = uy + ld;
  for (int s = begin; s < end; ++s) {
    const int first = super_[s], columns = super_[s + 1] - first;
    const int below = rowStart_[s + 1] - rowStart_[s];
    const double* triangle = values_.data() + valueStart_[s];
    double* x = yv + 3 * static_cast<int64_t>(first);
    toColumns(x, columns, t.data(), tld);
    triangleForward(triangle, columns, t.data(), t.data() + tld, t.data() + 2 * tld, parallel);
    fromColumns(t.data(), tld, columns, x);
    if (below == 0) continue;
    std::fill(ux, ux + below, 0.0);
    std::fill(uy, uy + below, 0.0);
    std::fill(uz, uz + below, 0.0);
    const double* block = triangle + triangleSize(columns);
    if (parallel && static_cast<int64_t>(below) * columns >= kParallelEntries) {
      const int half = below / 2;
      tbb::parallel_invoke([&] { addProduct(block, below, x, columns, 0, half, ux, uy, uz); },
                           [&] { addProduct(block, below, x, columns, half, below, ux, uy, uz); });
    } else {
      addProduct(block, below, x, columns, 0, below, ux, uy, uz);
    }
    const int* target = rows_.data() + rowStart_[s];
    for (int i = 0; i < below; ++i) {
      double* row = target[i] < sharedRow
                        ? yv + 3 * static_cast<int64_t>(target[i])
                        : shared + 3 * static_cast<int64_t>(target[i] - sharedRow);
      row[0] -= ux[i];
      row[1] -= uy[i];
      row[2] -= uz[i];
    }
  }
}

// Back substitution L^T x = y over supernodes [begin, end), in reverse: per
// supernode x -= L21^T u (u the gathered rows below it, four columns at a
// time), then the triangle by columns.
void SupernodalFactor::backward(int begin, int end, double* yv, UpdateMatrix& u, UpdateMatrix& t,
                                bool parallel) const {
  const Eigen::Index ld = u.rows(), tld = t.rows();
  double* ux = u.data();
  double* uy = ux + ld;
  double* uz = uy + ld;
  for (int s = end - 1; s >= begin; --s) {
    const int first = super_[s], columns = super_[s + 1] - first;
    const int below = rowStart_[s + 1] - rowStart_[s];
    const double* triangle = values_.data() + valueStart_[s];
    double* x = yv + 3 * static_cast<int64_t>(first);
    if (below > 0) {
      const int* source = rows_.data() + rowStart_[s];
      for (int i = 0; i < below; ++i) {
        const double* row = yv + 3 * static_cast<int64_t>(source[i]);
        ux[i] = row[0];
        uy[i] = row[1];
        uz[i] = row[2];
      }
      const double* block = triangle + triangleSize(columns);
      if (parallel && static_cast<int64_t>(below) * columns >= kParallelEntries) {
        const int half = columns / 2;
        tbb::parallel_invoke([&] { subtractDots(block, below, x, 0, half, ux, uy, uz); },
                             [&] { subtractDots(block, below, x, half, columns, ux, uy, uz); });
      } else {
        subtractDots(block, below, x, 0, columns, ux, uy, uz);
      }
    }
    toColumns(x, columns, t.data(), tld);
    triangleBackward(triangle, columns, t.data(), t.data() + tld, t.data() + 2 * tld, parallel);
    fromColumns(t.data(), tld, columns, x);
  }
}

// Solves L L^T y = b in place on `y` (permuted order, #free by 3). The
// postordered supernodes [0, split) and [split, top) (chosen by findSplit)
// are unions of whole subtrees of the elimination tree with no ancestor in
// each other, so they share only the rows of supernodes >= top and run on
// two threads; the forward pass sends their updates of rows >= the first
// column of `top_` to per-half buffers, added in a fixed order after
// (deterministic). The other supernodes run sequentially.
void SupernodalFactor::solve(RowMatrix3& y, SupernodalWorkspace& workspace) const {
  auto& update = workspace.update;
  auto& column = workspace.columns;
  auto& shared = workspace.shared;
  const auto nsuper = static_cast<int>(super_.size()) - 1;
  const int* super = super_.data();
  for (auto& u : update) u.resize(std::max<Eigen::Index>(maxUpdateRows_, 1), 3);
  for (auto& t : column) t.resize(std::max<Eigen::Index>(maxColumns_, 1), 3);
  double* yv = y.data();
  const auto n = static_cast<int>(y.rows());
  if (split_ <= 0) {
    forward(0, nsuper, yv, update[0], column[0], n, nullptr, true);
    backward(0, nsuper, yv, update[0], column[0], true);
    return;
  }
  const int topRow = super[top_];
  for (auto& b : shared) b.setZero(n - topRow, 3);
  tbb::parallel_invoke(
      [&] { forward(0, split_, yv, update[0], column[0], topRow, shared[0].data(), false); },
      [&] { forward(split_, top_, yv, update[1], column[1], topRow, shared[1].data(), false); });
  y.bottomRows(n - topRow) += shared[0];
  y.bottomRows(n - topRow) += shared[1];
  forward(top_, nsuper, yv, update[0], column[0], n, nullptr, true);
  backward(top_, nsuper, yv, update[0], column[0], true);
  tbb::parallel_invoke([&] { backward(0, split_, yv, update[0], column[0], false); },
                       [&] { backward(split_, top_, yv, update[1], column[1], false); });
}

// Chooses `split_` and `top_`. In a postorder every prefix
// [0, split) is a union of whole subtrees; [split, top) is one too when
// `top` is the parent of supernode split - 1 (a supernode in between whose
// subtree reached below split would be an ancestor of split - 1 smaller
// than its parent), and the two halves then have no ancestor in each other.
// Each split is scored by the entries read on the longer path, max(half 0,
// half 1) + everything from top on (sequential), and the cheapest kept.
// split_ = 0 (sequential) when the supernodes are not postordered or no
// split beats one thread.
void SupernodalFactor::findSplit() {
  const auto nsuper = static_cast<int>(super_.size()) - 1;
  const int* super = super_.data();
  const int64_t* px = valueStart_.data();
  if (nsuper < 3) return;
  std::vector<int> column(perm_.size()), parent(nsuper, -1), first(nsuper);
  for (int s = 0; s < nsuper; ++s) {
    first[s] = s;
    for (int c = super[s]; c < super[s + 1]; ++c) column[c] = s;
  }
  std::vector<int> subtreeSize(nsuper, 1);
  for (int s = 0; s < nsuper; ++s) {
    if (rowStart_[s + 1] == rowStart_[s]) continue;
    parent[s] = column[rows_[rowStart_[s]]];  // > s in any elimination order
    first[parent[s]] = std::min(first[parent[s]], first[s]);
    subtreeSize[parent[s]] += subtreeSize[s];
  }
  // The two halves solve concurrently only if every subtree is the range
  // [first, s] (a postorder): otherwise they could share rows.
  for (int s = 0; s < nsuper; ++s) {
    if (subtreeSize[s] != s - first[s] + 1) return;
  }
  const auto entries = [&](int begin, int end) { return double(px[end]) - double(px[begin]); };
  double bestCost = entries(0, nsuper);
  for (int split = 1; split < nsuper; ++split) {
    const int top = parent[split - 1] < 0 ? nsuper : parent[split - 1];
    const double cost = std::max(entries(0, split), entries(split, top)) + entries(top, nsuper);
    if (cost < bestCost) {
      bestCost = cost;
      split_ = split;
      top_ = top;
    }
  }
}

}  // namespace stitch_detail
}  // namespace tetblend
