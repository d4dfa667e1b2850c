#include "tetblend/meshing/tet_mesh_io.h"

#include <algorithm>
#include <vector>

#include "formats.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/tet_boundary.h"
#include "text_parsing.h"

namespace tetblend {

TetMesh readTetMesh(const std::string& path) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".vtu") return detail::readVtu(path);
  if (ext == ".node" || ext == ".ele") return detail::readTetGen(path);
  if (ext == ".mesh") return detail::readMedit(path);
  throw InputError(path + ": unknown tet mesh extension '" + ext +
                   "'; use .vtu, .node/.ele or .mesh");
}

void writeTetMesh(const std::string& path, const TetMesh& mesh, const MeshDataArrays& data,
                  const VtkCompression& compression) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".vtu") {
    detail::writeVtu(path, mesh, data, compression);
    return;
  }
  if (!data.pointData.empty() || !data.cellData.empty()) {
    throw InputError(path + ": " + ext + " cannot store point or cell arrays; write .vtu instead");
  }
  if (ext == ".node" || ext == ".ele") {
    detail::writeTetGen(path, mesh);
  } else if (ext == ".mesh") {
    detail::writeMedit(path, mesh);
  } else {
    throw InputError(path + ": cannot write tet mesh extension '" + ext +
                     "'; use .vtu, .node/.ele or .mesh");
  }
}

void writeTetMeshBoundary(const std::string& path, const TetMesh& mesh,
                          const std::vector<NamedArray>& pointData) {
  if (detail::lowerExtension(path) != ".vtp") {
    throw InputError(path + ": the boundary surface is written as .vtp; change the extension");
  }
  detail::checkMeshForWriting(mesh, path);
  const Triangles boundary = boundarySurface(mesh).triangles;
  if (boundary.rows() == 0) throw InputError(path + ": the tet mesh has no boundary faces");
  // Keep the used vertices in increasing input order.
  std::vector<int> newIndex(static_cast<std::size_t>(mesh.vertices.rows()), -1);
  for (Eigen::Index i = 0; i < boundary.size(); ++i) newIndex[boundary.data()[i]] = 0;
  std::vector<int> inputIndex;
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (newIndex[v] < 0) continue;
    newIndex[v] = static_cast<int>(inputIndex.size());
    inputIndex.push_back(static_cast<int>(v));
  }
  SurfaceMesh surface;
  surface.vertices.resize(static_cast<Eigen::Index>(inputIndex.size()), 3);
  for (std::size_t v = 0; v < inputIndex.size(); ++v) {
    surface.vertices.row(static_cast<Eigen::Index>(v)) = mesh.vertices.row(inputIndex[v]);
  }
  surface.triangles.resize(boundary.rows(), 3);
  for (Eigen::Index i = 0; i < boundary.size(); ++i) {
    surface.triangles.data()[i] = newIndex[boundary.data()[i]];
  }
  MeshDataArrays data;
  for (const NamedArray& array : pointData) {
    const std::size_t components = static_cast<std::size_t>(std::max(array.components, 1));
    if (array.values.size() != newIndex.size() * components) {
      throw InputError(path + ": point array '" + array.name + "' has " +
                       std::to_string(array.values.size()) + " values, expected " +
                       std::to_string(newIndex.size()) + " vertices x " +
                       std::to_string(array.components) + " components");
    }
    NamedArray restricted{array.name, array.components, {}};
    restricted.values.reserve(inputIndex.size() * components);
    for (const int v : inputIndex) {
      const auto first = array.values.begin() + static_cast<std::ptrdiff_t>(v * components);
      restricted.values.insert(restricted.values.end(), first,
                               first + static_cast<std::ptrdiff_t>(components));
    }
    data.pointData.push_back(std::move(restricted));
  }
  detail::writeVtp(path, surface, data, inputIndex);
}

}  // namespace tetblend
