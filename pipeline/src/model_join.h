#pragma once
// Private to prepare: one model of two made from disjoint sets of the
// input's faces (the components meshed with an interior, and those
// tetrised face by face), as if prepared at once.

#include <vector>

#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// A model of some of the input's faces, and the input vertex each of its
/// own input vertices is.
struct ModelPart {
  ModelData model;
  std::vector<int> inputVertices;  ///< per vertex of the part's input, the whole input's
};

/// The model of the whole input (`inputTriangles`, `inputVertexCount`
/// vertices, each in `a` or `b`; one in both takes a's row, in b's tets
/// too, and b's copy is left in no tet) from two parts
/// with the same examples: rows are a's surface vertices, b's, a's other
/// vertices, b's; tets a's then b's; excluded tets of both; sources a's;
/// inputVertexRows empty where they would be 0, 1, 2, ...
ModelData joinedModel(const ModelPart& a, const ModelPart& b, const Triangles& inputTriangles,
                      int inputVertexCount);

}  // namespace tetblend
