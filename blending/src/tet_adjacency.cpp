#include "tetblend/blending/tet_adjacency.h"

#include <algorithm>
#include <array>
#include <queue>

namespace tetblend {

TetAdjacency buildTetAdjacency(const Tets& tets) {
  // Each face as (sorted corner indices, owning tet); equal neighbours in the
  // sorted list share that face.
  struct Face {
    std::array<int, 3> corners;
    int tet;
  };
  const int count = static_cast<int>(tets.rows());
  std::vector<Face> faces;
  faces.reserve(4 * static_cast<size_t>(count));
  for (int t = 0; t < count; ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      Face face{{}, t};
      int k = 0;
      for (int c = 0; c < 4; ++c) {
        if (c != skip) face.corners[k++] = tets(t, c);
      }
      std::sort(face.corners.begin(), face.corners.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b) { return a.corners < b.corners; });
  TetAdjacency adjacency;
  adjacency.neighbours.resize(count);
  for (size_t i = 0; i + 1 < faces.size(); ++i) {
    if (faces[i].corners == faces[i + 1].corners) {
      adjacency.neighbours[faces[i].tet].push_back(faces[i + 1].tet);
      adjacency.neighbours[faces[i + 1].tet].push_back(faces[i].tet);
    }
  }
  return adjacency;
}

TetComponents tetComponents(const TetAdjacency& adjacency) {
  const int count = static_cast<int>(adjacency.neighbours.size());
  TetComponents components;
  components.label.assign(count, -1);
  std::queue<int> frontier;
  for (int seed = 0; seed < count; ++seed) {
    if (components.label[seed] >= 0) continue;
    components.label[seed] = components.count;
    frontier.push(seed);
    while (!frontier.empty()) {
      const int t = frontier.front();
      frontier.pop();
      for (int n : adjacency.neighbours[t]) {
        if (components.label[n] < 0) {
          components.label[n] = components.count;
          frontier.push(n);
        }
      }
    }
    ++components.count;
  }
  return components;
}

}  // namespace tetblend
