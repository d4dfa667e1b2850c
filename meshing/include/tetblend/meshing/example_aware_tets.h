#pragma once
// Example-aware compatible tet meshes: the rest tet mesh is refined where the
// examples need it, then every example's interior is placed on the refined
// mesh (compatible_tets.h).
//
// Why refinement: a tet whose four vertices all lie on the surface is fixed
// by the example surfaces alone, so no placement of interior vertices can
// repair it when an example turns it inside out (a thin part bent or twisted
// across the tet); likewise an interior edge joining two surface vertices, or
// an interior face whose three edges lie on the surface. Such tets are split
// (stellar subdivision at the centroid of those edges and faces) until every
// new tet has a movable interior vertex. Refinement never touches the
// surface: surface vertices stay first, bit for bit and in order; boundary
// faces are unchanged; new vertices are appended as interior vertices.
//
// The stages:
//  1. before any placement: interior edges and faces with all vertices on
//     the surface that leave the solid of an example whose surface does not
//     intersect itself (a valid tet mesh of the example covers exactly that
//     solid; exact predicates, surface_interior.h) are split, then
//     all-surface tets inverted by any example (repeated while new ones
//     appear, at most maxRounds times);
//  2. every example is placed (harmonic → ARAP → untangling,
//     compatible_tets.h; one factorisation for all), several at once when
//     there are threads and memory for it (the result does not depend on
//     how many);
//  3. while an example whose surface does not intersect itself keeps
//     inverted tets (at most maxRounds rounds per example): those tets are
//     split as in stage 1, or where they already have an interior vertex
//     their longest interior edge is halved; every example's new vertices
//     start at the centroid of their simplex in that example (a valid
//     placement stays valid: each child tet has a positive fraction of its
//     parent's volume) and only the still-inverted regions are untangled
//     again (no new factorisation). Rounds stop early when the inverted
//     count grows. A split also splits the inverted tets of the other
//     examples there into more inverted tets: an example is untangled again
//     on the refined mesh before its own rounds, and every example with
//     inverted tets once more at the end.
// With several tet components (tets linked through shared vertices), each is
// a solid of its own: an example's faces of different components may
// intersect (closed components meshed each on their own overlap,
// component_meshing.h) and still leave it clean.
// Examples whose surface intersects itself cannot be embedded where it does;
// they are untangled only locally and briefly (intersectingUntangle) so they
// fail fast, and they do not drive refinement. So are examples that collapse
// faces to (almost) zero area, except where the faces are whole parts (a
// part scaled to a point, as animations hide parts): such a part is placed
// as a small copy of itself, so the example's other parts are placed as in
// a clean example, and the example's own surface is put back at the end
// (the part's tets, of no volume, stay inverted).

#include <cstddef>
#include <functional>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/compatible_tets.h"
#include "tetblend/meshing/self_intersection.h"

namespace tetblend {

/// Options of buildCompatibleTetMeshes, with their defaults.
struct ExampleAwareOptions {
  /// Placement of the interior vertices on each round's mesh.
  CompatibleTetOptions placement;
  /// Refinement rounds at most, in stage 1 and in stage 3 for each example
  /// (0: place on the given mesh only).
  int maxRounds = 8;
  /// Untangling of examples whose surface intersects itself: 3 tet-rings,
  /// 1 Newton step per round, 40 rounds, and a rise of min det F below
  /// 1e-3 of it is no progress, and every attempt, the first too, gives up
  /// after 4 rounds without progress so they fail fast; ε shrinks by at
  /// least 10 % per round (clean examples: the whole interior, 2, 150, any
  /// rise, 30 rounds for the first attempt, 5 %; see UntangleEffort). On 48
  /// harshly skinned dino frames (27 with excluded tets where they
  /// intersect) this took 25 s against 32 s with the clean examples' steps
  /// and rounds, and excluded 4 % more tets (1458 against 1407 of 16 k;
  /// measured before untangle.cpp's stall and start rules, with which the
  /// run takes 15 s and excludes 1384). ε shrinking by 10 % instead of 5 %
  /// (2026-11-29): 5.7 % fewer excluded tets over the sets of the README's
  /// The untangler (44 391 -> 41 850, summed over frames) in the same time,
  /// and the same clean frames; 15 % excluded 42 282. Giving up after 4
  /// rounds without progress instead of 8 (2026-11-29, with untangle.cpp
  /// returning each attempt's best state): 6 % less time over those sets
  /// (241.6 -> 227.0 s), 0.5 % more excluded tets (41 601 -> 41 815), the
  /// same clean frames; judging progress by the inverted count alone (min
  /// det F rising not counted) with 8 rounds: 221.7 s, 42 980. Giving up
  /// after 8 rounds in a row that end with no fewer inverted tets than the
  /// start (roundsToFallBelowStart; 2026-12-02): bench_meshing's hard 1 M
  /// row embedded in 9.5 s instead of 13.3 s (the same excluded tets), the
  /// sets excluded 1.1 % more tets (46 059 -> 46 555) in about the same
  /// time, the same clean frames; not counting a rise of min det F as
  /// progress while the count is above the start, instead: 9.0 s against
  /// 14.7 s, but 2.8 % more (47 350). Giving up after 4 rounds in a row
  /// that each raise the count above the start (risingRoundsToGiveUp;
  /// 2026-12-02, eleventh session): the 1 M row's elbow stops after 4
  /// rounds instead of 8; see the README, "Self-intersecting examples whose
  /// count keeps rising". Starting at ε ≤ 0.4 instead of 1
  /// (largestStartEpsilon; 2026-12-03, fourteenth session): the sets
  /// excluded 1.7 % fewer tets (46 700 -> 45 916) in about the same time, the
  /// same clean frames; see the README, "The first ε of self-intersecting
  /// examples".
  UntangleEffort intersectingUntangle{3, 1, 40, 1e-3, false, 4, 4, 0.2, 8, 4, 0.4};
  /// ARAP iterations at most for examples whose surface intersects itself
  /// (clean ones: placement.arapIterations, 15). Measured 2026-12-02, 5
  /// against 15: bench_meshing's hard 100 k row embedded in 0.78, 0.78 s
  /// instead of 1.26, 1.20 s and its 1 M row in 15.4 s instead of 17.4 s,
  /// while their self-intersecting elbow (a deep fold) excluded 24 % more
  /// tets (1369 against 1106, 13 395 against 10 807); over the five prepare
  /// sets of the README (364 self-intersecting frames) one frame changed,
  /// by 3 excluded tets.
  int intersectingArapIterations = 5;
  /// Examples whose surface intersects itself run ARAP only over the
  /// interior vertices within this many tet-rings of their harmonic map's
  /// inverted tets, unless those are more than half of the interior
  /// (CompatibleTetBuilder::place; 0: always the whole interior). Only the
  /// fold needs ARAP: the harmonic map is valid elsewhere, and the fold's
  /// tets are excluded wherever ARAP puts them. Measured 2026-12-03 against
  /// the whole interior: bench_meshing's hard elbow excluded 90, 882 and
  /// 11 746 tets at 10 k, 100 k and 1 M instead of 96, 1121 and 13 395, and
  /// its 1 M ARAP took 0.27 s instead of 1.7-2.0 s; the five prepare sets of
  /// the README excluded 46 455 tets instead of 46 351 (34 of 362
  /// self-intersecting frames changed, 22 up by 193, 12 down by 67) in
  /// 106-114 s instead of 133 s. 6 rings (a scratch build): 46 425 tets in
  /// 110 s, and 0.44 s at 1 M.
  int intersectingArapRings = 4;
};

/// The compatible tet meshes of a rest mesh and its examples.
struct CompatibleTetMeshes {
  /// The (possibly refined) rest mesh: rows 0..#S-1 are the input's surface
  /// vertices bit for bit, then the input's interior vertices, then the
  /// Steiner points added; all tets positively oriented.
  TetMesh rest;
  /// One per example, placed on `rest` (vertices #V by 3 and the tets that
  /// stay inverted, ascending).
  std::vector<CompatibleTetResult> examples;
  /// Per example: the self-intersections of its surface (pairCount 0 =
  /// clean; the first pair listed), counting only faces of one tet component
  /// (components meshed each on their own may overlap, component_meshing.h).
  std::vector<SelfIntersections> selfIntersections;
  /// Per example: how many faces its surface collapses to (almost) zero
  /// area that are not so in the rest (a part scaled to a point). No tet on
  /// them can have a volume (see the top of this file for how such an
  /// example is placed).
  std::vector<std::size_t> collapsedFaces;
  int steinerPoints = 0;           ///< interior vertices added by refinement
  int rounds = 0;                  ///< refinement rounds performed (stages 1 and 3)
  int allSurfaceTetsInverted = 0;  ///< all-surface tets found inverted in stage 1
  int rigidSimplicesOutside = 0;   ///< edges and faces split in stage 1 for leaving a solid
};

/// Called after each stage with a short description (for progress display);
/// from one thread at a time, though not always the caller's.
using MeshingProgress = std::function<void(const char* stage)>;

/// Builds compatible tet meshes for `rest` (#V by 3 vertices, #T by 4
/// positively oriented tets, surface vertices 0..surfaceVertexCount-1 first,
/// as tetrahedralize returns them) and the example surfaces (#S by 3 each,
/// the rest surface's vertex order), refining the rest as described above.
/// The example surfaces' triangles are the rest mesh's boundary faces.
/// Examples whose tets stay inverted come back with them listed (the caller
/// decides whether to refuse or exclude them). Throws what
/// CompatibleTetBuilder throws (InputError on bad sizes or non-finite
/// positions).
CompatibleTetMeshes buildCompatibleTetMeshes(const TetMesh& rest, int surfaceVertexCount,
                                             const std::vector<Vertices>& exampleSurfaces,
                                             const ExampleAwareOptions& options = {},
                                             const MeshingProgress& progress = {});

/// Tets of `tets` whose four vertices are all < surfaceVertexCount and whose
/// signed volume in `positions` (at least #S rows) is <= 0, ascending.
std::vector<int> invertedAllSurfaceTets(const Tets& tets, int surfaceVertexCount,
                                        const Vertices& positions);

}  // namespace tetblend
