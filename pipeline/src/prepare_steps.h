#pragma once
// Private to prepare: the steps that the main flow (prepare_model.cpp) and
// its fallbacks for parts of the rest (component_fallbacks.h) share: the
// messages, the checks of the examples, and the per-face tetrisation's
// model.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "tetblend/meshing/self_intersection.h"
#include "tetblend/pipeline/model_file.h"
#include "tetblend/pipeline/prepare_model.h"

namespace tetblend::prepare_steps {

/// Passes `line` to `sink` if there is one.
void say(const std::function<void(const std::string&)>& sink, const std::string& line);

/// Reports `steps` done to messages.step if there is one.
void advance(const PrepareMessages& messages, std::size_t steps);

/// "1.34 M" / "134 k" / "950": a tet count people read at a glance.
std::string roughCount(long long n);

/// "1 tet" / "3 tets": `n` and `noun`, plural unless n is 1.
std::string counted(std::size_t n, const std::string& noun);

/// `value` with three significant digits ("-0.0462", "1.5e+03").
std::string threeDigits(double value);

/// Why an example's tets cannot be embedded, in words: its surface
/// intersects itself (how many face pairs, the first), or it collapses
/// `collapsedFaces` faces (CompatibleTetMeshes::collapsedFaces), or the
/// placement failed.
std::string diagnosis(const SelfIntersections& found, std::size_t collapsedFaces = 0);

/// --strict fails fast: an example whose surface intersects itself is
/// refused before any meshing, since some of its tets can never be
/// embedded. With `faceComponent` (components meshed each on its own), only
/// faces of one component count.
void refuseSelfIntersecting(const Triangles& triangles, const std::vector<SurfaceMesh>& examples,
                            const std::vector<std::string>& exampleNames,
                            const std::vector<int>& faceComponent = {});

/// Refuses, naming the remedy, a rest that collapses faces to (almost) zero
/// area that an example gives an area (a part scaled to a point, as an
/// animation's first frame may hide one): no tet can fill them, and
/// removing them would break the examples' correspondence, but that example
/// (or any frame where the part has its size) can be the rest. Does nothing
/// when no example gives such faces an area. Called where the rest could
/// not be meshed, neither whole nor part by part.
void refuseCollapsedRest(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                         const std::string& restName, const std::vector<std::string>& exampleNames);

/// Refuses an example that turns a closed part of `rest` inside out, as a
/// mirror does (a negative scale in an exporter): the part's enclosed volume
/// changes sign, and the part intersects itself at no more face pairs than
/// in `rest`. Every tet of that part would be inverted, whatever the
/// placement. (A part pushed through itself may enclose a negative volume
/// too; it crosses itself more, is accepted, and its tets that cannot be
/// embedded are excluded.) `rest` is the surface meshed (closed, oriented;
/// holes filled), and each example has its vertex rows.
void refuseInsideOut(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                     const std::vector<std::string>& exampleNames);

/// Warns about each example equal to the rest (one with another vertex
/// count is left to checkExamples).
void warnUnchangedExamples(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                           const std::string& restName,
                           const std::vector<std::string>& exampleNames,
                           const PrepareMessages& messages);

/// prepareModel without warnUnchangedExamples: for the parts of a surface
/// prepared each on its own, which would each repeat its warning (and a
/// part that one example leaves in place still moves with the others).
ModelData preparedPart(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                       const std::string& restName, const std::vector<std::string>& exampleNames,
                       const PrepareOptions& options, const PrepareMessages& messages);

/// Refuses an example that is not the rest's surface; warns about one whose
/// quads are split the other way.
void checkExamples(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                   const std::vector<std::string>& exampleNames, const PrepareMessages& messages);

/// The model of the per-face tetrisation: the user's surface as it is (open
/// or not, seams and all, crossing itself, pinched or oriented any way: each
/// face's tet is its own), no interior.
ModelData tetrisedModel(const SurfaceMesh& rest, const std::vector<SurfaceMesh>& examples,
                        const std::string& restName, const std::vector<std::string>& exampleNames,
                        const PrepareOptions& options, const PrepareMessages& messages);

}  // namespace tetblend::prepare_steps
