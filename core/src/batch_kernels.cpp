#include "tetblend/core/batch_kernels.h"

#include <algorithm>

#include "batch_lanes.h"
#include "tetblend/core/so3.h"
#include "tetblend/core/sym3.h"

// Each block function is compiled three times (AVX-512, AVX2+FMA, baseline
// x86-64) and the loader picks the best the CPU supports (GCC function
// multi-versioning). This file is built with -fno-math-errno so that sqrt
// vectorises (CMakeLists.txt). Defining TETBLEND_BATCH_SINGLE_TARGET builds one
// version for whatever -march is given (to test a single clone). So does a
// build whose -march already has AVX2 (e.g. -march=native): there GCC would
// not inline the Eigen and helper functions, compiled for that -march, into
// the x86-64-v4 clone (their targets differ), and the block loops called them
// per lane (sym_exp and sym_log ran 23 % slower than in the default build).
// That version is compiled for the x86-64 level the -march covers
// (cmake/TetblendBatchLevel.cmake), the code of the default build's clone.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(TETBLEND_BATCH_SINGLE_TARGET) && !defined(__AVX2__)
#define TETBLEND_BATCH_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define TETBLEND_BATCH_CLONES
#endif

namespace tetblend {
namespace {

using batch_detail::Mat;
using batch_detail::Sym;

/// Elements per structure-of-arrays block: enough lanes for 8-wide vectors
/// to amortise the loop, small enough for the block to stay in L1.
constexpr int kBlock = 64;

// Blocks are structure-of-arrays: component k of lane l at [k][l], so the
// lane loops read and write unit-stride.
using Block9 = double[9][kBlock];
using Block6 = double[6][kBlock];
using Block3 = double[3][kBlock];

void loadMatrix(const Eigen::Matrix3d& a, Block9& b, int l) {
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 9
    for (int j = 0; j < 3; ++j) b[3 * i + j][l] = a(i, j);
}

void loadSym(const Eigen::Matrix3d& y, Block6& b, int l) {
  b[0][l] = y(0, 0);
  b[1][l] = y(0, 1);
  b[2][l] = y(0, 2);
  b[3][l] = y(1, 1);
  b[4][l] = y(1, 2);
  b[5][l] = y(2, 2);
}

/// Unused lanes of the last block hold the identity (all kernels accept it).
void padIdentity9(Block9& b, int from) {
  for (int l = from; l < kBlock; ++l)
#pragma GCC unroll 9
    for (int k = 0; k < 9; ++k) b[k][l] = k % 4 == 0 ? 1.0 : 0.0;
}

void padIdentity6(Block6& b, int from) {
  for (int l = from; l < kBlock; ++l)
#pragma GCC unroll 9
    for (int k = 0; k < 6; ++k) b[k][l] = (k == 0 || k == 3 || k == 5) ? 1.0 : 0.0;
}

inline Mat matAt(const Block9& b, int l) {
  Mat m;
#pragma GCC unroll 9
  for (int k = 0; k < 9; ++k) m.m[k] = b[k][l];
  return m;
}

inline void storeMat(const Mat& m, Block9& b, int l) {
#pragma GCC unroll 9
  for (int k = 0; k < 9; ++k) b[k][l] = m.m[k];
}

inline Sym symAt(const Block6& b, int l) {
  return {b[0][l], b[1][l], b[2][l], b[3][l], b[4][l], b[5][l]};
}

inline void storeSym(const Sym& s, Block6& b, int l) {
  b[0][l] = s.xx;
  b[1][l] = s.xy;
  b[2][l] = s.xz;
  b[3][l] = s.yy;
  b[4][l] = s.yz;
  b[5][l] = s.zz;
}

Eigen::Matrix3d fullSym(const Block6& b, int l) {
  Eigen::Matrix3d m;
  m << b[0][l], b[1][l], b[2][l], b[1][l], b[3][l], b[4][l], b[2][l], b[4][l], b[5][l];
  return m;
}

TETBLEND_BATCH_CLONES
void so3LogBlock(const Eigen::Matrix3d* r, Eigen::Vector3d* out, int n) {
  Block9 in;
  Block3 w;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadMatrix(r[l], in, l);
  padIdentity9(in, n);
  for (int l = 0; l < kBlock; ++l) {
    double wl[3];
    ok[l] = batch_detail::so3LogLane(matAt(in, l), wl);
#pragma GCC unroll 9
    for (int i = 0; i < 3; ++i) w[i][l] = wl[i];
  }
  for (int l = 0; l < n; ++l)
    out[l] = ok[l] ? Eigen::Vector3d(w[0][l], w[1][l], w[2][l]) : so3Log(r[l]);
}

TETBLEND_BATCH_CLONES
void symExpBlock(const Eigen::Matrix3d* y, Eigen::Matrix3d* out, int n) {
  Block6 in, res;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadSym(y[l], in, l);
  padIdentity6(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Sym s;
    ok[l] = batch_detail::symExpLane(symAt(in, l), s);
    storeSym(s, res, l);
  }
  for (int l = 0; l < n; ++l) out[l] = ok[l] ? fullSym(res, l) : symExp(y[l]);
}

TETBLEND_BATCH_CLONES
void symLogBlock(const Eigen::Matrix3d* s, Eigen::Matrix3d* out, int n) {
  Block6 in, res;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadSym(s[l], in, l);
  padIdentity6(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Sym r;
    ok[l] = batch_detail::symLogLane(symAt(in, l), r);
    storeSym(r, res, l);
  }
  for (int l = 0; l < n; ++l) out[l] = ok[l] ? fullSym(res, l) : symLog(s[l]);
}

/// Lane loop of phi's linear block so3Exp(w) symExp(y) (Kaji–Ochiai eq. (2)).
TETBLEND_LANE void rotationStretchLanes(const Block3& w, const Block6& y, Block9& res, bool* ok) {
  for (int l = 0; l < kBlock; ++l) {
    Mat rot;
    Sym st;
    const bool rotOk = batch_detail::so3ExpLane(w[0][l], w[1][l], w[2][l], rot);
    ok[l] = batch_detail::symExpLane(symAt(y, l), st) && rotOk;
    const double s[9] = {st.xx, st.xy, st.xz, st.xy, st.yy, st.yz, st.xz, st.yz, st.zz};
#pragma GCC unroll 9
    for (int i = 0; i < 3; ++i) {
#pragma GCC unroll 9
      for (int j = 0; j < 3; ++j) {
        res[3 * i + j][l] =
            rot.m[3 * i] * s[j] + rot.m[3 * i + 1] * s[3 + j] + rot.m[3 * i + 2] * s[6 + j];
      }
    }
  }
}

void padZero3(Block3& b, int from) {
  for (int l = from; l < kBlock; ++l) b[0][l] = b[1][l] = b[2][l] = 0.0;
}

Eigen::Matrix3d matrixAt(const Block9& b, int l) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = b[3 * i + j][l];
  return m;
}

TETBLEND_BATCH_CLONES
void phiBlock(const AffineParams* params, Eigen::Matrix4d* out, int n) {
  Block3 w;
  Block6 y;
  Block9 res;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) {
    for (int i = 0; i < 3; ++i) w[i][l] = params[l].rotationLog(i);
    loadSym(params[l].stretchLog, y, l);
  }
  padZero3(w, n);
  padIdentity6(y, n);
  rotationStretchLanes(w, y, res, ok);
  for (int l = 0; l < n; ++l) {
    if (!ok[l]) {
      out[l] = phi(params[l]);
      continue;
    }
    Eigen::Matrix4d& m = out[l];
    m.topLeftCorner<3, 3>() = matrixAt(res, l);
    m.topRightCorner<3, 1>() = params[l].translation;
    m.row(3) << 0.0, 0.0, 0.0, 1.0;
  }
}

TETBLEND_BATCH_CLONES
void phiLinearBlock(const double* logs, Eigen::Matrix3d* out, int n) {
  Block3 w;
  Block6 y;
  Block9 res;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) {
    const double* p = logs + 9 * l;
    for (int i = 0; i < 3; ++i) w[i][l] = p[i];
    for (int k = 0; k < 6; ++k) y[k][l] = p[3 + k];
  }
  padZero3(w, n);
  padIdentity6(y, n);
  rotationStretchLanes(w, y, res, ok);
  for (int l = 0; l < n; ++l) {
    if (ok[l]) {
      out[l] = matrixAt(res, l);
    } else {
      const double* p = logs + 9 * l;
      Eigen::Matrix3d stretch;
      stretch << p[3], p[4], p[5], p[4], p[6], p[7], p[5], p[7], p[8];
      out[l] = so3Exp(Eigen::Vector3d(p[0], p[1], p[2])) * symExp(stretch);
    }
  }
}

TETBLEND_BATCH_CLONES
void psiBlock(const Eigen::Matrix4d* a, AffineParams* out, int n) {
  Block9 in, rot;
  Block6 logS;
  Block3 w;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadMatrix(a[l].topLeftCorner<3, 3>(), in, l);
  padIdentity9(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Mat r;
    Sym ls;
    ok[l] = batch_detail::polarLogLane(matAt(in, l), r, ls);
    storeSym(ls, logS, l);
    storeMat(r, rot, l);
  }
  for (int l = 0; l < kBlock; ++l) {
    double wl[3];
    ok[l] = batch_detail::so3LogLane(matAt(rot, l), wl) && ok[l];
#pragma GCC unroll 9
    for (int i = 0; i < 3; ++i) w[i][l] = wl[i];
  }
  for (int l = 0; l < n; ++l) {
    out[l] = ok[l] ? AffineParams{a[l].topRightCorner<3, 1>(),
                                  Eigen::Vector3d(w[0][l], w[1][l], w[2][l]), fullSym(logS, l)}
                   : psi(a[l]);
  }
}

TETBLEND_BATCH_CLONES
void polarLogBlock(const Eigen::Matrix3d* a, PolarLogDecomposition* out, int n) {
  Block9 in, rot;
  Block6 logS;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadMatrix(a[l], in, l);
  padIdentity9(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Mat r;
    Sym ls;
    ok[l] = batch_detail::polarLogLane(matAt(in, l), r, ls);
    storeSym(ls, logS, l);
    storeMat(r, rot, l);
  }
  for (int l = 0; l < n; ++l) {
    out[l] =
        ok[l] ? PolarLogDecomposition{matrixAt(rot, l), fullSym(logS, l)} : polarDecomposeLog(a[l]);
  }
}

TETBLEND_BATCH_CLONES
void polarRotationBlock(const Eigen::Matrix3d* a, Eigen::Matrix3d* out, int n) {
  Block9 in, rot;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l) loadMatrix(a[l], in, l);
  padIdentity9(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Mat r;
    double v[3][3], sigma[3];
    ok[l] = batch_detail::polarSvdLane(matAt(in, l), v, sigma, r);
    storeMat(r, rot, l);
  }
  for (int l = 0; l < n; ++l) out[l] = ok[l] ? matrixAt(rot, l) : polarDecompose(a[l]).rotation;
}

/// Runs `block` on consecutive blocks of kBlock elements.
TETBLEND_BATCH_CLONES
void so3ExpBlock(const Eigen::Vector3d* omega, Eigen::Matrix3d* out, int n) {
  Block3 in;
  Block9 res;
  bool ok[kBlock];
  for (int l = 0; l < n; ++l)
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) in[i][l] = omega[l](i);
  padZero3(in, n);
  for (int l = 0; l < kBlock; ++l) {
    Mat r;
    ok[l] = batch_detail::so3ExpLane(in[0][l], in[1][l], in[2][l], r);
    storeMat(r, res, l);
  }
  for (int l = 0; l < n; ++l) out[l] = ok[l] ? matrixAt(res, l) : so3Exp(omega[l]);
}

template <typename In, typename Out, typename Block>
void forEachBlock(const In* in, Out* out, std::size_t n, Block block) {
  for (std::size_t start = 0; start < n; start += kBlock) {
    block(in + start, out + start, static_cast<int>(std::min<std::size_t>(kBlock, n - start)));
  }
}

}  // namespace

void so3ExpBatch(const Eigen::Vector3d* omega, Eigen::Matrix3d* out, std::size_t n) {
  forEachBlock(omega, out, n, so3ExpBlock);
}

void so3LogBatch(const Eigen::Matrix3d* rotations, Eigen::Vector3d* out, std::size_t n) {
  forEachBlock(rotations, out, n, so3LogBlock);
}

void symExpBatch(const Eigen::Matrix3d* y, Eigen::Matrix3d* out, std::size_t n) {
  forEachBlock(y, out, n, symExpBlock);
}

void symLogBatch(const Eigen::Matrix3d* s, Eigen::Matrix3d* out, std::size_t n) {
  forEachBlock(s, out, n, symLogBlock);
}

void phiBatch(const AffineParams* params, Eigen::Matrix4d* out, std::size_t n) {
  forEachBlock(params, out, n, phiBlock);
}

void psiBatch(const Eigen::Matrix4d* a, AffineParams* out, std::size_t n) {
  forEachBlock(a, out, n, psiBlock);
}

void phiLinearBatch(const double* logs, Eigen::Matrix3d* out, std::size_t n) {
  for (std::size_t start = 0; start < n; start += kBlock) {
    phiLinearBlock(logs + 9 * start, out + start,
                   static_cast<int>(std::min<std::size_t>(kBlock, n - start)));
  }
}

void polarDecomposeLogBatch(const Eigen::Matrix3d* a, PolarLogDecomposition* out, std::size_t n) {
  forEachBlock(a, out, n, polarLogBlock);
}

void polarRotationBatch(const Eigen::Matrix3d* a, Eigen::Matrix3d* out, std::size_t n) {
  forEachBlock(a, out, n, polarRotationBlock);
}

}  // namespace tetblend
