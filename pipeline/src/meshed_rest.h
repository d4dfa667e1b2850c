#pragma once
// Private to prepare: the rest surface as TetGen meshes it. The user's faces
// stay the model's (and every output's); what is meshed is closed (holes
// filled), oriented outward, and free of self-intersections, where the
// user's rest may lack the last two.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "tetblend/meshing/hole_filling.h"
#include "tetblend/pipeline/prepare_model.h"

namespace tetblend {

/// The surface TetGen meshes, and how it differs from the user's rest.
struct MeshedRest {
  /// The user's vertices (or, when `separated`, the separated copy's) and
  /// faces: the user's, reoriented where needed, then the hole fill's.
  SurfaceMesh surface;
  HoleFilling filling;
  int reorientedFaces = 0;  ///< user's faces meshed reversed
  /// Degenerate faces flipped with a neighbour for meshing (degenerate_faces.h).
  int flippedFaces = 0;
  /// The user's rest intersects itself: `surface` holds a separated copy
  /// (surface_separation.h), and the user's rest is embedded like a pose.
  bool separated = false;
  std::size_t intersectingPairs = 0;      ///< of the user's rest (closed)
  std::pair<int, int> firstPair{-1, -1};  ///< its first intersecting faces
  int movedVertices = 0;                  ///< by the separation
  double largestDisplacement = 0.0;       ///< by the separation, file units
  /// When the separation fails: the example whose positions `surface`
  /// holds instead (the one nearest the rest that bounds a solid), or -1.
  int meshedOnExample = -1;
  /// Closed components that intersect one another are meshed each on its
  /// own (component_meshing.h), every one oriented outward: per face of
  /// `surface`, its component (empty when the surface is meshed whole).
  std::vector<int> faceComponent;
  int componentCount = 0;
  std::size_t overlappingPairs = 0;  ///< intersecting face pairs of different components
  /// Closed components inside another that the user's faces turn outward,
  /// as a solid's (an eyeball in a head), not inward, as a cavity's: then
  /// every component is meshed on its own too.
  int nestedSolids = 0;
};

/// The meshed rest of `rest` (read from `restName`). Faces that point inwards
/// or against their neighbours are reversed for meshing; holes are filled
/// unless options.fillHoles is off; closed components that intersect one
/// another are meshed each on its own; a rest that intersects itself within
/// a component is separated unless options.strict, or, when it intersects
/// itself too deeply, meshed on the nearest of `examples` (positions of
/// the rest's vertices) whose closed surface bounds a solid. Throws InputError with the first
/// problem when the rest cannot be meshed: non-manifold, open with fillHoles off, a hole fill that
/// cuts the surface, or self-intersections too deep to separate (or any, with strict). Not for the
/// tetrisation, which meshes the user's faces as they are.
MeshedRest meshedRest(const SurfaceMesh& rest, const std::string& restName,
                      const PrepareOptions& options, const std::vector<Vertices>& examples = {});

}  // namespace tetblend
