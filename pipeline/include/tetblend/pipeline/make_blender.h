#pragma once
// A ShapeBlender for a prepared model: the mesh it stitches (the rest without
// the excluded tets) and the blender's construction, as the command line, the
// benchmarks and the Python module all make it.

#include <vector>

#include "tetblend/blending/shape_blender.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// The model's rest mesh without its excluded tets (the tets some example
/// cannot embed): the mesh the blender parametrises and stitches. All
/// vertices are kept, in order; a vertex left in no tet is blended linearly
/// (its own stitch component, placed at its blended position).
TetMesh stitchedMesh(const ModelData& model);

/// A blender for `model` with `methods` prepared (parametrisation and the
/// stitch factorisation happen here); `nonlinearStitch` runs the nonlinear
/// stitch (nonlinear_stitch.h) after the linear one whenever that leaves
/// inverted tets (not for vertex-linear, which has no per-tet maps). InputError/DomainError from
/// the library name the example and tet at fault. The blender works on
/// stitchedMesh(model): tet indices in its results are of that mesh. A model
/// with a blend cache starts from it where it fits (ShapeBlender's cache
/// constructor): no factorisation, and no kaji parametrisation with rotation
/// consistency on. `keepTargets` keeps the
/// blended maps in each result (ShapeBlenderOptions::keepTargets), which the target_residual
/// quality array needs; without them the blend and the stitch run fused, to the same vertices.
ShapeBlender makeBlender(const ModelData& model, const std::vector<BlendMethod>& methods,
                         bool rotationConsistency, bool nonlinearStitch, bool keepTargets = true);

/// The blend cache of `model` (ModelData::blendCache): the stitch factor and
/// the kaji parameters with rotation consistency on, the defaults of every
/// front-end.
BlendCache blendCacheOf(const ModelData& model);

}  // namespace tetblend
