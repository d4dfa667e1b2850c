#include "tetblend/blending/rotation_consistency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <queue>

#include "tetblend/core/so3.h"

namespace tetblend {
namespace {

// Largest distance (radians) between a tet's logarithm and the one that
// continuity from its neighbour predicts for the two to count as the same
// branch. Neighbouring tets of a smooth deformation differ by a small
// fraction of a radian; the logarithms of one rotation, (theta + 2 pi k) a,
// are 2 pi apart. pi/2 separates the two cases with margin on both sides.
constexpr double kBranchJump = 0.5 * 3.14159265358979323846;

}  // namespace

std::vector<Eigen::Vector3d> rotationLogs(const std::vector<Eigen::Matrix3d>& rotations,
                                          const TetAdjacency& adjacency,
                                          const TetComponents& components, bool consistent) {
  const int count = static_cast<int>(rotations.size());
  std::vector<Eigen::Vector3d> logs(count);
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 4096),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int j = range.begin(); j != range.end(); ++j) {
                        logs[j] = so3Log(rotations[j]);
                      }
                    });
  if (!consistent) return logs;
  std::vector<int> seed(components.count, -1);
  for (int j = 0; j < count; ++j) {
    int& s = seed[components.label[j]];
    if (s < 0 || logs[j].norm() < logs[s].norm()) s = j;
  }
  // ref[t]: the logarithm that continuity predicts for tet t. A tet whose
  // rotation has a logarithm within kBranchJump of its prediction snaps the
  // prediction to it; one without (e.g. R = I + tilt inside a 2 pi twist,
  // whose logarithms all lie along the tilt axis) keeps its closest
  // logarithm but passes the prediction on, so one such tet cannot drop the
  // turns of everything reached through it.
  std::vector<Eigen::Vector3d> ref(count);
  std::vector<char> visited(count, 0);
  std::queue<int> frontier;
  for (int s : seed) {
    visited[s] = 1;
    ref[s] = logs[s];
    frontier.push(s);
    while (!frontier.empty()) {
      const int t = frontier.front();
      frontier.pop();
      for (int n : adjacency.neighbours[t]) {
        if (visited[n]) continue;
        visited[n] = 1;
        // Predicted log: the parent's plus the (small) relative rotation.
        ref[n] = ref[t] + so3Log(rotations[t].transpose() * rotations[n]);
        logs[n] = so3LogClosest(rotations[n], ref[n]);
        if ((logs[n] - ref[n]).norm() <= kBranchJump) ref[n] = logs[n];
        frontier.push(n);
      }
    }
  }
  return logs;
}

}  // namespace tetblend
