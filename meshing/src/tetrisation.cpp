#include "tetblend/meshing/tetrisation.h"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {

TetMesh tetrise(const SurfaceMesh& surface) {
  const Eigen::Index nv = surface.vertices.rows(), nf = surface.triangles.rows();
  if (!surface.vertices.allFinite()) {
    throw InputError(
        "tetrise: the surface has a NaN or infinite coordinate: run "
        "validateSurface to find the vertex and fix it");
  }
  TetMesh mesh;
  mesh.vertices.resize(nv + nf, 3);
  mesh.vertices.topRows(nv) = surface.vertices;
  mesh.tets.resize(nf, 4);
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles(f, k);
      if (v < 0 || v >= nv) {
        throw InputError("tetrise: face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(v) + ", outside 0.." + std::to_string(nv - 1) +
                         ": fix the face indices");
      }
    }
    const Eigen::Vector3d p0 = surface.vertices.row(surface.triangles(f, 0));
    const Eigen::Vector3d p1 = surface.vertices.row(surface.triangles(f, 1));
    const Eigen::Vector3d p2 = surface.vertices.row(surface.triangles(f, 2));
    const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0);
    const double doubleArea = cross.norm();
    if (!(doubleArea > 0.0)) {
      throw InputError("tetrise: face " + std::to_string(f) + " (" +
                       std::to_string(surface.triangles(f, 0)) + ", " +
                       std::to_string(surface.triangles(f, 1)) + ", " +
                       std::to_string(surface.triangles(f, 2)) +
                       ") has zero area, so no normal: remove or repair the degenerate face");
    }
    const Eigen::Vector3d apex = (p0 + p1 + p2) / 3.0 + cross / doubleArea * std::sqrt(doubleArea);
    mesh.vertices.row(nv + f) = apex.transpose();
    mesh.tets.row(f) << surface.triangles(f, 0), surface.triangles(f, 1), surface.triangles(f, 2),
        static_cast<int>(nv + f);
  }
  return mesh;
}

std::vector<TetMesh> tetriseCompatible(const SurfaceMesh& rest,
                                       const std::vector<SurfaceMesh>& examples,
                                       const std::vector<std::string>& exampleNames) {
  if (exampleNames.size() != examples.size()) {
    throw InputError("tetriseCompatible: " + std::to_string(examples.size()) + " examples but " +
                     std::to_string(exampleNames.size()) + " names: pass one name per example");
  }
  for (std::size_t k = 0; k < examples.size(); ++k) {
    requireCompatibleExample(rest, examples[k], exampleNames[k]);
  }
  std::vector<TetMesh> meshes;
  meshes.reserve(examples.size() + 1);
  meshes.push_back(tetrise(rest));
  // The rest's triangles: an example may list them in another order or split
  // a quad along the other diagonal (validateExample).
  for (const SurfaceMesh& example : examples) {
    meshes.push_back(tetrise(SurfaceMesh{example.vertices, rest.triangles}));
  }
  return meshes;
}

}  // namespace tetblend
