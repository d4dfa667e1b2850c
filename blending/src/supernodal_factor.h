#pragma once
// The stitch's supernodal Cholesky factor (private to tetblend_blending):
// CHOLMOD analyses and factors G^T W G once (supernodal LL^T, ordered by
// METIS or AMD, whichever CHOLMOD finds cheaper: METIS on the box grids, 4.9M
// entries in L against AMD's 7.3M at 23k vertices); the factor is repacked
// without CHOLMOD's explicit upper triangles (20% fewer stored entries) and
// the three-column solves are done here from the packed blocks, reading L
// only. CHOLMOD's own solve goes through the BLAS, whose narrow three-column
// kernels (ATLAS here) were the bottleneck, and writes its cholmod_common, so
// concurrent solves would race. Only compiled with TETBLEND_HAVE_CHOLMOD.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "tetblend/blending/blend_cache.h"

namespace tetblend {
namespace stitch_detail {

/// #rows by 3, one row of x, y, z per unknown.
using RowMatrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Scratch of one solve (one per concurrent caller).
struct SupernodalWorkspace {
  /// One supernode's L21 X (forward) or gathered rows (backward), x, y and z
  /// as three columns (structure of arrays), per half of the tree.
  Eigen::Matrix<double, Eigen::Dynamic, 3> update[2];
  /// One supernode's own rows, x, y and z as three columns, per half.
  Eigen::Matrix<double, Eigen::Dynamic, 3> columns[2];
  RowMatrix3 shared[2];  ///< each half's forward updates of the top rows
};

/// LL^T = P A P^T of a symmetric positive definite matrix, factored by
/// CHOLMOD (supernodal, its default ordering choice) and then repacked: per
/// supernode the lower triangle of the diagonal block (column by column) and
/// the dense off-diagonal block L21 (column-major), no explicit upper
/// triangle; CHOLMOD's own factor is freed after the copy.
class SupernodalFactor {
 public:
  /// Factors `lower` (n by n, lower triangle stored, compressed). Throws
  /// NumericalError when A is not positive definite.
  explicit SupernodalFactor(Eigen::SparseMatrix<double>& lower);
  /// A factor stored by data() for a system of `unknowns` unknowns. Throws
  /// InputError, naming the first inconsistency, unless its structure is one
  /// of `unknowns` rows (the values are not checked).
  SupernodalFactor(StitchFactorData data, int unknowns);

  /// The factor's arrays (blend_cache.h), for the constructor above.
  StitchFactorData data() const;

  /// P as CHOLMOD's Perm: row k of the permuted system is unknown perm()[k].
  const int* perm() const { return perm_.data(); }
  /// Stored entries of L (the packed lower trapezoids of the supernodes).
  double nonzeros() const { return static_cast<double>(values_.size()); }
  /// Heap bytes held by the factor.
  double bytes() const;

  /// Solves L L^T y = b in place on `y` (n by 3, permuted order, b on entry).
  /// Const and thread-safe given distinct `y` and `workspace`.
  void solve(RowMatrix3& y, SupernodalWorkspace& workspace) const;

 private:
  // `parallel`: split large blocks over two threads (only outside the two
  // concurrent halves of the tree).
  void forward(int begin, int end, double* yv, Eigen::Matrix<double, Eigen::Dynamic, 3>& u,
               Eigen::Matrix<double, Eigen::Dynamic, 3>& t, int sharedRow, double* shared,
               bool parallel) const;
  void backward(int begin, int end, double* yv, Eigen::Matrix<double, Eigen::Dynamic, 3>& u,
                Eigen::Matrix<double, Eigen::Dynamic, 3>& t, bool parallel) const;
  // The widest supernode and largest off-diagonal block, then findSplit.
  void finish();
  void findSplit();

  std::vector<int> perm_;            // n
  std::vector<int> super_;           // nsuper + 1: first column of each supernode
  std::vector<int> rowStart_;        // nsuper + 1: into rows_
  std::vector<int> rows_;            // rows of the off-diagonal block of each supernode
  std::vector<int64_t> valueStart_;  // nsuper + 1: into values_
  std::vector<double> values_;       // triangle, then L21 (below by columns), per supernode
  Eigen::Index maxUpdateRows_ = 0;   // largest off-diagonal block of a supernode
  Eigen::Index maxColumns_ = 0;      // widest supernode
  int top_ = 0;                      // see findSplit
  int split_ = 0;
};

}  // namespace stitch_detail
}  // namespace tetblend
