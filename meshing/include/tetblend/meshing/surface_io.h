#pragma once
// Reading and writing triangle surfaces. The format is chosen by the file
// extension (case-insensitive):
//   .obj   Wavefront OBJ (v/f; texture and normal indices are ignored)
//   .off   Geomview OFF (also COFF/NOFF/CNOFF headers; colours are ignored)
//   .ply   Stanford PLY, ascii, binary_little_endian or binary_big_endian
//   .stl   STL, ascii or binary (read only)
//   .vtp   VTK XML PolyData
// Vertex order is kept exactly as in the file, so results can be mapped back
// to the input by index. Polygons with more than three corners (quads of an
// animation exported from Blender, say) are split into the triangle fan from
// their first corner: files with the same faces get the same triangles.

#include <string>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/mesh_data_arrays.h"
#include "tetblend/meshing/vtk_compression.h"

namespace tetblend {

/// Reads the surface at `path`: #V by 3 positions (file units) and #F by 3
/// zero-based triangle indices in file order, a face of n > 3 corners giving
/// its n - 2 fan triangles (c0, ci, ci+1) in place.
/// STL stores each triangle's corners separately; the reader merges exactly
/// coincident positions (bitwise equal after -0 == +0), and the vertex order
/// is the order of first appearance in the file.
/// Throws InputError (naming file, line or byte offset, value and remedy) for
/// a missing or unreadable file, an unknown extension, malformed numbers,
/// NaN/Inf coordinates, faces of fewer than 3 corners and out-of-range indices.
SurfaceMesh readSurface(const std::string& path);

/// Options of writeSurface.
struct SurfaceWriteOptions {
  /// PLY only: binary little endian with double coordinates (true, exact and
  /// compact) or ascii (false).
  bool plyBinary = true;
  /// VTP only: the compressor of the appended data.
  VtkCompression vtp;
};

/// Writes `mesh` to `path` (.obj, .off, .ply or .vtp, by extension),
/// atomically (see writeFileAtomically). Text formats print the shortest
/// decimal form that reads back to the same double, so every format
/// round-trips positions exactly. `data` (point and cell arrays, see
/// MeshDataArrays) is only stored by .vtp; passing arrays for another format
/// throws InputError rather than dropping them. .vtp is written as binary
/// appended data compressed by options.vtp (zlib by default).
/// Throws InputError for an unknown extension, indices out of range,
/// inconsistent array lengths or an I/O failure; the old file is then kept.
void writeSurface(const std::string& path, const SurfaceMesh& mesh, const MeshDataArrays& data = {},
                  const SurfaceWriteOptions& options = {});

}  // namespace tetblend
