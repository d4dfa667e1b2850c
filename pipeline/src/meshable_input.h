#pragma once
// What an exporter leaves in a surface that takes no part in its volume, set
// aside before meshing and given back to the model after:
// - faces that repeat a vertex (a, a, b): triangle strips written as lists
//   leave them; they cover nothing, so the meshing leaves them out;
// - edges of zero length, whose two ends are at one position in the rest
//   and in every example (an exporter's collapsed edge, a triangle joining
//   the copies of a seam vertex): the ends are merged for meshing, the one
//   with the larger index becoming a copy of the other (it shares its row,
//   as seam copies do), and the faces that then repeat a vertex are left
//   out as above;
// - vertices that no (other) face uses, "loose" vertices: deleted parts,
//   stray points, a vertex buffer shared with other meshes. The model gives
//   each a row of its own after the tet mesh's vertices, in no tet, with its
//   position in the rest and in every example. The stitch places a vertex in
//   no tet at its blended position (make_blender.h), so loose vertices
//   follow the examples linearly.
// The model keeps the input's faces and vertices, so every blended surface
// has them all.

#include <string>
#include <vector>

#include "tetblend/meshing/surface_validation.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// The input as it is meshed.
struct MeshableInput {
  /// Ascending: the input's faces that repeat a vertex, once the ends of
  /// zero-length edges are merged.
  std::vector<int> droppedFaces;
  /// Ascending: input vertices merged into the end of a zero-length edge
  /// with a smaller index.
  std::vector<int> copies;
  std::vector<int> copyOf;            ///< per input vertex: the one it is merged into, or itself
  std::vector<int> loose;             ///< ascending: input vertices no other face uses
  SurfaceMesh rest;                   ///< the rest without both (faces renumbered)
  std::vector<SurfaceMesh> examples;  ///< each example without the same
};

/// `mesh` without the listed faces (ascending), its vertices all kept.
SurfaceMesh withoutFaces(const SurfaceMesh& mesh, const std::vector<int>& faces);

/// True if `rest` (face indices in range) has a face that repeats a vertex,
/// an edge of zero length or a vertex that no face uses.
bool hasUnmeshableParts(const SurfaceMesh& rest);

/// The rest and every example with the ends of their zero-length edges
/// merged (where they coincide in the rest and every example), without the
/// faces that then repeat a vertex, then without the vertices no remaining
/// face uses. Each example must be compatible with the rest
/// (requireCompatibleExample, which names it in its InputError).
MeshableInput meshableInput(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames);

/// Gives `model`, prepared from meshableInput(rest, examples), the input
/// back: the loose vertices one row each after its vertices (rest and every
/// example), the input's faces, and ModelData::inputVertexRows for every
/// input vertex (a copy on the row of the vertex it was merged into).
void restoreInput(ModelData& model, const SurfaceMesh& rest,
                  const std::vector<SurfaceMesh>& examples, const MeshableInput& input);

}  // namespace tetblend
