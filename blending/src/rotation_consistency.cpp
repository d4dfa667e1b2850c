#include "tetblend/blending/rotation_consistency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <queue>

#include "tetblend/core/so3.h"

namespace tetblend {

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
  std::vector<char> visited(count, 0);
  std::queue<int> frontier;
  for (int s : seed) {
    visited[s] = 1;
    frontier.push(s);
    while (!frontier.empty()) {
      const int t = frontier.front();
      frontier.pop();
      for (int n : adjacency.neighbours[t]) {
        if (visited[n]) continue;
        visited[n] = 1;
        logs[n] = so3LogClosest(rotations[n], logs[t]);
        frontier.push(n);
      }
    }
  }
  return logs;
}

}  // namespace tetblend
