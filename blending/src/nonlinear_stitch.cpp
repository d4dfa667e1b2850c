#include "tetblend/blending/nonlinear_stitch.h"

#include <ceres/ceres.h>

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// Residuals of one tet: sqrt(vol) (F - B) (9, row-major) and
// sqrt(mu vol) max(0, t - det F) (1). Parameters: its 4 corners (3 each).
class TetCost final : public ceres::SizedCostFunction<10, 3, 3, 3, 3> {
 public:
  TetCost(const Eigen::Matrix3d& inverseEdges, double volume, const Eigen::Matrix3d& target,
          double penalty, double threshold)
      : target_(target),
        sqrtVolume_(std::sqrt(volume)),
        sqrtPenalty_(std::sqrt(penalty * volume)),
        threshold_(threshold) {
    // grad(x) = sum_i x_i g_i^T (stitch_solver.cpp).
    g_[0] = -inverseEdges.colwise().sum().transpose();
    for (int i = 1; i < 4; ++i) g_[i] = inverseEdges.row(i - 1).transpose();
  }

  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    Eigen::Matrix3d f = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 4; ++i) f += Eigen::Map<const Eigen::Vector3d>(x[i]) * g_[i].transpose();
    for (int c = 0; c < 3; ++c) {
      for (int d = 0; d < 3; ++d) residuals[3 * c + d] = sqrtVolume_ * (f(c, d) - target_(c, d));
    }
    const double gap = threshold_ - f.determinant();
    const bool active = gap > 0.0;
    residuals[9] = active ? sqrtPenalty_ * gap : 0.0;
    if (jacobians == nullptr) return true;
    // d det F / d F = cofactor(F) = det(F) F^-T, written without the inverse.
    Eigen::Matrix3d cofactor;
    cofactor.col(0) = f.col(1).cross(f.col(2));
    cofactor.col(1) = f.col(2).cross(f.col(0));
    cofactor.col(2) = f.col(0).cross(f.col(1));
    for (int i = 0; i < 4; ++i) {
      if (jacobians[i] == nullptr) continue;
      Eigen::Map<Eigen::Matrix<double, 10, 3, Eigen::RowMajor>> j(jacobians[i]);
      j.setZero();
      // dF(c, d) / dx_i(c) = g_i(d).
      for (int c = 0; c < 3; ++c) {
        for (int d = 0; d < 3; ++d) j(3 * c + d, c) = sqrtVolume_ * g_[i](d);
      }
      if (active) j.row(9) = -sqrtPenalty_ * (cofactor * g_[i]).transpose();
    }
    return true;
  }

 private:
  Eigen::Matrix3d target_;
  Eigen::Vector3d g_[4];
  double sqrtVolume_;
  double sqrtPenalty_;
  double threshold_;
};

}  // namespace

int countInvertedTets(const StitchSolver& solver, const Vertices& x) {
  int count = 0;
  for (int j = 0; j < solver.tetCount(); ++j) count += solver.gradient(x, j).determinant() <= 0.0;
  return count;
}

Vertices nonlinearStitch(const StitchSolver& solver, const std::vector<Eigen::Matrix3d>& targets,
                         const Vertices& initial, const Centroids& centroids,
                         const NonlinearStitchOptions& options, NonlinearStitchReport* report) {
  if (static_cast<int>(targets.size()) != solver.tetCount() ||
      initial.rows() != solver.vertexCount() || centroids.rows() != solver.componentCount()) {
    std::ostringstream message;
    message << "nonlinear stitch: " << targets.size() << " targets, " << initial.rows()
            << " vertices and " << centroids.rows() << " centroids for a mesh with "
            << solver.tetCount() << " tets, " << solver.vertexCount() << " vertices and "
            << solver.componentCount() << " components";
    throw InputError(message.str());
  }
  NonlinearStitchReport local;
  local.invertedBefore = countInvertedTets(solver, initial);
  local.energyBefore = solver.energy(initial, targets);
  Vertices x = initial;
  const Tets& tets = solver.tets();
  const RestTetData& rest = solver.restData();
  double penalty = options.initialPenalty;
  local.invertedAfter = local.invertedBefore;
  for (int round = 0; round < options.maxRounds && local.invertedAfter > 0; ++round) {
    ceres::Problem problem;
    for (int j = 0; j < solver.tetCount(); ++j) {
      problem.AddResidualBlock(new TetCost(rest.inverseEdges[j], rest.volumes[j], targets[j],
                                           penalty, options.minDeterminant),
                               nullptr, x.row(tets(j, 0)).data(), x.row(tets(j, 1)).data(),
                               x.row(tets(j, 2)).data(), x.row(tets(j, 3)).data());
    }
    // The energy is translation invariant: hold each component's first
    // vertex (the linear stitch's pinned vertex) fixed.
    std::vector<char> pinned(solver.componentCount(), 0);
    for (int v = 0; v < solver.vertexCount(); ++v) {
      const int c = solver.vertexComponent()[v];
      if (pinned[c]) continue;
      pinned[c] = 1;
      if (problem.HasParameterBlock(x.row(v).data()))
        problem.SetParameterBlockConstant(x.row(v).data());
    }
    ceres::Solver::Options ceresOptions;
    ceresOptions.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    ceresOptions.max_num_iterations = options.maxIterations;
    ceresOptions.num_threads = options.threads;
    ceresOptions.logging_type = ceres::SILENT;
    ceresOptions.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(ceresOptions, &problem, &summary);
    local.iterations += static_cast<int>(summary.iterations.size());
    ++local.rounds;
    local.invertedAfter = countInvertedTets(solver, x);
    penalty *= options.penaltyGrowth;
  }
  if (local.rounds > 0) {
    const Centroids shift = centroids - solver.componentCentroids(x);
    for (int v = 0; v < solver.vertexCount(); ++v) {
      x.row(v) += shift.row(solver.vertexComponent()[v]);
    }
  }
  local.energyAfter = solver.energy(x, targets);
  if (report != nullptr) *report = local;
  return x;
}

}  // namespace tetblend
