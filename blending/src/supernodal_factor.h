#pragma once
// The stitch's supernodal Cholesky factor (private to tetblend_blending):
// CHOLMOD analyses and factors G^T W G once (supernodal LL^T, CHOLMOD's
// default ordering strategy: AMD, and METIS too when AMD's fill is high,
// keeping the sparser factor); the three-column solves are done here from the
// factor's dense supernode blocks, reading L only. CHOLMOD's own solve goes
// through the BLAS, whose narrow three-column kernels (ATLAS here) were the
// bottleneck, and writes its cholmod_common, so concurrent solves would race.
// Only compiled with TETBLEND_HAVE_CHOLMOD.

#include <cholmod.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace tetblend {
namespace stitch_detail {

/// #rows by 3, one row of x, y, z per unknown.
using RowMatrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Scratch of one solve (one per concurrent caller).
struct SupernodalWorkspace {
  RowMatrix3 update[2];  ///< one supernode's L21 * X, per half of the tree
  RowMatrix3 shared[2];  ///< each half's forward updates of the top rows
};

/// LL^T = P A P^T of a symmetric positive definite matrix.
class SupernodalFactor {
 public:
  /// Factors `lower` (n by n, lower triangle stored, compressed). Throws
  /// NumericalError when A is not positive definite.
  explicit SupernodalFactor(Eigen::SparseMatrix<double>& lower);
  ~SupernodalFactor();
  SupernodalFactor(const SupernodalFactor&) = delete;
  SupernodalFactor& operator=(const SupernodalFactor&) = delete;

  /// P as CHOLMOD's Perm: row k of the permuted system is unknown perm()[k].
  const int* perm() const { return static_cast<const int*>(factor_->Perm); }
  /// Stored entries of L.
  double nonzeros() const { return static_cast<double>(factor_->xsize); }

  /// Solves L L^T y = b in place on `y` (n by 3, permuted order, b on entry).
  /// Const and thread-safe given distinct `y` and `workspace`.
  void solve(RowMatrix3& y, SupernodalWorkspace& workspace) const;

 private:
  void forward(int begin, int end, double* yv, double* u, int sharedRow, double* shared) const;
  void backward(int begin, int end, double* yv, double* u) const;
  void findSplit();

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  Eigen::Index maxUpdateRows_ = 0;  // largest off-diagonal block of a supernode
  int top_ = 0;                     // see findSplit
  int low_ = 0;
  int split_ = 0;
};

}  // namespace stitch_detail
}  // namespace tetblend
