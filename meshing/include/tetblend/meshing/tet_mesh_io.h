#pragma once
// Reading and writing tetrahedral meshes. The format is chosen by the file
// extension (case-insensitive):
//   .vtu          VTK XML UnstructuredGrid (every cell must be VTK_TETRA)
//   .node / .ele  TetGen; either name may be given, the other is found by
//                 replacing the extension; indices 0- or 1-based (the first
//                 index in the .node file decides, as in TetGen)
//   .mesh         Medit ascii (1-based; only Vertices and Tetrahedra are
//                 used, boundary Triangles/Edges/etc. are skipped)
// Vertex order and the corner order of each tet are kept exactly as in the
// file; orientation is not changed here (the validation step checks it).

#include <string>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/meshing/vtk_compression.h"

namespace tetblend {

/// Reads the tet mesh at `path`: #V by 3 positions (file units), #T by 4
/// zero-based tet indices in file order.
/// Throws InputError (naming file, line, value and remedy) for a missing or
/// unreadable file, an unknown extension, malformed numbers, NaN/Inf
/// coordinates, cells that are not linear tetrahedra and out-of-range indices.
TetMesh readTetMesh(const std::string& path);

/// Writes `mesh` to `path`, atomically (see writeFileAtomically):
///   .vtu          binary appended, compressed by `compression` (zlib by
///                 default), cells VTK_TETRA, with the point arrays (one
///                 tuple per vertex) and cell arrays (one tuple per tet) of
///                 `data`;
///   .node / .ele  both TetGen files (0-based), positions in shortest exact
///                 decimal form;
///   .mesh         Medit ascii, version 2 (double precision), 1-based.
/// `data` and `compression` are only used by .vtu; arrays for another format
/// throw InputError.
/// Throws InputError for an unknown extension, indices out of range, bad
/// arrays (empty, wrong length, name empty/with spaces/duplicated) or an I/O
/// failure; the old file is then kept.
void writeTetMesh(const std::string& path, const TetMesh& mesh, const MeshDataArrays& data = {},
                  const VtkCompression& compression = {});

/// Writes the boundary surface of `mesh` to `path` (.vtp, binary appended,
/// zlib compressed), atomically. The triangles are those of boundarySurface
/// (tet_boundary.h): faces used by exactly one tet, oriented outwards for
/// positively oriented tets. Only the vertices the
/// boundary uses are written, in increasing input index (so a tet mesh built
/// from a surface, whose surface vertices come first, gives back the surface's
/// vertex order); the point array "input_vertex_index" maps them back.
/// `pointData` holds one tuple per vertex of `mesh` and is restricted to the
/// written vertices.
/// Throws InputError as writeTetMesh, if the extension is not .vtp, if the mesh
/// has no boundary or if a face is shared by more than two tets.
void writeTetMeshBoundary(const std::string& path, const TetMesh& mesh,
                          const std::vector<NamedArray>& pointData = {});

}  // namespace tetblend
