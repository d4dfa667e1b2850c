// VertexBlockAmdOrdering (meshing/src/vertex_block_ordering.h) on the 3 by 3
// block matrix of a cube grid's vertex graph: a permutation that keeps each
// vertex's coordinates together, a factorisation that solves the system, and
// as little fill as Eigen's AMD on the scalar matrix.

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

#include <Eigen/SparseCholesky>

#include "test_seed.h"
#include "vertex_block_ordering.h"

namespace tetblend {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

constexpr int kSide = 7;  // grid vertices per side

int gridVertex(int i, int j, int k) { return (i * kSide + j) * kSide + k; }

// L ⊗ M + I (lower triangle): L the Laplacian of the grid's vertices joined
// to their 26 neighbours (a tet mesh's vertex graph is as dense), M a random
// symmetric positive definite 3 by 3 matrix, so every block is full.
SparseMatrix blockMatrix(std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::Matrix3d a;
  for (int e = 0; e < 9; ++e) a.data()[e] = uniform(random);
  const Eigen::Matrix3d m = a * a.transpose() + Eigen::Matrix3d::Identity();
  std::vector<Eigen::Triplet<double>> entries;
  auto addBlock = [&](int row, int column, double scale) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        if (3 * row + r >= 3 * column + c) {
          entries.emplace_back(3 * row + r, 3 * column + c,
                               scale * m(r, c) + (row == column && r == c ? 1.0 : 0.0));
        }
      }
    }
  };
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      for (int k = 0; k < kSide; ++k) {
        int degree = 0;
        for (int di = -1; di <= 1; ++di) {
          for (int dj = -1; dj <= 1; ++dj) {
            for (int dk = -1; dk <= 1; ++dk) {
              const int ni = i + di, nj = j + dj, nk = k + dk;
              if ((di == 0 && dj == 0 && dk == 0) || ni < 0 || nj < 0 || nk < 0 || ni >= kSide ||
                  nj >= kSide || nk >= kSide) {
                continue;
              }
              ++degree;
              if (gridVertex(ni, nj, nk) > gridVertex(i, j, k)) {
                addBlock(gridVertex(ni, nj, nk), gridVertex(i, j, k), -1.0);
              }
            }
          }
        }
        addBlock(gridVertex(i, j, k), gridVertex(i, j, k), degree);
      }
    }
  }
  const int size = 3 * kSide * kSide * kSide;
  SparseMatrix lower(size, size);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

TEST(VertexBlockOrdering, KeepsEachVertexTogetherAndFillsAsLittleAsScalarAmd) {
  std::mt19937 random(test_seed::seedOfCurrentTest(20261203u));
  const SparseMatrix lower = blockMatrix(random);
  const SparseMatrix full = lower.selfadjointView<Eigen::Lower>();

  VertexBlockAmdOrdering::Permutation order;
  VertexBlockAmdOrdering{}(full, order);
  ASSERT_EQ(order.size(), full.cols());
  const std::set<int> distinct(order.indices().data(), order.indices().data() + order.size());
  EXPECT_EQ(distinct.size(), static_cast<std::size_t>(full.cols()));
  EXPECT_EQ(*distinct.begin(), 0);
  EXPECT_EQ(*distinct.rbegin(), full.cols() - 1);
  for (Eigen::Index v = 0; v < full.cols() / 3; ++v) {
    EXPECT_EQ(order.indices()[3 * v] % 3, 0) << "vertex " << v;
    EXPECT_EQ(order.indices()[3 * v + 1], order.indices()[3 * v] + 1) << "vertex " << v;
    EXPECT_EQ(order.indices()[3 * v + 2], order.indices()[3 * v] + 2) << "vertex " << v;
  }

  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, VertexBlockAmdOrdering> blocked(lower);
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> scalar(lower);
  ASSERT_EQ(blocked.info(), Eigen::Success);
  ASSERT_EQ(scalar.info(), Eigen::Success);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.rows(), -1.0, 2.0);
  const Eigen::VectorXd x = blocked.solve(b);
  // The spectrum lies in [1, 1 + 52 ‖M‖] (a Laplacian of degree at most 26
  // has eigenvalues in [0, 52]; ‖M‖ <= ‖A‖_F² + 1 <= 10): a condition
  // number below 1e3, so 1e-12 is rounding.
  EXPECT_LT((full * x - b).norm(), 1e-12 * b.norm());
  // AMD is a heuristic: the two orders break ties differently. On the
  // Newton matrices of bench_meshing's 10 k elbow they gave the same fill.
  const auto blockedFill = blocked.matrixL().nestedExpression().nonZeros();
  const auto scalarFill = scalar.matrixL().nestedExpression().nonZeros();
  std::cout << "  nonzeros of L: block order " << blockedFill << ", scalar AMD " << scalarFill
            << "\n";
  EXPECT_LE(blockedFill, 1.1 * static_cast<double>(scalarFill));
}

}  // namespace
}  // namespace tetblend
