#include "tetblend/meshing/tet_boundary.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
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

// The faces used by exactly one tet among those whose corners all lie below
// `cornerLimit`, oriented outwards, in ascending order of their sorted
// corners. Corners must be in [0, #V).
Triangles facesUsedOnce(const Tets& tets, Eigen::Index cornerLimit) {
  // (sorted corners, outward corners) for every face, grouped by the
  // smallest corner (a counting sort over the vertices) and sorted within
  // each group: equal keys are adjacent, in ascending order. Linear but for
  // the small groups' sorts (about 20 faces each): a sort of all 4 #T faces
  // was 3 % of a 100 k-tet preparation's profile, called 3 times.
  struct Face {
    std::array<int, 3> key;
    std::array<int, 3> oriented;
  };
  auto faceOf = [&](Eigen::Index t, const std::array<int, 3>& local) {
    Face face;
    for (int k = 0; k < 3; ++k) face.oriented[k] = tets(t, local[k]);
    face.key = face.oriented;
    std::sort(face.key.begin(), face.key.end());
    return face;
  };
  // A face below the limit needs three of its tet's corners below it.
  auto hasFaceBelow = [&](Eigen::Index t) {
    return (tets.row(t).array() < cornerLimit).count() >= 3;
  };
  std::vector<std::size_t> groupStart(static_cast<std::size_t>(cornerLimit) + 1, 0);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (!hasFaceBelow(t)) continue;
    for (const auto& local : kOutwardFaces) {
      const Face face = faceOf(t, local);
      if (face.key[2] < cornerLimit) ++groupStart[face.key[0] + 1];
    }
  }
  std::partial_sum(groupStart.begin(), groupStart.end(), groupStart.begin());
  std::vector<Face> faces(groupStart.back());
  std::vector<std::size_t> next(groupStart.begin(), groupStart.end() - 1);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (!hasFaceBelow(t)) continue;
    for (const auto& local : kOutwardFaces) {
      const Face face = faceOf(t, local);
      if (face.key[2] < cornerLimit) faces[next[static_cast<std::size_t>(face.key[0])]++] = face;
    }
  }
  for (std::size_t v = 0; v + 1 < groupStart.size(); ++v) {
    std::sort(faces.begin() + static_cast<std::ptrdiff_t>(groupStart[v]),
              faces.begin() + static_cast<std::ptrdiff_t>(groupStart[v + 1]),
              [](const Face& a, const Face& b) { return a.key < b.key; });
  }
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
  Triangles triangles(static_cast<Eigen::Index>(boundary.size()), 3);
  for (size_t f = 0; f < boundary.size(); ++f) {
    for (int k = 0; k < 3; ++k) triangles(static_cast<Eigen::Index>(f), k) = boundary[f][k];
  }
  return triangles;
}

}  // namespace

SurfaceMesh boundarySurface(const TetMesh& mesh) {
  const Eigen::Index vertexCount = mesh.vertices.rows();
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) {
      if (mesh.tets(t, a) < 0 || mesh.tets(t, a) >= vertexCount) {
        throw InputError("boundarySurface: tet " + std::to_string(t) + " has corner " +
                         std::to_string(mesh.tets(t, a)) + ", not a vertex of the mesh's " +
                         std::to_string(vertexCount));
      }
    }
  }
  SurfaceMesh surface;
  surface.vertices = mesh.vertices;
  surface.triangles = facesUsedOnce(mesh.tets, vertexCount);
  return surface;
}

Triangles surfaceFirstBoundary(const Tets& tets, int surfaceVertexCount) {
  if (tets.size() > 0 && tets.minCoeff() < 0) {
    throw InputError("surfaceFirstBoundary: a tet has a negative corner");
  }
  return facesUsedOnce(tets, surfaceVertexCount);
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
