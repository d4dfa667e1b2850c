#include "local_arap.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#ifdef TETBLEND_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

// Tets per TBB task of the local step (about 1 µs of work each).
constexpr std::size_t kGrain = 2048;

// The region's stiffness is factored supernodally where CHOLMOD is there:
// Eigen's simplicial LDLᵀ took 314 ms on bench_meshing's 1 M elbow's region
// (10 842 vertices), where the whole local search now takes 268 ms.
#ifdef TETBLEND_HAVE_CHOLMOD
using RegionSolver = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>;
#else
using RegionSolver = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
#endif

// The region's tets: those with a free corner, ascending.
std::vector<int> regionTets(const VertexStars& stars, const std::vector<int>& region) {
  std::vector<int> result;
  for (int v : region) {
    const auto begin = stars.tets.begin() + stars.start[static_cast<std::size_t>(v)];
    const auto end = stars.tets.begin() + stars.start[static_cast<std::size_t>(v) + 1];
    result.insert(result.end(), begin, end);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

}  // namespace

int localArap(const Tets& tets, const std::vector<TetElement>& elements, const VertexStars& stars,
              const std::vector<int>& region, const LocalArapStops& stops, Vertices& positions) {
  if (region.empty()) return 0;
  const auto n = static_cast<Eigen::Index>(region.size());
  std::vector<int> local(static_cast<std::size_t>(positions.rows()), -1);
  for (Eigen::Index i = 0; i < n; ++i) {
    local[static_cast<std::size_t>(region[i])] = static_cast<int>(i);
  }
  const std::vector<int> touched = regionTets(stars, region);

  // K_RR = Σ_t vol_t G_tᵀ G_t over the free vertices, and −K_RF x_F, the
  // fixed vertices' share of the global step's right-hand side.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd fixedShare = Eigen::MatrixXd::Zero(n, 3);
  for (int t : touched) {
    const TetElement& element = elements[static_cast<std::size_t>(t)];
    for (int a = 0; a < 4; ++a) {
      const int i = local[static_cast<std::size_t>(tets(t, a))];
      if (i < 0) continue;
      for (int b = 0; b < 4; ++b) {
        const double k = element.volume * element.gradients.col(a).dot(element.gradients.col(b));
        const int j = local[static_cast<std::size_t>(tets(t, b))];
        if (j >= 0) {
          entries.emplace_back(i, j, k);
        } else {
          fixedShare.row(i) -= k * positions.row(tets(t, b));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> stiffness(n, n);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  RegionSolver solver;
  solver.compute(stiffness);
  if (solver.info() != Eigen::Success) return 0;

  std::vector<Eigen::Matrix3d> rotations(touched.size());
  std::vector<double> energies(touched.size());
  std::vector<char> inverted(touched.size());
  // The local step over the region's tets: their rotations, then their
  // inverted count and ARAP energy Σ vol ‖F − R‖², summed in tet order.
  auto localStep = [&](const Vertices& x) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, touched.size(), kGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::vector<Eigen::Matrix3d> f(range.size());
                        for (std::size_t k = range.begin(); k != range.end(); ++k) {
                          const int t = touched[k];
                          f[k - range.begin()] = deformationGradient(
                              x, tets.row(t), elements[static_cast<std::size_t>(t)]);
                        }
                        closestRotations(f.data(), rotations.data() + range.begin(), f.size());
                        for (std::size_t k = range.begin(); k != range.end(); ++k) {
                          const int t = touched[k];
                          energies[k] = elements[static_cast<std::size_t>(t)].volume *
                                        (f[k - range.begin()] - rotations[k]).squaredNorm();
                          inverted[k] = tetSignedVolume(x, tets.row(t)) > 0.0 ? 0 : 1;
                        }
                      });
    return std::pair{static_cast<std::size_t>(std::count(inverted.begin(), inverted.end(), 1)),
                     std::accumulate(energies.begin(), energies.end(), 0.0)};
  };
  // Only the region moves: `positions` is the current state, `best` keeps
  // the region's rows of the best one.
  std::pair<std::size_t, double> key = localStep(positions);
  Eigen::MatrixXd best(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) best.row(i) = positions.row(region[i]);
  std::pair<std::size_t, double> bestKey = key;
  int iterations = 0;
  for (; iterations < stops.maxIterations && !(stops.stopWhenValid && bestKey.first == 0);
       ++iterations) {
    Eigen::MatrixXd rhs = fixedShare;
    for (std::size_t k = 0; k < touched.size(); ++k) {
      const int t = touched[k];
      const TetElement& element = elements[static_cast<std::size_t>(t)];
      for (int a = 0; a < 4; ++a) {
        const int i = local[static_cast<std::size_t>(tets(t, a))];
        if (i >= 0) {
          rhs.row(i) += element.volume * (rotations[k] * element.gradients.col(a)).transpose();
        }
      }
    }
    const Eigen::MatrixXd moved = solver.solve(rhs);
    double largestMove = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      largestMove = std::max(largestMove, (moved.row(i) - positions.row(region[i])).norm());
      positions.row(region[i]) = moved.row(i);
    }
    const double previousEnergy = key.second;
    key = localStep(positions);
    if (key < bestKey) {
      best = moved;
      bestKey = key;
    }
    if (largestMove <= stops.tolerance || key.second > (1.0 - stops.stallFall) * previousEnergy) {
      ++iterations;
      break;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) positions.row(region[i]) = best.row(i);
  return iterations;
}

}  // namespace tetblend
