#include "rigid_simplices_outside.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "surface_interior.h"

namespace tetblend {
namespace {

// The solids an example's surface bounds, one per tet component that has a
// rigid simplex, all made up front so that the tests can share them
// across threads.
class ComponentInteriors {
 public:
  ComponentInteriors(const Vertices& example, const Triangles& triangles,
                     const std::vector<int>& faceComponent, const std::vector<int>& components) {
    for (int component : components) {
      std::vector<Eigen::Index> rows;
      for (std::size_t f = 0; f < faceComponent.size(); ++f) {
        if (faceComponent[f] == component) rows.push_back(static_cast<Eigen::Index>(f));
      }
      interiors_[component] =
          std::make_unique<SurfaceInterior>(example, triangles(rows, Eigen::all));
    }
  }

  const SurfaceInterior& of(int component) const { return *interiors_.at(component); }

 private:
  std::map<int, std::unique_ptr<SurfaceInterior>> interiors_;
};

// Rigid simplices tested per TBB task: each test is a few microseconds (a
// box query and a ray shot), 484 of them per example at bench_meshing's
// 10 k row.
constexpr std::size_t kRigidGrain = 32;

}  // namespace

std::vector<Simplex> rigidSimplicesOutside(const std::vector<Simplex>& rigid,
                                           const Vertices& example, const Triangles& triangles,
                                           const std::vector<int>& vertexComponent,
                                           const std::vector<int>& faceComponent) {
  std::vector<int> components;
  for (const Simplex& simplex : rigid) {
    components.push_back(vertexComponent[static_cast<std::size_t>(simplex.vertices[0])]);
  }
  std::sort(components.begin(), components.end());
  components.erase(std::unique(components.begin(), components.end()), components.end());
  const ComponentInteriors interiors(example, triangles, faceComponent, components);
  std::vector<Simplex> split(rigid.size());
  std::vector<char> outside(rigid.size(), 0);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rigid.size(), kRigidGrain),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const Simplex& simplex = rigid[i];
          const auto& v = simplex.vertices;
          const SurfaceInterior& interior =
              interiors.of(vertexComponent[static_cast<std::size_t>(v[0])]);
          if (simplex.count == 2) {
            outside[i] = !interior.segmentInside(v[0], v[1]);
            split[i] = simplex;
            continue;
          }
          if (interior.triangleInside(v[0], v[1], v[2])) continue;
          Simplex through = simplex;
          for (const auto& [a, b] : {std::pair{v[0], v[1]}, {v[1], v[2]}, {v[0], v[2]}}) {
            Simplex edge;
            edge.vertices = {a, b, 0};
            edge.count = 2;
            if (std::binary_search(rigid.begin(), rigid.end(), edge)) through = edge;
          }
          outside[i] = 1;
          split[i] = through;
        }
      });
  std::vector<Simplex> result;
  for (std::size_t i = 0; i < rigid.size(); ++i) {
    if (outside[i]) result.push_back(split[i]);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

}  // namespace tetblend
