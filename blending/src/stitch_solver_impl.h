#pragma once
// The state of StitchSolver and StitchWorkspace (stitch_solver.h): the rest
// mesh, components, right-hand-side chunks and factor, and the right-hand-side
// assembly. Private to tetblend_blending, included only by stitch_solver.cpp.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include "ordered_parallel.h"
#include "tetblend/blending/stitch_solver.h"
#include "tetblend/core/error.h"

#ifdef TETBLEND_HAVE_CHOLMOD
#include "supernodal_factor.h"
#endif

namespace tetblend {
namespace stitch_detail {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RowMatrix3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Clock = std::chrono::steady_clock;

// Fixed number of tet chunks of the right-hand side (a constant, not the
// thread count, so the summation order never changes). Each starts at a
// multiple of kTetMapChunk, so a fused solve blends the same fixed ranges as
// TetMapBlender::blendTargets.
constexpr int kRhsChunks = 16;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Gradient coefficients g_i (Sumner–Popović): grad_j(x) = sum_i x_i g_i^T,
// with g_i = row i-1 of D_rest^-1 for i = 1..3 and g_0 = -(g_1 + g_2 + g_3).
inline Eigen::Vector3d cornerGradient(const Eigen::Matrix3d& inverseEdges, int corner) {
  if (corner == 0) return -inverseEdges.colwise().sum().transpose();
  return inverseEdges.row(corner - 1).transpose();
}

inline int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

// 6 vol_j D_rest,j^-T = cof(D_rest,j): its columns are the cross products
// e2 x e3, e3 x e1, e1 x e2 of the rest edges (D^-1 = cof(D)^T / det D and
// vol = det D / 6), so the right-hand side needs no stored inverse or volume
// per tet; the factor 1/6 is applied once per vertex.
inline Eigen::Matrix3d cofactorMatrix(const Vertices& vertices, const Eigen::RowVector4i& tet) {
  const Eigen::Vector3d p0 = vertices.row(tet(0)).transpose();
  const Eigen::Vector3d e1 = vertices.row(tet(1)).transpose() - p0;
  const Eigen::Vector3d e2 = vertices.row(tet(2)).transpose() - p0;
  const Eigen::Vector3d e3 = vertices.row(tet(3)).transpose() - p0;
  Eigen::Matrix3d columns;
  columns.col(0) = e2.cross(e3);
  columns.col(1) = e3.cross(e1);
  columns.col(2) = e1.cross(e2);
  return columns;
}

}  // namespace stitch_detail

struct StitchSolver::Impl {
  // The rest mesh (#V by 3 vertices, #T by 4 tets); per-tet rest data is
  // recomputed from it where needed rather than stored (72 + 8 bytes per tet).
  TetMesh rest;
  std::vector<int> component;      // #V labels
  std::vector<int> componentSize;  // #C vertex counts
  std::vector<int> reducedIndex;   // #V, -1 for pinned vertices (construction only)
  std::vector<int> freeVertices;   // reduced index -> vertex
  // The tets in stitch_detail::kRhsChunks contiguous ranges [chunkTet[c], chunkTet[c + 1]).
  // Chunk c sums into rows [chunkRow[c], chunkRow[c + 1]) of the summing
  // buffer, one row per distinct vertex its tets use: corner k of tet j adds
  // into row cornerRow[4 j + k], and vertex v's rows (one per chunk that
  // uses it, in chunk order) are vertexRows[vertexRowStart[v] ..
  // vertexRowStart[v + 1]). Compact whatever the vertex numbering: a range of
  // tets may use vertices from anywhere in it (surface vertices keep the
  // user's order).
  std::vector<int> chunkTet, chunkRow, cornerRow, vertexRowStart, vertexRows;
  StitchBackend backend = StitchBackend::kEigenSimplicialLdlt;
  Eigen::SimplicialLDLT<stitch_detail::SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
#ifdef TETBLEND_HAVE_CHOLMOD
  std::unique_ptr<stitch_detail::SupernodalFactor> supernodal;
  std::vector<int> factorRow;     // free vertex r -> row of the permuted system
  std::vector<int> factorVertex;  // row of the permuted system -> vertex

  void factorCholmod(stitch_detail::SparseMatrix& matrix) {
    adoptFactor(std::make_unique<stitch_detail::SupernodalFactor>(matrix));
  }
  // Keeps `factor` (of the free vertices) and the row maps of its permutation.
  void adoptFactor(std::unique_ptr<stitch_detail::SupernodalFactor> factor) {
    supernodal = std::move(factor);
    const int* perm = supernodal->perm();
    factorRow.resize(freeVertices.size());
    factorVertex.resize(freeVertices.size());
    for (size_t k = 0; k < freeVertices.size(); ++k) {
      factorRow[perm[k]] = static_cast<int>(k);
      factorVertex[k] = freeVertices[perm[k]];
    }
  }
#endif

  // Checks the rest tets (InputError), then keeps the mesh, its components
  // and the right-hand side's chunks; returns the rest data the normal
  // matrix is built from.
  RestTetData setUp(const TetMesh& mesh) {
    RestTetData data = restTetData(mesh);
    rest = mesh;
    buildComponents(static_cast<int>(mesh.vertices.rows()));
    buildChunks();
    return data;
  }
  void buildComponents(int vertexCount) {
    std::vector<int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    for (Eigen::Index j = 0; j < tets().rows(); ++j) {
      const int a = stitch_detail::findRoot(parent, tets()(j, 0));
      for (int c = 1; c < 4; ++c) {
        const int b = stitch_detail::findRoot(parent, tets()(j, c));
        if (a != b) parent[b] = a;
      }
    }
    component.assign(vertexCount, -1);
    reducedIndex.assign(vertexCount, -1);
    std::vector<int> rootLabel(vertexCount, -1);
    int count = 0;
    for (int v = 0; v < vertexCount; ++v) {
      const int root = stitch_detail::findRoot(parent, v);
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
    const auto tetCount = static_cast<int>(tets().rows());
    const auto vertexCount = static_cast<int>(rest.vertices.rows());
    const int64_t mapChunks = (tetCount + kTetMapChunk - 1) / kTetMapChunk;
    chunkTet.resize(stitch_detail::kRhsChunks + 1);
    for (int c = 0; c <= stitch_detail::kRhsChunks; ++c) {
      chunkTet[c] = std::min(
          tetCount, static_cast<int>(mapChunks * c / stitch_detail::kRhsChunks * kTetMapChunk));
    }
    // Rows in chunk order, each vertex's first use in a chunk opening a row.
    chunkRow.assign(stitch_detail::kRhsChunks + 1, 0);
    cornerRow.resize(4 * static_cast<size_t>(tetCount));
    std::vector<int> rowInChunk(vertexCount, -1), chunkOfRow(vertexCount, -1);
    std::vector<std::pair<int, int>> vertexRow;  // (vertex, row), rows ascending
    int rows = 0;
    for (int c = 0; c < stitch_detail::kRhsChunks; ++c) {
      for (int j = chunkTet[c]; j < chunkTet[c + 1]; ++j) {
        for (int k = 0; k < 4; ++k) {
          const int v = tets()(j, k);
          if (chunkOfRow[v] != c) {
            chunkOfRow[v] = c;
            rowInChunk[v] = rows++;
            vertexRow.emplace_back(v, rowInChunk[v]);
          }
          cornerRow[4 * static_cast<size_t>(j) + k] = rowInChunk[v];
        }
      }
      chunkRow[c + 1] = rows;
    }
    vertexRowStart.assign(vertexCount + 1, 0);
    for (const auto& [v, row] : vertexRow) ++vertexRowStart[v + 1];
    std::partial_sum(vertexRowStart.begin(), vertexRowStart.end(), vertexRowStart.begin());
    vertexRows.resize(vertexRow.size());
    std::vector<int> filled(vertexRowStart.begin(), vertexRowStart.end() - 1);
    for (const auto& [v, row] : vertexRow) vertexRows[filled[v]++] = row;
  }

  const Tets& tets() const { return rest.tets; }

  // rhs(r, :) = sum over the tets j of free vertex r (corner c) of
  // vol_j B_j g_c (Sumner-Popovic eq. 6's right-hand side), rows in reduced
  // order; row rowOf[r] receives free vertex r (identity when rowOf is empty).
  // Each tet is visited once: C = 6 vol_j B_j D_rest,j^-T holds 6 vol_j B_j g_c
  // for corners 1..3 in its columns, and corner 0 gets minus their sum. The
  // chunks of tets are summed in parallel, each sequentially into its own
  // rows of the buffer (buildChunks), kTetMapChunk tets at a time:
  // targets(begin, end, scratch) returns B_j for those tets (a pointer into a
  // stored field, or scratch filled by a blender). Every vertex then adds its
  // rows in chunk order, so the result does not depend on the schedule or
  // the thread count. Returns the thread-seconds spent in targets() and in
  // the whole pass.
  template <typename Targets, typename Rhs>
  std::pair<double, double> assembleRhs(const Targets& targets, const std::vector<int>& rowOf,
                                        stitch_detail::RowMatrix3& buffer, Rhs& rhs) const {
    buffer.resize(chunkRow[stitch_detail::kRhsChunks], 3);
    std::vector<double> targetSeconds(stitch_detail::kRhsChunks, 0.0),
        chunkSeconds(stitch_detail::kRhsChunks, 0.0);
    blend_detail::parallelForFirstError(stitch_detail::kRhsChunks, [&](int c) {
      const auto chunkStart = stitch_detail::Clock::now();
      buffer.middleRows(chunkRow[c], chunkRow[c + 1] - chunkRow[c]).setZero();
      std::vector<Eigen::Matrix3d> scratch(kTetMapChunk);
      for (int begin = chunkTet[c]; begin < chunkTet[c + 1]; begin += kTetMapChunk) {
        const int end = std::min(chunkTet[c + 1], begin + kTetMapChunk);
        const auto targetStart = stitch_detail::Clock::now();
        const Eigen::Matrix3d* maps = targets(begin, end, scratch.data());
        targetSeconds[c] += stitch_detail::secondsSince(targetStart);
        for (int j = begin; j < end; ++j) {
          const Eigen::Matrix3d columns =
              maps[j - begin] * stitch_detail::cofactorMatrix(rest.vertices, rest.tets.row(j));
          const int* row = cornerRow.data() + 4 * static_cast<size_t>(j);
          buffer.row(row[0]) -= columns.rowwise().sum().transpose();
          for (int corner = 1; corner < 4; ++corner) {
            buffer.row(row[corner]) += columns.col(corner - 1).transpose();
          }
        }
      }
      chunkSeconds[c] = stitch_detail::secondsSince(chunkStart);
    });
    const auto freeCount = static_cast<Eigen::Index>(freeVertices.size());
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, freeCount, 4096),
                      [&](const tbb::blocked_range<Eigen::Index>& range) {
                        for (Eigen::Index r = range.begin(); r != range.end(); ++r) {
                          const int v = freeVertices[r];
                          Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
                          for (int i = vertexRowStart[v]; i < vertexRowStart[v + 1]; ++i) {
                            sum += buffer.row(vertexRows[i]);
                          }
                          rhs.row(rowOf.empty() ? r : rowOf[r]) = sum / 6.0;
                        }
                      });
    double targetTotal = 0.0, chunkTotal = 0.0;
    for (int c = 0; c < stitch_detail::kRhsChunks; ++c) {
      targetTotal += targetSeconds[c];
      chunkTotal += chunkSeconds[c];
    }
    return {targetTotal, chunkTotal};
  }

  stitch_detail::SparseMatrix reducedNormalMatrix(const RestTetData& data) const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(10 * static_cast<size_t>(tets().rows()));
    for (Eigen::Index j = 0; j < tets().rows(); ++j) {
      Eigen::Vector3d g[4];
      for (int c = 0; c < 4; ++c) g[c] = stitch_detail::cornerGradient(data.inverseEdges[j], c);
      for (int a = 0; a < 4; ++a) {
        const int ra = reducedIndex[tets()(j, a)];
        if (ra < 0) continue;
        for (int b = 0; b < 4; ++b) {
          const int rb = reducedIndex[tets()(j, b)];
          if (rb < 0 || rb < ra) continue;  // lower triangle (row >= column) only
          triplets.emplace_back(rb, ra, data.volumes[j] * g[a].dot(g[b]));
        }
      }
    }
    const auto n = static_cast<Eigen::Index>(freeVertices.size());
    stitch_detail::SparseMatrix matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
  }

  template <typename Solver>
  void factor(Solver& solver, const stitch_detail::SparseMatrix& matrix) {
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
  stitch_detail::RowMatrix3 values;
  stitch_detail::RowMatrix3 chunkSums;  // per-chunk right-hand-side sums (see assembleRhs)
#ifdef TETBLEND_HAVE_CHOLMOD
  stitch_detail::SupernodalWorkspace workspace;
#endif
  Eigen::Matrix<double, Eigen::Dynamic, 3> solution;  // SimplicialLDLT backend only
};

}  // namespace tetblend
