#include "tetblend/blending/tet_adjacency.h"

#include <algorithm>
#include <array>
#include <queue>
#include <utility>

namespace tetblend {
namespace {

// Links each tet that has no face neighbour to every tet it shares an edge
// with (both directions, no duplicates).
void linkFacelessTetsThroughEdges(const Tets& tets, TetAdjacency& adjacency) {
  const int count = static_cast<int>(tets.rows());
  std::vector<char> faceless(static_cast<size_t>(count), 0);
  bool any = false;
  for (int t = 0; t < count; ++t) {
    faceless[static_cast<size_t>(t)] = adjacency.neighbours[static_cast<size_t>(t)].empty();
    any = any || faceless[static_cast<size_t>(t)];
  }
  if (!any) return;
  std::vector<std::pair<std::array<int, 2>, int>> edges;  // (sorted corners, tet)
  edges.reserve(6 * static_cast<size_t>(count));
  for (int t = 0; t < count; ++t) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        edges.push_back({{std::min(tets(t, a), tets(t, b)), std::max(tets(t, a), tets(t, b))}, t});
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    for (size_t p = i; p < j; ++p) {
      for (size_t q = i; q < j; ++q) {
        const int from = edges[p].second;
        const int to = edges[q].second;
        if (from == to ||
            (!faceless[static_cast<size_t>(from)] && !faceless[static_cast<size_t>(to)])) {
          continue;
        }
        std::vector<int>& list = adjacency.neighbours[static_cast<size_t>(from)];
        if (std::find(list.begin(), list.end(), to) == list.end()) list.push_back(to);
      }
    }
    i = j;
  }
}

}  // namespace

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
  linkFacelessTetsThroughEdges(tets, adjacency);
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
