#include "meshable_input.h"

#include <algorithm>
#include <iterator>
#include <numeric>

namespace tetblend {
namespace {

bool repeatsAVertex(const Triangles& triangles, Eigen::Index f) {
  return triangles(f, 0) == triangles(f, 1) || triangles(f, 1) == triangles(f, 2) ||
         triangles(f, 0) == triangles(f, 2);
}

// Whether vertices a and b are at one position in every one of `surfaces`.
bool coincide(const std::vector<const Vertices*>& surfaces, int a, int b) {
  return std::all_of(surfaces.begin(), surfaces.end(),
                     [&](const Vertices* v) { return v->row(a) == v->row(b); });
}

// Per vertex, the smallest vertex joined to it by edges of zero length in
// every one of `surfaces` (itself if none).
std::vector<int> mergedEnds(const Triangles& triangles,
                            const std::vector<const Vertices*>& surfaces) {
  std::vector<int> parent(static_cast<std::size_t>(surfaces.front()->rows()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      v = parent[static_cast<std::size_t>(v)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
    }
    return v;
  };
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int a = triangles(f, c), b = triangles(f, (c + 1) % 3);
      if (a == b || !coincide(surfaces, a, b)) continue;
      const int ra = find(a), rb = find(b);
      parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
  }
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = find(static_cast<int>(v));
  return parent;
}

SurfaceMesh renumbered(const SurfaceMesh& mesh, const std::vector<int>& copyOf) {
  SurfaceMesh result = mesh;
  for (Eigen::Index i = 0; i < result.triangles.size(); ++i) {
    result.triangles.data()[i] = copyOf[static_cast<std::size_t>(result.triangles.data()[i])];
  }
  return result;
}

bool hasZeroLengthEdge(const SurfaceMesh& rest) {
  for (Eigen::Index f = 0; f < rest.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int a = rest.triangles(f, c), b = rest.triangles(f, (c + 1) % 3);
      if (a != b && rest.vertices.row(a) == rest.vertices.row(b)) return true;
    }
  }
  return false;
}

}  // namespace

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

bool hasUnmeshableParts(const SurfaceMesh& rest) {
  for (Eigen::Index f = 0; f < rest.triangles.rows(); ++f) {
    if (repeatsAVertex(rest.triangles, f)) return true;
  }
  return hasZeroLengthEdge(rest) || !unreferencedVertices(rest).empty();
}

MeshableInput meshableInput(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames) {
  MeshableInput result;
  std::vector<const Vertices*> surfaces{&rest.vertices};
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
    surfaces.push_back(&examples[k].vertices);
  }
  result.copyOf = mergedEnds(rest.triangles, surfaces);
  for (std::size_t v = 0; v < result.copyOf.size(); ++v) {
    if (result.copyOf[v] != static_cast<int>(v)) result.copies.push_back(static_cast<int>(v));
  }
  const SurfaceMesh merged = renumbered(rest, result.copyOf);
  for (Eigen::Index f = 0; f < merged.triangles.rows(); ++f) {
    if (repeatsAVertex(merged.triangles, f)) result.droppedFaces.push_back(static_cast<int>(f));
  }
  const SurfaceMesh faces = withoutFaces(merged, result.droppedFaces);
  std::vector<int> unused = unreferencedVertices(faces);
  std::set_difference(unused.begin(), unused.end(), result.copies.begin(), result.copies.end(),
                      std::back_inserter(result.loose));
  result.rest = removeVertices(faces, unused);
  for (const SurfaceMesh& example : examples) {
    const SurfaceMesh exampleFaces{example.vertices, faces.triangles};
    result.examples.push_back(removeVertices(exampleFaces, unused));
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
  // Input vertex i: its loose row, the row of the vertex it is a copy of
  // (always a smaller one), or the row the model gave the next vertex of
  // the meshed surface.
  std::vector<int> rows;
  rows.reserve(static_cast<std::size_t>(rest.vertices.rows()));
  std::size_t nextLoose = 0;
  int kept = 0;
  for (Eigen::Index i = 0; i < rest.vertices.rows(); ++i) {
    const int original = input.copyOf[static_cast<std::size_t>(i)];
    if (nextLoose < loose.size() && loose[nextLoose] == i) {
      rows.push_back(static_cast<int>(first + static_cast<Eigen::Index>(nextLoose++)));
    } else if (original != i) {
      rows.push_back(rows[static_cast<std::size_t>(original)]);
    } else {
      rows.push_back(model.inputVertexRows.empty() ? kept : model.inputVertexRows[kept]);
      ++kept;
    }
  }
  model.inputVertexRows = std::move(rows);
  model.surfaceTriangles = rest.triangles;
}

}  // namespace tetblend
