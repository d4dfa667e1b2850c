#include "supernodal_kernels.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>

namespace tetblend {
namespace stitch_detail {
namespace {

// out[d] = sum_i p[i] u_d[i] for i in [0, n), d = x, y, z, two rows per step
// (SSE2 lanes) with the odd row last.
inline void dot3(const double* __restrict p, const double* __restrict ux,
                 const double* __restrict uy, const double* __restrict uz, int n, double out[3]) {
  using Lanes = Eigen::Array2d;
  Lanes sx = Lanes::Zero(), sy = Lanes::Zero(), sz = Lanes::Zero();
  int i = 0;
  for (; i + 2 <= n; i += 2) {
    const Lanes l = Lanes::Map(p + i);
    sx += l * Lanes::Map(ux + i);
    sy += l * Lanes::Map(uy + i);
    sz += l * Lanes::Map(uz + i);
  }
  out[0] = sx.sum();
  out[1] = sy.sum();
  out[2] = sz.sum();
  if (i < n) {
    out[0] += p[i] * ux[i];
    out[1] += p[i] * uy[i];
    out[2] += p[i] * uz[i];
  }
}

// Column c of a packed triangle as an array indexed by row: column(c)[r] =
// L(r, c) for r in [c, columns).
inline const double* triangleColumn(const double* triangle, int c, int columns) {
  return triangle + triangleOffset(c, columns) - c;
}

// t[r] -= sum_c L(r, c) t[c] for rows [r0, r1) and columns [c0, c1) of a packed
// triangle (r0 >= c1), x, y and z as separate arrays, four columns at a time.
void triangleUpdateRows(const double* triangle, int columns, int c0, int c1, int r0, int r1,
                        double* __restrict tx, double* __restrict ty, double* __restrict tz) {
  int c = c0;
  for (; c + 4 <= c1; c += 4) {
    const double* __restrict p0 = triangleColumn(triangle, c, columns);
    const double* __restrict p1 = triangleColumn(triangle, c + 1, columns);
    const double* __restrict p2 = triangleColumn(triangle, c + 2, columns);
    const double* __restrict p3 = triangleColumn(triangle, c + 3, columns);
    const double x0 = tx[c], x1 = tx[c + 1], x2 = tx[c + 2], x3 = tx[c + 3];
    const double y0 = ty[c], y1 = ty[c + 1], y2 = ty[c + 2], y3 = ty[c + 3];
    const double z0 = tz[c], z1 = tz[c + 1], z2 = tz[c + 2], z3 = tz[c + 3];
    for (int r = r0; r < r1; ++r) {
      tx[r] -= p0[r] * x0 + p1[r] * x1 + p2[r] * x2 + p3[r] * x3;
      ty[r] -= p0[r] * y0 + p1[r] * y1 + p2[r] * y2 + p3[r] * y3;
      tz[r] -= p0[r] * z0 + p1[r] * z1 + p2[r] * z2 + p3[r] * z3;
    }
  }
  for (; c < c1; ++c) {
    const double* __restrict p0 = triangleColumn(triangle, c, columns);
    const double x0 = tx[c], y0 = ty[c], z0 = tz[c];
    for (int r = r0; r < r1; ++r) {
      tx[r] -= p0[r] * x0;
      ty[r] -= p0[r] * y0;
      tz[r] -= p0[r] * z0;
    }
  }
}

// t[c] -= sum_{r >= r0} L(r, c) t[r] for columns [c0, c1) of a packed triangle
// (r0 >= c1).
void triangleSubtractDots(const double* triangle, int columns, int c0, int c1, int r0, double* tx,
                          double* ty, double* tz) {
  for (int c = c0; c < c1; ++c) {
    double sum[3];
    dot3(triangleColumn(triangle, c, columns) + r0, tx + r0, ty + r0, tz + r0, columns - r0, sum);
    tx[c] -= sum[0];
    ty[c] -= sum[1];
    tz[c] -= sum[2];
  }
}

// Width of the column panels of a large triangle solved on two threads.
constexpr int kTrianglePanel = 128;
// Triangles with at least this many columns are solved by panels on two
// threads when the caller allows it (the sequential top of the tree).
constexpr int kParallelTriangleColumns = 512;

}  // namespace

// u[i0, i1) += L21[i0, i1) X for the `columns` columns of a supernode's
// off-diagonal block (below by columns, column-major) and its solved rows X
// (x, y, z interleaved), four columns at a time so u is read and written once
// per four entries; x, y and z of u are separate arrays, so the row loop
// vectorises.
void addProduct(const double* block, int below, const double* x, int columns, int i0, int i1,
                double* __restrict ux, double* __restrict uy, double* __restrict uz) {
  int c = 0;
  for (; c + 4 <= columns; c += 4) {
    const double* __restrict p0 = block + static_cast<int64_t>(c) * below;
    const double* __restrict p1 = p0 + below;
    const double* __restrict p2 = p1 + below;
    const double* __restrict p3 = p2 + below;
    const double* a = x + 3 * c;
    const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], a4 = a[4], a5 = a[5];
    const double a6 = a[6], a7 = a[7], a8 = a[8], a9 = a[9], a10 = a[10], a11 = a[11];
    for (int i = i0; i < i1; ++i) {
      ux[i] += p0[i] * a0 + p1[i] * a3 + p2[i] * a6 + p3[i] * a9;
      uy[i] += p0[i] * a1 + p1[i] * a4 + p2[i] * a7 + p3[i] * a10;
      uz[i] += p0[i] * a2 + p1[i] * a5 + p2[i] * a8 + p3[i] * a11;
    }
  }
  for (; c < columns; ++c) {
    const double* __restrict p0 = block + static_cast<int64_t>(c) * below;
    const double a0 = x[3 * c], a1 = x[3 * c + 1], a2 = x[3 * c + 2];
    for (int i = i0; i < i1; ++i) {
      ux[i] += p0[i] * a0;
      uy[i] += p0[i] * a1;
      uz[i] += p0[i] * a2;
    }
  }
}

// x[c] -= L21(:, c)^T u for columns [c0, c1) of a supernode's off-diagonal
// block (below by columns, column-major).
void subtractDots(const double* block, int below, double* x, int c0, int c1, const double* ux,
                  const double* uy, const double* uz) {
  for (int c = c0; c < c1; ++c) {
    double sum[3];
    dot3(block + static_cast<int64_t>(c) * below, ux, uy, uz, below, sum);
    x[3 * c] -= sum[0];
    x[3 * c + 1] -= sum[1];
    x[3 * c + 2] -= sum[2];
  }
}

// The diagonal block's triangle (packed by columns) on a supernode's rows,
// x, y and z as separate arrays tx, ty, tz of `columns` entries.
// Forward: L11 t = t by columns (axpy form). With `parallel`, a large
// triangle goes by panels of kTrianglePanel columns: each panel's own
// triangle in sequence, then its update of the rows below split between two
// threads (rows are independent).
void triangleForward(const double* triangle, int columns, double* __restrict tx,
                     double* __restrict ty, double* __restrict tz, bool parallel) {
  const int panel =
      parallel && columns >= kParallelTriangleColumns ? kTrianglePanel : std::max(columns, 1);
  for (int c0 = 0; c0 < columns; c0 += panel) {
    const int c1 = std::min(c0 + panel, columns);
    for (int c = c0; c < c1; ++c) {
      const double* __restrict column = triangle + triangleOffset(c, columns);
      const double inverse = 1.0 / column[0];
      const double a0 = tx[c] *= inverse, a1 = ty[c] *= inverse, a2 = tz[c] *= inverse;
      for (int i = 1; i < c1 - c; ++i) {
        tx[c + i] -= column[i] * a0;
        ty[c + i] -= column[i] * a1;
        tz[c + i] -= column[i] * a2;
      }
    }
    if (c1 == columns) break;
    const int half = c1 + (columns - c1) / 2;
    tbb::parallel_invoke(
        [&] { triangleUpdateRows(triangle, columns, c0, c1, c1, half, tx, ty, tz); },
        [&] { triangleUpdateRows(triangle, columns, c0, c1, half, columns, tx, ty, tz); });
  }
}

// Backward: L11^T t = t, last column first (dot form); with `parallel`, by
// panels from the last: the panel's dot products with the rows below it
// split between two threads by columns, then its own triangle.
void triangleBackward(const double* triangle, int columns, double* tx, double* ty, double* tz,
                      bool parallel) {
  const int panel =
      parallel && columns >= kParallelTriangleColumns ? kTrianglePanel : std::max(columns, 1);
  for (int c1 = columns; c1 > 0;) {
    const int c0 = std::max(c1 - panel, 0);
    if (c1 < columns) {
      const int half = c0 + (c1 - c0) / 2;
      tbb::parallel_invoke(
          [&] { triangleSubtractDots(triangle, columns, c0, half, c1, tx, ty, tz); },
          [&] { triangleSubtractDots(triangle, columns, half, c1, c1, tx, ty, tz); });
    }
    for (int c = c1 - 1; c >= c0; --c) {
      const double* column = triangle + triangleOffset(c, columns);
      double sum[3];
      dot3(column + 1, tx + c + 1, ty + c + 1, tz + c + 1, c1 - c - 1, sum);
      const double inverse = 1.0 / column[0];
      tx[c] = (tx[c] - sum[0]) * inverse;
      ty[c] = (ty[c] - sum[1]) * inverse;
      tz[c] = (tz[c] - sum[2]) * inverse;
    }
    c1 = c0;
  }
}

// Copies a supernode's `columns` rows of x (x, y, z interleaved) to the
// separate arrays t (leading dimension ld), or back.
void toColumns(const double* x, int columns, double* t, Eigen::Index ld) {
  for (int c = 0; c < columns; ++c) {
    t[c] = x[3 * c];
    t[ld + c] = x[3 * c + 1];
    t[2 * ld + c] = x[3 * c + 2];
  }
}
void fromColumns(const double* t, Eigen::Index ld, int columns, double* x) {
  for (int c = 0; c < columns; ++c) {
    x[3 * c] = t[c];
    x[3 * c + 1] = t[ld + c];
    x[3 * c + 2] = t[2 * ld + c];
  }
}

}  // namespace stitch_detail
}  // namespace tetblend
