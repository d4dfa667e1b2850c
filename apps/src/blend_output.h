#pragma once
// Writing one blended shape: the tet mesh as .vtu (point data: displacement
// from the rest; cell data: quality arrays) and the surface, in the rest
// surface's vertex order, as .vtp beside it (plus .obj/.ply/.off on request);
// or, for a .vtp output, the surface alone.

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/meshing/vtk_compression.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

/// Parses --surface-format values ("obj", "ply", "off"; "vtp" is always
/// written); InputError for anything else.
std::vector<std::string> parseSurfaceFormats(const std::vector<std::string>& formats);

/// InputError unless `outputPath` ends in .vtu (tets and surface) or .vtp
/// (the surface only); `what` names the option or entry that gave it.
void checkBlendOutputPath(const std::string& outputPath, const std::string& what);

/// The files written for `outputPath` (.vtu or .vtp): the .vtu itself (only
/// for a .vtu), the .vtp and one file per extra surface format, in that order.
std::vector<std::string> blendOutputFiles(const std::string& outputPath,
                                          const std::vector<std::string>& surfaceFormats);

/// Writes `positions` (#V by 3, the model's vertex order): for a .vtu
/// `outputPath`, as the tets of `model` with point array "displacement"
/// (positions - rest, 3 components) and `cellData` (one tuple per tet); then,
/// for either output, the surface (first surfaceVertexCount vertices, rest
/// surface triangles, point arrays "displacement" and "input_vertex_index")
/// to the .vtp and to each extra format. `cellData` is not written for a .vtp
/// output. The .vtu and .vtp are compressed by `compression`. Every file is
/// written atomically.
void writeBlendResult(const std::string& outputPath, const ModelData& model,
                      const Vertices& positions, const std::vector<NamedArray>& cellData,
                      const std::vector<std::string>& surfaceFormats,
                      const VtkCompression& compression);

}  // namespace tetblend::cli
