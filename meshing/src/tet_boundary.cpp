#include "tetblend/meshing/tet_boundary.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// The four faces of a positively oriented tet (a, b, c, d), each ordered so
// that its normal points away from the opposite corner.
constexpr std::array<std::array<int, 3>, 4> kOutwardFaces = {
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

}  // namespace

SurfaceMesh boundarySurface(const TetMesh& mesh) {
  // (sorted corners, tet, local face) for every face; equal keys are adjacent
  // after sorting.
  struct Face {
    std::array<int, 3> key;
    std::array<int, 3> oriented;
  };
  std::vector<Face> faces;
  faces.reserve(static_cast<size_t>(mesh.tets.rows()) * 4);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (const auto& local : kOutwardFaces) {
      Face face;
      for (int k = 0; k < 3; ++k) face.oriented[k] = mesh.tets(t, local[k]);
      face.key = face.oriented;
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  std::vector<std::array<int, 3>> boundary;
  for (size_t i = 0; i < faces.size();) {
    size_t j = i;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i > 2) {
      throw InputError("boundarySurface: face (" + std::to_string(faces[i].key[0]) + ", " +
                       std::to_string(faces[i].key[1]) + ", " + std::to_string(faces[i].key[2]) +
                       ") is shared by " + std::to_string(j - i) +
                       " tets; a tet mesh needs at most 2 (non-manifold or duplicated tets)");
    }
    if (j - i == 1) boundary.push_back(faces[i].oriented);
    i = j;
  }
  SurfaceMesh surface;
  surface.vertices = mesh.vertices;
  surface.triangles.resize(static_cast<Eigen::Index>(boundary.size()), 3);
  for (size_t f = 0; f < boundary.size(); ++f) {
    for (int k = 0; k < 3; ++k) surface.triangles(static_cast<Eigen::Index>(f), k) = boundary[f][k];
  }
  return surface;
}

BoundaryFirstMesh reorderBoundaryFirst(const TetMesh& mesh) {
  const SurfaceMesh surface = boundarySurface(mesh);
  const Eigen::Index vertexCount = mesh.vertices.rows();
  std::vector<char> onBoundary(static_cast<size_t>(vertexCount), 0);
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) onBoundary[static_cast<size_t>(surface.triangles(f, k))] = 1;
  }
  BoundaryFirstMesh result;
  result.newToOld.reserve(static_cast<size_t>(vertexCount));
  for (int pass = 1; pass >= 0; --pass) {
    for (int v = 0; v < static_cast<int>(vertexCount); ++v) {
      if (onBoundary[static_cast<size_t>(v)] == pass) result.newToOld.push_back(v);
    }
    if (pass == 1) result.boundaryVertexCount = static_cast<int>(result.newToOld.size());
  }
  result.oldToNew.assign(static_cast<size_t>(vertexCount), 0);
  for (size_t i = 0; i < result.newToOld.size(); ++i) {
    result.oldToNew[static_cast<size_t>(result.newToOld[i])] = static_cast<int>(i);
  }
  result.mesh.vertices.resize(vertexCount, 3);
  for (Eigen::Index v = 0; v < vertexCount; ++v) {
    result.mesh.vertices.row(v) = mesh.vertices.row(result.newToOld[static_cast<size_t>(v)]);
  }
  result.mesh.tets = mesh.tets;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int k = 0; k < 4; ++k) {
      result.mesh.tets(t, k) = result.oldToNew[static_cast<size_t>(mesh.tets(t, k))];
    }
  }
  return result;
}

}  // namespace tetblend
