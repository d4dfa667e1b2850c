#pragma once
// Vertices of the input surface that no face uses ("loose" vertices):
// exporters leave them behind (deleted parts, stray points, a vertex buffer
// shared with other meshes). They take no part in the tets: prepare meshes
// the surface without them, and the model gives each a row of its own after
// the tet mesh's vertices, in no tet, with its position in the rest and in
// every example. The stitch places a vertex in no tet at its blended
// position (make_blender.h), so loose vertices follow the examples linearly
// and every blended surface keeps the input's vertices.

#include <string>
#include <vector>

#include "tetblend/meshing/surface_validation.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// The input without its loose vertices.
struct WithoutLooseVertices {
  std::vector<int> loose;             ///< ascending input indices used by no face of the rest
  SurfaceMesh rest;                   ///< the rest without them (faces renumbered)
  std::vector<SurfaceMesh> examples;  ///< each example without the same vertices
};

/// Removes the vertices that no face of `rest` uses from the rest and every
/// example. Each example must first be compatible with the rest
/// (requireCompatibleExample, which names it in its InputError).
WithoutLooseVertices withoutLooseVertices(const SurfaceMesh& rest,
                                          const std::vector<SurfaceMesh>& examples,
                                          const std::vector<std::string>& exampleNames);

/// Gives `model`, prepared from withoutLooseVertices(rest, examples), the
/// loose vertices back: one row each after its vertices (rest and every
/// example), the input's faces, and ModelData::inputVertexRows for every
/// input vertex.
void keepLooseVertices(ModelData& model, const SurfaceMesh& rest,
                       const std::vector<SurfaceMesh>& examples, const std::vector<int>& loose);

}  // namespace tetblend
