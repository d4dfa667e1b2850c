#pragma once
// Optional nonlinear stitch: starting from the linear stitch's result, remove
// inverted tets while staying close to the blended maps. Minimises, with
// Ceres (sparse normal Cholesky, analytic per-tet Jacobians),
//     sum_j vol_j ||grad_j(x) - B_j||_F^2
//   + mu sum_j vol_j max(0, minDeterminant - det grad_j(x))^2,
// the linear stitch energy plus a one-sided quadratic penalty on det F below
// a small positive threshold, raising mu until no tet is inverted.

#include <Eigen/Core>
#include <vector>

#include "tetblend/blending/stitch_solver.h"

namespace tetblend {

/// Options of the nonlinear stitch, with their defaults.
struct NonlinearStitchOptions {
  /// det F (the volume ratio, dimensionless) below which the penalty acts.
  double minDeterminant = 0.05;
  /// Penalty weight mu of the first round (dimensionless: it multiplies a
  /// squared volume ratio against a squared gradient error).
  double initialPenalty = 10.0;
  /// Factor by which mu grows from one round to the next.
  double penaltyGrowth = 10.0;
  /// Rounds at most; stops early once no tet is inverted.
  int maxRounds = 4;
  /// Levenberg–Marquardt iterations per round at most.
  int maxIterations = 50;
  /// Threads of Ceres' Jacobian evaluation and linear solver.
  int threads = 2;
};

/// What the nonlinear stitch did.
struct NonlinearStitchReport {
  int invertedBefore = 0;     ///< tets with det F <= 0 in the input
  int invertedAfter = 0;      ///< ... in the output
  double energyBefore = 0.0;  ///< stitch energy sum vol ||F - B||^2 of the input
  double energyAfter = 0.0;   ///< ... of the output (without the penalty)
  int rounds = 0;             ///< penalty rounds run
  int iterations = 0;         ///< Ceres iterations over all rounds
};

/// Runs the nonlinear stitch from `initial` (#V by 3, typically
/// solver.solve(targets, centroids)) for `targets` (#T maps) and places every
/// component's vertex centroid at the row of `centroids` (#C by 3), as the
/// linear stitch does (an input without inverted tets is returned as it
/// is). Returns the new positions and fills `report` if not null. Throws
/// InputError on size mismatches.
Vertices nonlinearStitch(const StitchSolver& solver, const std::vector<Eigen::Matrix3d>& targets,
                         const Vertices& initial, const Centroids& centroids,
                         const NonlinearStitchOptions& options = {},
                         NonlinearStitchReport* report = nullptr);

/// Number of tets of `solver`'s mesh with det grad_j(x) <= 0.
int countInvertedTets(const StitchSolver& solver, const Vertices& x);

}  // namespace tetblend
