#include "model_join.h"

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// Row r of `part`'s model in the joined one: its surface rows from
// `surfaceStart`, its other rows from `otherStart`.
struct RowMap {
  int surfaceCount, surfaceStart, otherStart;
  int operator()(int r) const {
    return r < surfaceCount ? surfaceStart + r : otherStart + (r - surfaceCount);
  }
};

void place(const Vertices& from, const RowMap& map, Vertices& to) {
  for (Eigen::Index r = 0; r < from.rows(); ++r) to.row(map(static_cast<int>(r))) = from.row(r);
}

}  // namespace

ModelData joinedModel(const ModelPart& a, const ModelPart& b, const Triangles& inputTriangles,
                      int inputVertexCount) {
  const ModelData& ma = a.model;
  const ModelData& mb = b.model;
  if (ma.examples.size() != mb.examples.size()) {
    throw InputError("joinedModel: parts with " + std::to_string(ma.examples.size()) + " and " +
                     std::to_string(mb.examples.size()) + " examples");
  }
  const auto rowsA = static_cast<int>(ma.rest.vertices.rows());
  const auto rowsB = static_cast<int>(mb.rest.vertices.rows());
  const int surface = ma.surfaceVertexCount + mb.surfaceVertexCount;
  const RowMap mapA{ma.surfaceVertexCount, 0, surface};
  const RowMap mapB{mb.surfaceVertexCount, ma.surfaceVertexCount,
                    surface + rowsA - ma.surfaceVertexCount};
  ModelData joined;
  joined.surfaceVertexCount = surface;
  joined.surfaceTriangles = inputTriangles;
  joined.restSource = ma.restSource;
  joined.exampleSources = ma.exampleSources;
  joined.rest.vertices.resize(rowsA + rowsB, 3);
  place(ma.rest.vertices, mapA, joined.rest.vertices);
  place(mb.rest.vertices, mapB, joined.rest.vertices);
  for (std::size_t k = 0; k < ma.examples.size(); ++k) {
    Vertices example(rowsA + rowsB, 3);
    place(ma.examples[k], mapA, example);
    place(mb.examples[k], mapB, example);
    joined.examples.push_back(std::move(example));
  }
  // b's tets use a's row of an input vertex both parts have (a sheet
  // attached at a vertex stays attached); b's own copy is left in no tet.
  std::vector<int> rowOfInputInA(static_cast<std::size_t>(inputVertexCount), -1);
  for (std::size_t i = 0; i < a.inputVertices.size(); ++i) {
    rowOfInputInA[static_cast<std::size_t>(a.inputVertices[i])] =
        mapA(ma.inputVertexRows.empty() ? static_cast<int>(i) : ma.inputVertexRows[i]);
  }
  std::vector<int> tetRowB(static_cast<std::size_t>(rowsB));
  for (int r = 0; r < rowsB; ++r) tetRowB[static_cast<std::size_t>(r)] = mapB(r);
  for (std::size_t i = 0; i < b.inputVertices.size(); ++i) {
    const int shared = rowOfInputInA[static_cast<std::size_t>(b.inputVertices[i])];
    const int row = mb.inputVertexRows.empty() ? static_cast<int>(i) : mb.inputVertexRows[i];
    if (shared >= 0) tetRowB[static_cast<std::size_t>(row)] = shared;
  }
  const Eigen::Index tetsA = ma.rest.tets.rows();
  joined.rest.tets.resize(tetsA + mb.rest.tets.rows(), 4);
  for (Eigen::Index t = 0; t < joined.rest.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      joined.rest.tets(t, c) = t < tetsA
                                   ? mapA(ma.rest.tets(t, c))
                                   : tetRowB[static_cast<std::size_t>(mb.rest.tets(t - tetsA, c))];
    }
  }
  joined.excludedTets = ma.excludedTets;
  for (int t : mb.excludedTets) joined.excludedTets.push_back(static_cast<int>(tetsA) + t);
  // Per input vertex, its row: b's first, so that a's wins where both have it.
  joined.inputVertexRows.assign(static_cast<std::size_t>(inputVertexCount), -1);
  for (const auto& [part, map] : {std::pair{&b, mapB}, std::pair{&a, mapA}}) {
    const ModelData& m = part->model;
    for (std::size_t i = 0; i < part->inputVertices.size(); ++i) {
      const int row = m.inputVertexRows.empty() ? static_cast<int>(i) : m.inputVertexRows[i];
      joined.inputVertexRows[static_cast<std::size_t>(part->inputVertices[i])] = map(row);
    }
  }
  bool identity = true;
  for (std::size_t v = 0; v < joined.inputVertexRows.size(); ++v) {
    if (joined.inputVertexRows[v] < 0) {
      throw InputError("joinedModel: input vertex " + std::to_string(v) + " is in neither part");
    }
    identity = identity && joined.inputVertexRows[v] == static_cast<int>(v);
  }
  if (identity && inputVertexCount == surface) joined.inputVertexRows.clear();
  return joined;
}

}  // namespace tetblend
