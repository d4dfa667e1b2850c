#include "loose_vertices.h"

namespace tetblend {

WithoutLooseVertices withoutLooseVertices(const SurfaceMesh& rest,
                                          const std::vector<SurfaceMesh>& examples,
                                          const std::vector<std::string>& exampleNames) {
  WithoutLooseVertices result;
  result.loose = unreferencedVertices(rest);
  result.rest = removeVertices(rest, result.loose);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
    result.examples.push_back(removeVertices(examples[k], result.loose));
  }
  return result;
}

void keepLooseVertices(ModelData& model, const SurfaceMesh& rest,
                       const std::vector<SurfaceMesh>& examples, const std::vector<int>& loose) {
  const Eigen::Index first = model.rest.vertices.rows();
  const auto count = static_cast<Eigen::Index>(loose.size());
  const auto append = [&](Vertices& rows, const Vertices& input) {
    rows.conservativeResize(first + count, 3);
    for (Eigen::Index j = 0; j < count; ++j) rows.row(first + j) = input.row(loose[j]);
  };
  append(model.rest.vertices, rest.vertices);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    append(model.examples[k], examples[k].vertices);
  }
  // Input vertex i: its loose row, or the row the model gave the i-th vertex
  // of the surface without loose vertices.
  std::vector<int> rows;
  rows.reserve(static_cast<std::size_t>(rest.vertices.rows()));
  std::size_t nextLoose = 0;
  int kept = 0;
  for (Eigen::Index i = 0; i < rest.vertices.rows(); ++i) {
    if (nextLoose < loose.size() && loose[nextLoose] == i) {
      rows.push_back(static_cast<int>(first + static_cast<Eigen::Index>(nextLoose++)));
    } else {
      rows.push_back(model.inputVertexRows.empty() ? kept : model.inputVertexRows[kept]);
      ++kept;
    }
  }
  model.inputVertexRows = std::move(rows);
  model.surfaceTriangles = rest.triangles;
}

}  // namespace tetblend
