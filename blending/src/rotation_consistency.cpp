#include "tetblend/blending/rotation_consistency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <queue>

#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

// Snap rule. The prediction for tet n is ref_t + delta, delta =
// log(R_n R_t^T) the (world-frame) relative rotation: the first-order
// continuation ref_t + J_l^-1(ref_t) delta with J_l^-1 replaced by I. That is
// exact for steps along ref_t (a pure twist) and off by
// |J_l^-1 - I| |delta_perp| otherwise, without bound as |ref_t| nears 2 pi k
// (the exponential is singular there). The logarithm closest to the
// prediction (Kaji–Ochiai Alg. 1) is taken while it is within
// kSnapRatio |delta| + kSnapFloor of it. Beyond, the logarithm's axis swings
// faster than the rotation turns (R = R_z(theta) R_tilt near theta = 2 pi:
// the continued logarithm swings from the twist axis to the tilt axis), and
// following it would blend into a rotation about the swung axis: the tet
// keeps the prediction as base and the rest as correction. Known cost: for
// |ref_t| above ~1.9 rad, steps across the axis also un-snap (|J_l^-1 - I|
// exceeds 1 there), so such tets are lifted rather than plain Kaji–Ochiai.
constexpr double kSnapRatio = 1.0;
// Absolute part of the snap tolerance (radians): round-off of so3Log on
// rotation vectors up to ~30 rad, far below any real step between tets.
constexpr double kSnapFloor = 1e-9;

}  // namespace

std::vector<RotationLift> rotationLifts(const std::vector<Eigen::Matrix3d>& rotations,
                                        const TetAdjacency& adjacency,
                                        const TetComponents& components, bool consistent) {
  const int count = static_cast<int>(rotations.size());
  std::vector<RotationLift> lifts(count);
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 4096),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int j = range.begin(); j != range.end(); ++j) {
                        lifts[j].base = so3Log(rotations[j]);
                      }
                    });
  if (!consistent) return lifts;
  std::vector<int> seed(components.count, -1);
  for (int j = 0; j < count; ++j) {
    int& s = seed[components.label[j]];
    if (s < 0 || lifts[j].base.norm() < lifts[s].base.norm()) s = j;
  }
  // ref[t]: the rotation vector that continuity predicts for tet t, summed
  // along the breadth-first tree and snapped to the exact logarithm wherever
  // one is on the same branch (so errors of the first-order sum do not build
  // up there).
  std::vector<Eigen::Vector3d> ref(count);
  std::vector<char> visited(count, 0);
  std::queue<int> frontier;
  for (int s : seed) {
    visited[s] = 1;
    ref[s] = lifts[s].base;
    frontier.push(s);
    while (!frontier.empty()) {
      const int t = frontier.front();
      frontier.pop();
      for (int n : adjacency.neighbours[t]) {
        if (visited[n]) continue;
        visited[n] = 1;
        const Eigen::Vector3d delta = so3Log(rotations[n] * rotations[t].transpose());
        const Eigen::Vector3d prediction = ref[t] + delta;
        const Eigen::Vector3d closest = so3LogClosest(rotations[n], prediction);
        if ((closest - prediction).norm() <= kSnapRatio * delta.norm() + kSnapFloor) {
          lifts[n] = {closest, Eigen::Vector3d::Zero()};
          ref[n] = closest;
        } else {
          lifts[n] = {prediction, so3Log(so3Exp(prediction).transpose() * rotations[n])};
          ref[n] = prediction;
        }
        frontier.push(n);
      }
    }
  }
  return lifts;
}

std::vector<Eigen::Vector3d> rotationLogs(const std::vector<Eigen::Matrix3d>& rotations,
                                          const TetAdjacency& adjacency,
                                          const TetComponents& components, bool consistent) {
  const std::vector<RotationLift> lifts =
      rotationLifts(rotations, adjacency, components, consistent);
  std::vector<Eigen::Vector3d> logs(lifts.size());
  for (size_t j = 0; j < lifts.size(); ++j) logs[j] = lifts[j].base + lifts[j].correction;
  return logs;
}

}  // namespace tetblend
