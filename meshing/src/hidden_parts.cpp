#include "hidden_parts.h"

#include <algorithm>
#include <cstddef>
#include <map>

namespace tetblend {
namespace {

// A hidden part is placed as this fraction of its rest size about its
// point: its faces keep 1e-4 of their rest area, well above collapsedFaces'
// threshold (1e-12 of the squared diagonal) on meshes whose faces are not
// themselves nearly collapsed. Where they would be, the stand-in still
// collapses faces and the caller treats the example as self-intersecting.
constexpr double kHiddenPartScale = 1e-2;

}  // namespace

Vertices hiddenPartsStandIn(const Vertices& rest, const Vertices& example,
                            const Triangles& triangles, const std::vector<int>& faceComponent,
                            const std::vector<int>& collapsed) {
  // Per component: its faces minus its collapsed faces (0: hidden).
  std::map<int, int> visibleFaces;
  for (int component : faceComponent) ++visibleFaces[component];
  for (int f : collapsed) --visibleFaces[faceComponent[static_cast<std::size_t>(f)]];
  std::map<int, std::vector<int>> hidden;  // component: its surface vertices
  for (const auto& [component, visible] : visibleFaces) {
    if (visible == 0) hidden[component];
  }
  if (hidden.empty()) return example;
  for (std::size_t f = 0; f < faceComponent.size(); ++f) {
    const auto part = hidden.find(faceComponent[f]);
    if (part == hidden.end()) continue;
    for (int c = 0; c < 3; ++c) part->second.push_back(triangles(static_cast<Eigen::Index>(f), c));
  }
  Vertices standIn = example;
  for (auto& [component, vertices] : hidden) {
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    const Vertices restPart = rest(vertices, Eigen::all);
    const Eigen::RowVector3d restCentre = restPart.colwise().mean();
    const Eigen::RowVector3d point = example(vertices, Eigen::all).colwise().mean();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      standIn.row(vertices[i]) =
          point + kHiddenPartScale * (restPart.row(static_cast<Eigen::Index>(i)) - restCentre);
    }
  }
  return standIn;
}

}  // namespace tetblend
