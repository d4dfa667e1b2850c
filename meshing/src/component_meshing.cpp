#include "tetblend/meshing/component_meshing.h"

#include <string>

#include "half_edge_table.h"
#include "tetblend/core/error.h"

namespace tetblend {

SurfacePart surfacePart(const SurfaceMesh& surface, const std::vector<int>& faceComponent,
                        int component) {
  std::vector<int> partRow(static_cast<std::size_t>(surface.vertices.rows()), -1);
  std::vector<Eigen::Index> faces;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    if (faceComponent[static_cast<std::size_t>(f)] != component) continue;
    faces.push_back(f);
    for (int c = 0; c < 3; ++c) partRow[static_cast<std::size_t>(surface.triangles(f, c))] = 0;
  }
  SurfacePart part;
  for (int v = 0; v < static_cast<int>(partRow.size()); ++v) {
    if (partRow[static_cast<std::size_t>(v)] < 0) continue;
    partRow[static_cast<std::size_t>(v)] = static_cast<int>(part.vertexRows.size());
    part.vertexRows.push_back(v);
  }
  part.surface.vertices.resize(static_cast<Eigen::Index>(part.vertexRows.size()), 3);
  for (std::size_t i = 0; i < part.vertexRows.size(); ++i) {
    part.surface.vertices.row(static_cast<Eigen::Index>(i)) =
        surface.vertices.row(part.vertexRows[i]);
  }
  part.surface.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      part.surface.triangles(static_cast<Eigen::Index>(i), c) =
          partRow[static_cast<std::size_t>(surface.triangles(faces[i], c))];
    }
  }
  return part;
}

int manifoldRegions(const Triangles& triangles, std::vector<int>& faceRegion, int* splitEdges) {
  const auto faceCount = static_cast<std::size_t>(triangles.rows());
  const std::vector<char> skip = detail::repeatedIndexFaces(triangles);
  const detail::HalfEdgeTable table = detail::buildHalfEdgeTable(triangles, skip);
  detail::UnionFind regions(faceCount);
  if (splitEdges != nullptr) *splitEdges = 0;
  for (const auto& [begin, end] : table.edges) {
    if (end - begin > 2 && splitEdges != nullptr) ++*splitEdges;
    if (end - begin == 2) {
      regions.unite(static_cast<std::size_t>(table.halfEdges[begin].face),
                    static_cast<std::size_t>(table.halfEdges[begin + 1].face));
    }
  }
  std::vector<int> regionOfRoot(faceCount, -1);
  faceRegion.assign(faceCount, -1);
  int count = 0;
  for (std::size_t f = 0; f < faceCount; ++f) {
    if (skip[f]) continue;
    int& region = regionOfRoot[regions.find(f)];
    if (region < 0) region = count++;
    faceRegion[f] = region;
  }
  return count;
}

TetMesh tetrahedralizeEachComponent(const SurfaceMesh& surface,
                                    const std::vector<int>& faceComponent, int componentCount,
                                    const TetGenOptions& options) {
  if (faceComponent.size() != static_cast<std::size_t>(surface.triangles.rows())) {
    throw InputError("tetrahedralizeEachComponent: " + std::to_string(faceComponent.size()) +
                     " labels for " + std::to_string(surface.triangles.rows()) + " faces");
  }
  const Eigen::Index surfaceCount = surface.vertices.rows();
  std::vector<TetMesh> meshes;
  std::vector<std::vector<int>> rows;
  Eigen::Index vertexCount = surfaceCount, tetCount = 0;
  for (int component = 0; component < componentCount; ++component) {
    SurfacePart part = surfacePart(surface, faceComponent, component);
    if (part.surface.triangles.rows() == 0) continue;
    int firstFace = 0;
    while (faceComponent[static_cast<std::size_t>(firstFace)] != component) ++firstFace;
    try {
      meshes.push_back(tetrahedralize(part.surface, options));
    } catch (const InputError& error) {
      throw InputError(std::string(error.what()) + " (in its closed component of face " +
                       std::to_string(firstFace) +
                       ", meshed on its own: the numbers count that component's own faces and "
                       "vertices)");
    }
    vertexCount += meshes.back().vertices.rows() - part.surface.vertices.rows();
    tetCount += meshes.back().tets.rows();
    rows.push_back(std::move(part.vertexRows));
  }
  TetMesh joined;
  joined.vertices.resize(vertexCount, 3);
  joined.vertices.topRows(surfaceCount) = surface.vertices;
  joined.tets.resize(tetCount, 4);
  Eigen::Index nextVertex = surfaceCount, nextTet = 0;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const TetMesh& mesh = meshes[m];
    const auto partCount = static_cast<Eigen::Index>(rows[m].size());
    const Eigen::Index steiner = mesh.vertices.rows() - partCount;
    joined.vertices.middleRows(nextVertex, steiner) = mesh.vertices.bottomRows(steiner);
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
      for (int c = 0; c < 4; ++c) {
        const int v = mesh.tets(t, c);
        joined.tets(nextTet, c) = v < partCount ? rows[m][static_cast<std::size_t>(v)]
                                                : static_cast<int>(nextVertex + v - partCount);
      }
      ++nextTet;
    }
    nextVertex += steiner;
  }
  return joined;
}

}  // namespace tetblend
