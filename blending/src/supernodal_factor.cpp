#include "supernodal_factor.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tetblend/core/error.h"

namespace tetblend {
namespace stitch_detail {

SupernodalFactor::SupernodalFactor(Eigen::SparseMatrix<double>& lower) {
  cholmod_start(&common_);
  common_.print = 0;  // library code never prints; failures are thrown below
  common_.supernodal = CHOLMOD_SUPERNODAL;
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
  factor_ = cholmod_analyze(&view, &common_);
  const bool factored = factor_ != nullptr && cholmod_factorize(&view, factor_, &common_) &&
                        common_.status == CHOLMOD_OK && factor_->minor >= factor_->n;
  if (!factored || !factor_->is_super || !factor_->is_ll) {
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
    throw NumericalError(
        "stitch: CHOLMOD could not factor G^T W G as supernodal LL^T (the rest mesh may have "
        "near-degenerate tets)");
  }
  findSplit();
  const auto* super = static_cast<const int*>(factor_->super);
  const auto* pi = static_cast<const int*>(factor_->pi);
  for (size_t s = 0; s < factor_->nsuper; ++s) {
    maxUpdateRows_ =
        std::max<Eigen::Index>(maxUpdateRows_, (pi[s + 1] - pi[s]) - (super[s + 1] - super[s]));
  }
}

SupernodalFactor::~SupernodalFactor() {
  cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

// Forward substitution L y = b over supernodes [begin, end); updates of
// rows >= sharedRow go to `shared` (rows relative to sharedRow) instead.
void SupernodalFactor::forward(int begin, int end, double* yv, double* u, int sharedRow,
                               double* shared) const {
  const cholmod_factor& f = *factor_;
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
void SupernodalFactor::backward(int begin, int end, double* yv, double* u) const {
  const cholmod_factor& f = *factor_;
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
// the split supernode `top_` (found by findSplit) the elimination tree's
// postordered supernodes [low, split) and [split, top) are disjoint
// subtrees that share only the rows of top_ and its ancestors, so they run
// on two threads; the forward pass sends their updates of rows >= the
// first column of `top_` to per-half buffers, added in a fixed order after
// (deterministic). Supernodes outside top_'s subtree run sequentially.
void SupernodalFactor::solve(RowMatrix3& y, SupernodalWorkspace& workspace) const {
  auto& update = workspace.update;
  auto& shared = workspace.shared;
  const auto nsuper = static_cast<int>(factor_->nsuper);
  const auto* super = static_cast<const int*>(factor_->super);
  for (auto& u : update) u.resize(maxUpdateRows_, 3);
  double* yv = y.data();
  const auto n = static_cast<int>(y.rows());
  if (split_ <= 0) {
    forward(0, nsuper, yv, update[0].data(), n, nullptr);
    backward(0, nsuper, yv, update[0].data());
    return;
  }
  const int topRow = super[top_];
  for (auto& b : shared) b.setZero(n - topRow, 3);
  forward(0, low_, yv, update[0].data(), n, nullptr);
  tbb::parallel_invoke(
      [&] { forward(low_, split_, yv, update[0].data(), topRow, shared[0].data()); },
      [&] { forward(split_, top_, yv, update[1].data(), topRow, shared[1].data()); });
  y.bottomRows(n - topRow) += shared[0];
  y.bottomRows(n - topRow) += shared[1];
  forward(top_, nsuper, yv, update[0].data(), n, nullptr);
  backward(top_, nsuper, yv, update[0].data());
  tbb::parallel_invoke([&] { backward(low_, split_, yv, update[0].data()); },
                       [&] { backward(split_, top_, yv, update[1].data()); });
  backward(0, low_, yv, update[0].data());
}

// Chooses `top_`, `low_` and `split_`: from the last root, descend into the
// largest child subtree while it holds more than 2/3 of the entries, then
// splits top_'s child subtrees [low_, top_) at the boundary closest to half of
// their entries. split_ = 0 (sequential) when no balanced split exists.
void SupernodalFactor::findSplit() {
  const cholmod_factor& f = *factor_;
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
  top_ = node;
  low_ = first[node];
  split_ = best;
}

}  // namespace stitch_detail
}  // namespace tetblend
