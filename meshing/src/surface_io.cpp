#include "tetblend/meshing/surface_io.h"

#include "formats.h"
#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend {

SurfaceMesh readSurface(const std::string& path) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".obj") return detail::readObj(path);
  if (ext == ".off") return detail::readOff(path);
  if (ext == ".ply") return detail::readPly(path);
  if (ext == ".stl") return detail::readStl(path);
  if (ext == ".vtp") return detail::readVtp(path);
  throw InputError(path + ": unknown surface extension '" + ext +
                   "'; use .obj, .off, .ply, .stl or .vtp");
}

void writeSurface(const std::string& path, const SurfaceMesh& mesh, const MeshDataArrays& data,
                  const SurfaceWriteOptions& options) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".vtp") {
    detail::writeVtp(path, mesh, data, {}, options.vtp);
    return;
  }
  if (!data.pointData.empty() || !data.cellData.empty()) {
    throw InputError(path + ": " + ext + " cannot store point or cell arrays; write .vtp instead");
  }
  if (ext == ".obj") {
    detail::writeObj(path, mesh);
  } else if (ext == ".off") {
    detail::writeOff(path, mesh);
  } else if (ext == ".ply") {
    detail::writePly(path, mesh, options.plyBinary);
  } else {
    throw InputError(path + ": cannot write surface extension '" + ext +
                     "'; use .obj, .off, .ply or .vtp");
  }
}

}  // namespace tetblend
