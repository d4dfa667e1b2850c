#include "tetblend/blending/tet_maps.h"

#include <Eigen/LU>
#include <algorithm>
#include <limits>
#include <sstream>

#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {

RestTetData restTetData(const TetMesh& rest, const std::vector<int>& mayBeFlat) {
  const int tetCount = static_cast<int>(rest.tets.rows());
  const int vertexCount = static_cast<int>(rest.vertices.rows());
  RestTetData data;
  data.inverseEdges.resize(tetCount);
  data.volumes.resize(tetCount);
  for (int j = 0; j < tetCount; ++j) {
    for (int c = 0; c < 4; ++c) {
      const int v = rest.tets(j, c);
      if (v < 0 || v >= vertexCount) {
        std::ostringstream message;
        message << "rest tet " << j << " refers to vertex " << v << ", outside [0, " << vertexCount
                << "): fix the tet indices";
        throw InputError(message.str());
      }
    }
    const Eigen::Matrix3d edges = tetEdgeMatrix(rest.vertices, rest.tets.row(j));
    const double volume = edges.determinant() / 6.0;
    const bool tolerated = std::binary_search(mayBeFlat.begin(), mayBeFlat.end(), j);
    if (!(volume > 0.0) && tolerated) {
      data.inverseEdges[j] = Eigen::Matrix3d::Constant(std::numeric_limits<double>::quiet_NaN());
      data.volumes[j] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    if (!(volume > 0.0)) {
      std::ostringstream message;
      message << "rest tet " << j << " has signed volume " << volume
              << " (must be > 0): reorient or remove it";
      throw InputError(message.str());
    }
    data.inverseEdges[j] = edges.inverse();
    data.volumes[j] = volume;
  }
  return data;
}

std::vector<Eigen::Matrix3d> deformationGradients(const TetMesh& rest, const RestTetData& restData,
                                                  const Vertices& example, int exampleIndex) {
  if (example.rows() != rest.vertices.rows()) {
    std::ostringstream message;
    message << "example " << exampleIndex + 1 << " has " << example.rows()
            << " vertices but the rest mesh has " << rest.vertices.rows()
            << ": the meshes must be compatible";
    throw InputError(message.str());
  }
  const int tetCount = static_cast<int>(rest.tets.rows());
  std::vector<Eigen::Matrix3d> gradients(tetCount);
  for (int j = 0; j < tetCount; ++j) {
    const Eigen::Matrix3d edges = tetEdgeMatrix(example, rest.tets.row(j));
    const double volume = edges.determinant() / 6.0;
    if (!(volume > 0.0)) {
      std::ostringstream message;
      message << "example " << exampleIndex + 1 << ", tet " << j << " has signed volume " << volume
              << " (must be > 0): the example is inverted or flat there; fix the example";
      throw InputError(message.str());
    }
    gradients[j] = edges * restData.inverseEdges[j];
  }
  return gradients;
}

}  // namespace tetblend
