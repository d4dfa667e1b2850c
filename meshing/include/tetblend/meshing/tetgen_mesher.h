#pragma once
// Filling a closed surface with tetrahedra by TetGen 1.5 (Si 2015), keeping the
// surface exactly: the rest tet mesh of the shape blender (Kaji–Ochiai §6.2
// works on per-element maps; tets make them full-rank). TetGen's switch string
// is built inside and never exposed.

#include <functional>
#include <string>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Options of tetrahedralize, with their defaults.
struct TetGenOptions {
  /// Quality bound: each tet's circumradius / shortest edge at most this
  /// (TetGen -q first value). 0 disables quality refinement (then only the
  /// surface vertices are used, plus Steiner points TetGen needs to recover
  /// the surface). Otherwise must exceed 1; TetGen's own default is 2.0.
  double maxRadiusEdgeRatio = 2.0;
  /// Lower bound on dihedral angles in degrees (TetGen -q second value),
  /// pursued by refinement but not guaranteed; 0 = none. Used only when
  /// maxRadiusEdgeRatio > 0. Values above ~20 may not terminate.
  double minDihedralAngleDeg = 0.0;
  /// Upper bound on tet volume in file units cubed (TetGen -a); 0 = none.
  double maxTetVolume = 0.0;
  /// Upper bound on tet volume relative to the cube of the surface's
  /// bounding-box diagonal; 0 = none. With both bounds set, the smaller
  /// absolute value applies. Both are pursued by refinement, not guaranteed:
  /// tets against the kept surface may stay larger (TetGen may not split
  /// them without adding points on the boundary).
  double maxTetVolumeRelative = 0.0;
  /// 0: TetGen is silent (switch Q; library code never prints by default).
  /// 1: TetGen's normal report on stdout. 2: its verbose report (switch V).
  int verbosity = 0;
  /// Seconds the quality refinement (maxRadiusEdgeRatio > 0) may take; 0
  /// = automatic (30 s plus 20 times TetGen's usual time for the tets
  /// expected), negative = no limit. TetGen still running then is stopped,
  /// the solid is meshed again by TetGen's constrained Delaunay
  /// tetrahedralisation alone (no quality refinement, no volume bound), and
  /// `notice` says so. TetGen's refinement can run for minutes near very
  /// small input angles or faces that nearly touch, where the plain
  /// tetrahedralisation takes seconds.
  double qualityTimeLimitSeconds = 0.0;
  /// Name of the surface (e.g. its file) used in error messages.
  std::string sourceName = "surface";
  /// Told, in one line naming sourceName, when tetrahedralize departs from
  /// these options (the quality refinement stopped at its time limit); may
  /// be empty. Called on the calling thread.
  std::function<void(const std::string&)> notice;
};

/// Tetrahedralises the solid bounded by `closedSurface` (#V by 3, #F by 3,
/// closed, manifold, outward oriented, no self-intersection: checked first by
/// requireValidRest, so bad input is refused with a named face before TetGen
/// runs). Several components and nested ones (cavities, oriented inwards)
/// are allowed; the regions outside the solid are removed.
///
/// Postconditions, checked after TetGen returns (NumericalError if violated):
/// the first #V output vertices are the input vertices bit for bit and in
/// order; further vertices (Steiner points) lie strictly inside; the boundary
/// faces of the tets are exactly the input triangles (same orientation, up to
/// a rotation of the indices within a face); every tet is positively oriented
/// (det[p1-p0, p2-p0, p3-p0] > 0). The tets come in spatial order (a Morton
/// curve of their centroids) and the Steiner points in the order the tets
/// first use them, so that ranges of tets are compact in space and in
/// memory (TetGen's own order scatters them). TetGen's failures are turned into
/// InputError (self-intersection, tiny features, very close facets, invalid
/// input, or TetGen crashing on the surface) or NumericalError / Error
/// (internal error, out of memory, no child process) with a message naming
/// `options.sourceName` and saying what to do.
///
/// TetGen runs in a forked child process (its output comes back through a
/// pipe): Debian's TetGen 1.5.0 frees its mesh twice when it fails, which
/// would otherwise abort the caller. The child discards the parent's
/// unflushed stdio buffers and leaves with _exit (no atexit handlers).
/// Costs one fork per call and a copy of the output mesh.
TetMesh tetrahedralize(const SurfaceMesh& closedSurface, const TetGenOptions& options = {});

}  // namespace tetblend
