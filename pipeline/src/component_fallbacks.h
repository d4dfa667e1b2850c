#pragma once
// Private to prepare: what it does when the rest as a whole cannot be
// meshed with an interior, part by part. Its parts are its components, split
// where an edge joins more than two faces (manifoldRegions: a fin on a body,
// two parts touching along an edge). Parts that cannot be filled with tets
// on their own get one tet per face; when every part meshes on its own but
// not together, each is prepared on its own. The parts' models are joined
// (model_join.h), sharing the rows of the vertices they share.

#include <string>
#include <vector>

#include "tetblend/core/error.h"
#include "tetblend/meshing/seam_welding.h"
#include "tetblend/pipeline/model_file.h"
#include "tetblend/pipeline/prepare_model.h"

namespace tetblend {

/// The model of `rest` and `examples` when meshing the rest (zipped as
/// `welding`) was refused with `refusal`: the components that cannot be
/// meshed with an interior on their own get one tet per face (the
/// tetrisation), the others are prepared as usual (prepareModel), and the
/// models are joined; when every component meshes on its own, each is
/// prepared on its own (notes silenced, warnings kept and marked with the
/// component) and the models are joined. Rethrows `refusal` with
/// --no-fill-holes or --strict, for a single component that meshes, or
/// when the tetrisation refuses the components that do not mesh.
ModelData preparedPartByPart(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                             const std::string& restName,
                             const std::vector<std::string>& exampleNames,
                             const PrepareOptions& options, const PrepareMessages& messages,
                             const SeamWelding& welding, const InputError& refusal);

}  // namespace tetblend
