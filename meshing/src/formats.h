#pragma once
// Internal: one reader/writer pair per file format, dispatched by extension
// from surface_io.cpp and tet_mesh_io.cpp. Writers are given the final path
// and write it atomically themselves.

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/meshing/vtk_compression.h"

namespace tetblend::detail {

SurfaceMesh readObj(const std::string& path);
void writeObj(const std::string& path, const SurfaceMesh& mesh);

SurfaceMesh readOff(const std::string& path);
void writeOff(const std::string& path, const SurfaceMesh& mesh);

SurfaceMesh readPly(const std::string& path);
void writePly(const std::string& path, const SurfaceMesh& mesh, bool binary);

SurfaceMesh readStl(const std::string& path);

SurfaceMesh readVtp(const std::string& path);
/// `inputVertexIndex`, when not empty, is stored as the int point array
/// "input_vertex_index" (one entry per vertex).
void writeVtp(const std::string& path, const SurfaceMesh& mesh, const MeshDataArrays& data,
              const std::vector<int>& inputVertexIndex = {},
              const VtkCompression& compression = {});

TetMesh readVtu(const std::string& path);
void writeVtu(const std::string& path, const TetMesh& mesh, const MeshDataArrays& data,
              const VtkCompression& compression = {});

/// `path` ends in .node or .ele; both files are read or written.
TetMesh readTetGen(const std::string& path);
void writeTetGen(const std::string& path, const TetMesh& mesh);

TetMesh readMedit(const std::string& path);
void writeMedit(const std::string& path, const TetMesh& mesh);

/// Writers call these first so no file refers to a missing vertex or holds a
/// position the readers would refuse: InputError naming `path` unless every
/// index lies in 0..#V-1 and every coordinate is finite.
void checkMeshForWriting(const SurfaceMesh& mesh, const std::string& path);
void checkMeshForWriting(const TetMesh& mesh, const std::string& path);

}  // namespace tetblend::detail
