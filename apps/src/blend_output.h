#pragma once
// Writing one blended shape: the tet mesh as .vtu (point data: displacement
// from the rest; cell data: quality arrays) and the surface, in the rest
// surface's vertex order, as .vtp beside it (plus .obj/.ply/.off on request).

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

/// Parses --surface-format values ("obj", "ply", "off"; "vtp" is always
/// written); InputError for anything else.
std::vector<std::string> parseSurfaceFormats(const std::vector<std::string>& formats);

/// The files written for `vtuPath`: the .vtu itself, the .vtp and one file per
/// extra surface format, in that order.
std::vector<std::string> blendOutputFiles(const std::string& vtuPath,
                                          const std::vector<std::string>& surfaceFormats);

/// Writes `positions` (#V by 3, the model's vertex order) as the tets of
/// `model` to `vtuPath` (must end in .vtu) with point array "displacement"
/// (positions - rest, 3 components) and `cellData` (one tuple per tet), then
/// the surface (first surfaceVertexCount vertices, rest surface triangles,
/// with its displacement) to the .vtp beside it and to each extra format.
/// Every file is written atomically.
void writeBlendResult(const std::string& vtuPath, const ModelData& model, const Vertices& positions,
                      const std::vector<NamedArray>& cellData,
                      const std::vector<std::string>& surfaceFormats);

}  // namespace tetblend::cli
