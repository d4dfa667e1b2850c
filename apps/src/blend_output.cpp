#include "blend_output.h"

#include "cli_common.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_mesh_io.h"

namespace tetblend::cli {

namespace {

NamedArray displacementArray(const Vertices& positions, const Vertices& rest) {
  NamedArray a{"displacement", 3, {}};
  a.values.reserve(static_cast<std::size_t>(positions.rows()) * 3);
  for (Eigen::Index i = 0; i < positions.rows(); ++i)
    for (int c = 0; c < 3; ++c) a.values.push_back(positions(i, c) - rest(i, c));
  return a;
}

}  // namespace

std::vector<std::string> parseSurfaceFormats(const std::vector<std::string>& formats) {
  std::vector<std::string> out;
  for (const std::string& f : formats) {
    if (f == "vtp") continue;
    if (f != "obj" && f != "ply" && f != "off") {
      throw InputError("--surface-format: unknown format '" + f + "'; use obj, ply or off");
    }
    out.push_back(f);
  }
  return out;
}

void checkBlendOutputPath(const std::string& outputPath, const std::string& what) {
  const std::string extension = extensionOf(outputPath);
  if (extension != ".vtu" && extension != ".vtp") {
    throw InputError(what + " " + outputPath +
                     ": the output must be a .vtu file (tets; the surface .vtp goes beside it) "
                     "or a .vtp file (the surface only)");
  }
}

std::vector<std::string> blendOutputFiles(const std::string& outputPath,
                                          const std::vector<std::string>& surfaceFormats) {
  std::vector<std::string> files;
  if (extensionOf(outputPath) == ".vtu") files.push_back(outputPath);
  files.push_back(withExtension(outputPath, ".vtp"));
  for (const std::string& f : surfaceFormats) files.push_back(withExtension(outputPath, "." + f));
  return files;
}

void writeBlendResult(const std::string& outputPath, const ModelData& model,
                      const Vertices& positions, const std::vector<NamedArray>& cellData,
                      const std::vector<std::string>& surfaceFormats,
                      const VtkCompression& compression) {
  checkBlendOutputPath(outputPath, "output");
  if (positions.rows() != model.rest.vertices.rows()) {
    throw InputError(outputPath + ": " + std::to_string(positions.rows()) +
                     " blended vertices for a model of " +
                     std::to_string(model.rest.vertices.rows()));
  }
  if (extensionOf(outputPath) == ".vtu") {
    MeshDataArrays tetData;
    tetData.pointData.push_back(displacementArray(positions, model.rest.vertices));
    tetData.cellData = cellData;
    writeTetMesh(outputPath, TetMesh{positions, model.rest.tets}, tetData, compression);
  }

  const SurfaceMesh surface{model.inputVertices(positions), model.surfaceTriangles};
  const Eigen::Index ns = surface.vertices.rows();
  MeshDataArrays surfaceData;
  surfaceData.pointData.push_back(
      displacementArray(surface.vertices, model.inputVertices(model.rest.vertices)));
  // The surface has the input's vertices and order (seam copies included):
  // vertex i is input vertex i.
  NamedArray inputIndex{"input_vertex_index", 1, std::vector<double>(static_cast<std::size_t>(ns))};
  for (Eigen::Index i = 0; i < ns; ++i)
    inputIndex.values[static_cast<std::size_t>(i)] = static_cast<double>(i);
  surfaceData.pointData.push_back(std::move(inputIndex));
  SurfaceWriteOptions vtp;
  vtp.vtp = compression;
  writeSurface(withExtension(outputPath, ".vtp"), surface, surfaceData, vtp);
  for (const std::string& f : surfaceFormats)
    writeSurface(withExtension(outputPath, "." + f), surface);
}

}  // namespace tetblend::cli
