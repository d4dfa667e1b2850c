#pragma once
// Dense kernels of the supernodal triangular solves (private to
// tetblend_blending, used by supernodal_factor.cpp): a supernode's packed
// lower triangle (column c holds rows c..columns-1) and its off-diagonal
// block L21 (below by columns, column-major), applied to three right-hand
// sides x, y, z. Kernels marked "SoA" take x, y and z as three separate
// arrays, so their row loops vectorise.

#include <Eigen/Core>
#include <cstdint>

namespace tetblend {
namespace stitch_detail {

// Entries before column c in the packed lower triangle of a block of
// `columns` columns (column c holds rows c..columns-1).
inline int64_t triangleOffset(int c, int columns) {
  return static_cast<int64_t>(c) * columns - static_cast<int64_t>(c) * (c - 1) / 2;
}

inline int64_t triangleSize(int columns) { return triangleOffset(columns, columns); }

/// u[i0, i1) += L21[i0, i1) X for a supernode's `columns` columns; X is the
/// supernode's solved rows (x, y, z interleaved), u SoA (ux, uy, uz).
void addProduct(const double* block, int below, const double* x, int columns, int i0, int i1,
                double* ux, double* uy, double* uz);

/// x[c] -= L21(:, c)^T u for columns [c0, c1); x interleaved, u SoA.
void subtractDots(const double* block, int below, double* x, int c0, int c1, const double* ux,
                  const double* uy, const double* uz);

/// Forward solve L11 t = t with the packed triangle (t SoA, `columns`
/// entries each). With `parallel`, triangles of at least 512 columns go by
/// 128-column panels whose updates of the rows below run on two threads.
void triangleForward(const double* triangle, int columns, double* tx, double* ty, double* tz,
                     bool parallel);

/// Backward solve L11^T t = t with the packed triangle (t SoA); `parallel`
/// as for triangleForward (the panels' dot products split by columns).
void triangleBackward(const double* triangle, int columns, double* tx, double* ty, double* tz,
                      bool parallel);

/// Copies a supernode's `columns` rows of x (x, y, z interleaved) to the SoA
/// arrays t (leading dimension ld), or back.
void toColumns(const double* x, int columns, double* t, Eigen::Index ld);
void fromColumns(const double* t, Eigen::Index ld, int columns, double* x);

}  // namespace stitch_detail
}  // namespace tetblend
