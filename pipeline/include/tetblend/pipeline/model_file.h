#pragma once
// The prepared-model file written by `tetblend prepare` and read by every
// other subcommand: the compatible tet meshes of one example set, so that
// blending a thousand weight vectors costs one load, not a thousand
// tetrahedralisations. (Parametrisation and the stitch factorisation are
// cheap next to TetGen and are redone on load.)
//
// Binary layout, all integers little-endian, doubles IEEE-754 binary64 LE:
//   8 bytes   magic "TBMODEL\0"
//   u32       format version (kModelFormatVersion)
//   u64       payload size in bytes
//   payload:  u64 #V, #T, #F, surface vertex count, #examples;
//             rest vertices (#V*3 f64), tets (#T*4 i32), surface triangles
//             (#F*3 i32); per example: vertices (#V*3 f64);
//             rest source name, then one per example (u64 length + bytes);
//             version 2 on: u64 #X excluded tets, then #X i32 tet indices;
//             version 3 on: u64 #U input vertices (0: the surface vertices
//             are the input's), then #U i32 rows (ModelData::inputVertexRows)
//   u64       FNV-1a 64 hash of the payload bytes
// A file with another magic, another version, a wrong size or a wrong hash is
// refused with an InputError that says which and what to do.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Version of the layout above; bump on any change of the payload. Version 1
/// and 2 files (no excluded tets; no input vertex rows) are still read.
constexpr std::uint32_t kModelFormatVersion = 3;

/// What a model file holds.
struct ModelData {
  TetMesh rest;                             ///< rest tet mesh; surface vertices first
  /// The rest surface's faces as the input has them: indices into the
  /// input's vertices (inputVertexCount()).
  Triangles surfaceTriangles;
  int surfaceVertexCount = 0;               ///< the first rows of rest.vertices are the surface's
  std::vector<Vertices> examples;           ///< per example, #V by 3 positions (rest order)
  std::string restSource;                   ///< file the rest surface came from
  std::vector<std::string> exampleSources;  ///< one per example
  /// Tets (ascending, distinct) that some example inverts because its surface
  /// folds or intersects itself: left out of the stitch energy of every blend.
  std::vector<int> excludedTets;
  /// Per input surface vertex, its row of rest.vertices (and of every
  /// blend): copies of a vertex split along a texture or normal seam share
  /// one row (seam_welding.h). Empty when the input's vertices are the
  /// surface vertices themselves (row i is input vertex i).
  std::vector<int> inputVertexRows;

  /// Vertices of the input surface (and of every blended surface written).
  Eigen::Index inputVertexCount() const;
  /// Rows `positions` (one per rest vertex) at the input's vertices: the
  /// blended surface's vertices, in the input's order, for surfaceTriangles.
  Vertices inputVertices(const Vertices& positions) const;
};

/// FNV-1a 64-bit hash of `size` bytes, continuing from `hash`.
std::uint64_t fnv1a64(const unsigned char* data, std::size_t size,
                      std::uint64_t hash = 0xcbf29ce484222325ULL);

/// Checks the internal consistency of `model` (index ranges, shapes); throws
/// InputError naming `what` (a file name) on the first problem.
void checkModel(const ModelData& model, const std::string& what);

/// Writes `model` to `path` atomically (writeFileAtomically).
void writeModelFile(const std::string& path, const ModelData& model);

/// Reads and checks a model file; throws InputError for a missing, foreign,
/// other-version, truncated or damaged file.
ModelData readModelFile(const std::string& path);

}  // namespace tetblend
