#pragma once
// Private to prepare: one model of several made from disjoint sets of the
// input's faces (components meshed each on its own, components tetrised
// face by face), as if prepared at once.

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
/// vertices, each in some part) from parts with the same examples: rows are
/// the parts' surface vertices, part by part, then their other vertices;
/// tets and excluded tets part by part; sources the first part's;
/// inputVertexRows empty where they would be 0, 1, 2, ... An input vertex
/// in several parts (parts touching at a vertex) takes the first one's row,
/// in the later parts' tets too, which leave their own copy in no tet.
ModelData joinedModel(const std::vector<ModelPart>& parts, const Triangles& inputTriangles,
                      int inputVertexCount);

}  // namespace tetblend
