#pragma once
// The prepared-model file written by `tetblend prepare` and read by every
// other subcommand: the compatible tet meshes of one example set, so that
// blending a thousand weight vectors costs one load, not a thousand
// tetrahedralisations. Parametrisation and the stitch factorisation are
// cheap next to TetGen and are redone on load, unless the model keeps them
// (a blend cache, `tetblend prepare --fast-load`: larger file, faster load).
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
//             are the input's), then #U i32 rows (ModelData::inputVertexRows);
//             version 4 on: u64 1 if a blend cache follows, else 0; the cache
//             (blend_cache.h) is the factor's perm, super, rowStart, rows (i32
//             arrays), valueStart (i64), values (f64), then the kaji data's
//             u64 tets, examples, rotationConsistency (0 or 1), params (f64),
//             correctedTets, correctionStart, correctionExample (i32),
//             corrections (f64); each array is a u64 count and its values
//   u64       checksum of the payload bytes (modelChecksum)
// A file with another magic, another version, a wrong size or a wrong hash is
// refused with an InputError that says which and what to do.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tetblend/blending/blend_cache.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Version of the layout above; bump on any change of the payload. Version
/// 1, 2 and 3 files (no excluded tets; no input vertex rows; no blend cache)
/// are still read.
constexpr std::uint32_t kModelFormatVersion = 4;

/// What a model file holds.
struct ModelData {
  TetMesh rest;  ///< rest tet mesh; surface vertices first
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
  /// one row (seam_welding.h); a vertex no face uses has a row of its own
  /// after the tet mesh's, in no tet (meshable_input.h). Empty when the
  /// input's vertices are the surface vertices themselves (row i is input
  /// vertex i).
  std::vector<int> inputVertexRows;
  /// The stitch factor and kaji parameters of the model's blender
  /// (makeBlender), if kept: blenders then start from them.
  std::optional<BlendCache> blendCache;
  /// The format version of the file it was read from (readModelFile); a
  /// model made in memory is written as kModelFormatVersion.
  std::uint32_t formatVersion = kModelFormatVersion;

  /// Vertices of the input surface (and of every blended surface written).
  Eigen::Index inputVertexCount() const;
  /// Rows `positions` (one per rest vertex) at the input's vertices: the
  /// blended surface's vertices, in the input's order, for surfaceTriangles.
  Vertices inputVertices(const Vertices& positions) const;
};

/// FNV-1a 64-bit hash of `size` bytes, continuing from `hash`.
std::uint64_t fnv1a64(const unsigned char* data, std::size_t size,
                      std::uint64_t hash = 0xcbf29ce484222325ULL);

/// FNV-1a's step over the little-endian 64-bit words of `data` (the last
/// size % 8 bytes byte by byte): eight times faster than fnv1a64, and a
/// change of any one word still changes it (each step is invertible).
std::uint64_t fnv1a64Words(const unsigned char* data, std::size_t size);

/// The checksum a model file of format `version` stores after its payload:
/// fnv1a64 up to version 3, fnv1a64Words from version 4 (a blend cache can
/// be hundreds of megabytes).
std::uint64_t modelChecksum(const unsigned char* payload, std::size_t size, std::uint32_t version);

/// Checks the internal consistency of `model` (index ranges, shapes); throws
/// InputError naming `what` (a file name) on the first problem.
void checkModel(const ModelData& model, const std::string& what);

/// Writes `model` to `path` atomically (writeFileAtomically).
void writeModelFile(const std::string& path, const ModelData& model);

/// Reads and checks a model file; throws InputError for a missing, foreign,
/// other-version, truncated or damaged file.
ModelData readModelFile(const std::string& path);

}  // namespace tetblend
