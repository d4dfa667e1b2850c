#include "model_join.h"

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// Row r of a part's model in the joined one: its surface rows from
// `surfaceStart`, its other rows from `otherStart`.
struct RowMap {
  int surfaceCount = 0, surfaceStart = 0, otherStart = 0;
  int operator()(int r) const {
    return r < surfaceCount ? surfaceStart + r : otherStart + (r - surfaceCount);
  }
};

void place(const Vertices& from, const RowMap& map, Vertices& to) {
  for (Eigen::Index r = 0; r < from.rows(); ++r) to.row(map(static_cast<int>(r))) = from.row(r);
}

// Row of the part's i-th input vertex in its own model.
int ownRow(const ModelData& m, std::size_t i) {
  return m.inputVertexRows.empty() ? static_cast<int>(i) : m.inputVertexRows[i];
}

}  // namespace

ModelData joinedModel(const std::vector<ModelPart>& parts, const Triangles& inputTriangles,
                      int inputVertexCount) {
  if (parts.empty()) throw InputError("joinedModel: no parts");
  const std::size_t exampleCount = parts.front().model.examples.size();
  int surface = 0, rows = 0;
  Eigen::Index tets = 0;
  for (const ModelPart& part : parts) {
    if (part.model.examples.size() != exampleCount) {
      throw InputError("joinedModel: parts with " + std::to_string(exampleCount) + " and " +
                       std::to_string(part.model.examples.size()) + " examples");
    }
    surface += part.model.surfaceVertexCount;
    rows += static_cast<int>(part.model.rest.vertices.rows());
    tets += part.model.rest.tets.rows();
  }
  std::vector<RowMap> maps;
  int surfaceStart = 0, otherStart = surface;
  for (const ModelPart& part : parts) {
    const ModelData& m = part.model;
    maps.push_back({m.surfaceVertexCount, surfaceStart, otherStart});
    surfaceStart += m.surfaceVertexCount;
    otherStart += static_cast<int>(m.rest.vertices.rows()) - m.surfaceVertexCount;
  }
  ModelData joined;
  joined.surfaceVertexCount = surface;
  joined.surfaceTriangles = inputTriangles;
  joined.restSource = parts.front().model.restSource;
  joined.exampleSources = parts.front().model.exampleSources;
  joined.rest.vertices.resize(rows, 3);
  joined.examples.assign(exampleCount, Vertices(rows, 3));
  joined.rest.tets.resize(tets, 4);
  joined.inputVertexRows.assign(static_cast<std::size_t>(inputVertexCount), -1);
  Eigen::Index nextTet = 0;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const ModelData& m = parts[p].model;
    const RowMap& map = maps[p];
    place(m.rest.vertices, map, joined.rest.vertices);
    for (std::size_t k = 0; k < exampleCount; ++k) place(m.examples[k], map, joined.examples[k]);
    // The part's rows in its tets: an input vertex an earlier part has
    // takes that part's row.
    std::vector<int> tetRow(static_cast<std::size_t>(m.rest.vertices.rows()));
    for (std::size_t r = 0; r < tetRow.size(); ++r) tetRow[r] = map(static_cast<int>(r));
    const std::vector<int>& inputs = parts[p].inputVertices;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const int earlier = joined.inputVertexRows[static_cast<std::size_t>(inputs[i])];
      if (earlier >= 0) tetRow[static_cast<std::size_t>(ownRow(m, i))] = earlier;
    }
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      int& row = joined.inputVertexRows[static_cast<std::size_t>(inputs[i])];
      if (row < 0) row = tetRow[static_cast<std::size_t>(ownRow(m, i))];
    }
    for (int t : m.excludedTets) joined.excludedTets.push_back(static_cast<int>(nextTet) + t);
    for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t, ++nextTet) {
      for (int c = 0; c < 4; ++c) {
        joined.rest.tets(nextTet, c) = tetRow[static_cast<std::size_t>(m.rest.tets(t, c))];
      }
    }
  }
  bool identity = true;
  for (std::size_t v = 0; v < joined.inputVertexRows.size(); ++v) {
    if (joined.inputVertexRows[v] < 0) {
      throw InputError("joinedModel: input vertex " + std::to_string(v) + " is in no part");
    }
    identity = identity && joined.inputVertexRows[v] == static_cast<int>(v);
  }
  if (identity && inputVertexCount == surface) joined.inputVertexRows.clear();
  return joined;
}

}  // namespace tetblend
