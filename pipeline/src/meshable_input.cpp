#include "meshable_input.h"

namespace tetblend {
namespace {

bool repeatsAVertex(const Triangles& triangles, Eigen::Index f) {
  return triangles(f, 0) == triangles(f, 1) || triangles(f, 1) == triangles(f, 2) ||
         triangles(f, 0) == triangles(f, 2);
}

SurfaceMesh withoutFaces(const SurfaceMesh& mesh, const std::vector<int>& faces) {
  SurfaceMesh kept{mesh.vertices, Triangles(mesh.triangles.rows() - faces.size(), 3)};
  std::size_t next = 0;
  Eigen::Index row = 0;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    if (next < faces.size() && faces[next] == f) {
      ++next;
      continue;
    }
    kept.triangles.row(row++) = mesh.triangles.row(f);
  }
  return kept;
}

}  // namespace

bool hasUnmeshableParts(const SurfaceMesh& rest) {
  for (Eigen::Index f = 0; f < rest.triangles.rows(); ++f) {
    if (repeatsAVertex(rest.triangles, f)) return true;
  }
  return !unreferencedVertices(rest).empty();
}

MeshableInput meshableInput(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames) {
  MeshableInput result;
  for (Eigen::Index f = 0; f < rest.triangles.rows(); ++f) {
    if (repeatsAVertex(rest.triangles, f)) result.droppedFaces.push_back(static_cast<int>(f));
  }
  const SurfaceMesh faces = withoutFaces(rest, result.droppedFaces);
  result.loose = unreferencedVertices(faces);
  result.rest = removeVertices(faces, result.loose);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
    result.examples.push_back(
        removeVertices(withoutFaces(examples[k], result.droppedFaces), result.loose));
  }
  return result;
}

void restoreInput(ModelData& model, const SurfaceMesh& rest,
                  const std::vector<SurfaceMesh>& examples, const MeshableInput& input) {
  const std::vector<int>& loose = input.loose;
  const Eigen::Index first = model.rest.vertices.rows();
  const auto count = static_cast<Eigen::Index>(loose.size());
  const auto append = [&](Vertices& rows, const Vertices& inputRows) {
    rows.conservativeResize(first + count, 3);
    for (Eigen::Index j = 0; j < count; ++j) rows.row(first + j) = inputRows.row(loose[j]);
  };
  append(model.rest.vertices, rest.vertices);
  for (std::size_t k = 0; k < examples.size(); ++k) {
    append(model.examples[k], examples[k].vertices);
  }
  // Input vertex i: its loose row, or the row the model gave the i-th vertex
  // of the meshed surface.
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
