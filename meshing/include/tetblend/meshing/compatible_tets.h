#pragma once
// Compatible tetrahedral meshes: given the rest tet mesh (surface vertices
// first, then interior Steiner points, as TetGen's `Y` switch returns them)
// and an example surface with the rest surface's connectivity, place the
// interior vertices so every example tet keeps a positive volume. The
// boundary is pinned to the example surface exactly.
//
// Pipeline per example (one factorisation of the rest stiffness matrix is
// shared by every step and every example):
//  1. harmonic extension: piecewise-linear FEM Laplace equation with the
//     surface as Dirichlet data; reproduces affine boundary maps exactly.
//     With CompatibleTetOptions::stopWhenValid (the default) a harmonic
//     extension without inverted tets is the result, and step 2 stops at the
//     first candidate without inverted tets: on the benchmark's 2π twist,
//     180° bend and 170° elbow (10k tets) ARAP lowers the ARAP energy by
//     0.2%, 19% and 12% (0.1023→0.1021, 0.030→0.025, 0.140→0.123) and
//     makes place() 40–60× slower;
//  2. volumetric ARAP (Sorkine & Alexa 2007, per tet: min Σ_t vol_t
//     ‖∇_t x − R_t‖², local polar rotation, global solve with the same
//     matrix), warm-started from whichever has the lower ARAP energy: the
//     harmonic extension or the global solve with a rotation field
//     propagated from the boundary (so twists of several turns and 180°
//     bends need not start from collapsed harmonic rotations). Of all these
//     candidates, the one with the fewest inverted tets (then the lowest
//     ARAP energy) is kept: ARAP can fold strongly compressed regions that
//     the harmonic extension kept valid;
//  3. if tets are still inverted: untangling of the interior vertices by
//     minimising a regularised distortion energy with a decreasing
//     regularisation (Garanzha, Kaporin, Kudryavtseva, Protais, Ray,
//     Sokolov, "Foldover-free maps in 50 lines of code", 2021), each value
//     by projected Newton steps.
// The result reports exactly which tets remain inverted, if any.

#include <future>
#include <memory>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// How far one untangling attempt goes: the free region, the rounds (values
/// of the regularisation ε) and the Newton steps per round.
struct UntangleEffort {
  /// The free region stops growing past this many tet-rings (0: it grows
  /// until the whole interior is free). A bound makes hopeless cases (an
  /// example surface that intersects itself) fail fast.
  int maxRings = 0;
  /// Maximum projected Newton steps per untangling round (the first factors
  /// the Newton matrix unless the round keeps the last round's factor,
  /// untangle.cpp's kModelAgreement; the others reuse that factor). A round only
  /// follows the minimiser as ε shrinks by 5-10 %: on the hard-pose corpus
  /// (before untangle.cpp's stall and start rules) 2 steps left 3 clean
  /// poses with 9 inverted tets in 76 s, 5 steps 4 with 72 in 88 s.
  int iterationsPerRound = 2;
  /// Maximum rounds per attempt. ε shrinks by at least 5 % per round, so 150
  /// rounds reach ε ≈ 5e-4 (60 rounds, 0.05, left knot1's 720° twist
  /// with tets inverted at min det F = −0.06).
  int maxRounds = 150;
  /// The rise of the smallest det F, relative to |min det F|, that counts
  /// as progress in the stall test (untangle.cpp), besides a fall of the
  /// inverted count. Clean examples: any rise (the barrier raises it for
  /// many rounds before the count falls; 1e-3 left 3 corpus poses with 66
  /// tets inverted instead of 1 with 78). Examples whose surface intersects
  /// itself: 1e-3 (bench_meshing's 1 M hard bar crept up by less for 40
  /// rounds, 16 s, to end with 3 times the inverted tets it started with).
  double minDetProgress = 0.0;
  /// Measure distortion against the rest's tets with their slivers thickened
  /// (compatible_tets.cpp) instead of the rest's own shapes. Validity is the
  /// same either way (the sign of det F); a sliver's own shape makes det F
  /// of a slightly inverted example tet about −1 / (its relative height),
  /// where the untangler gives up.
  bool thickenedReference = false;
  /// An attempt gives up after this many rounds in a row that neither raised
  /// the smallest det F (by minDetProgress) nor lowered the count of
  /// inverted tets: its free region is too small (or the example cannot be
  /// embedded), and a larger region or refinement is the remedy. (Rounds
  /// with Newton steps converge at each ε, so min det F can sit still for
  /// many rounds while the count falls: judged by min det F alone, cactus's
  /// 1080° twist stopped with 6 tets inverted, 27 → 6 in 12 rounds.)
  int stallRounds = 8;
  /// stallRounds for the first attempt of an untangling (the smallest
  /// region). From many inverted tets at a large ε, the count first rises
  /// while the region relaxes, then falls as ε shrinks: with 8, the 536 k-tet
  /// subdivided armadillo's first attempts (2-3 k free vertices) gave up at
  /// ε ≈ 0.5 with more tets inverted than at their start, and one frame was
  /// then untangled with 25 k free vertices (60 s of its 106 s); with 30 the
  /// first attempts succeed (42 s; see the README, The untangler).
  int firstAttemptStallRounds = 30;
  /// σ's floor in the ε update of Garanzha et al. (2021), Alg. 1,
  /// σ = max(1 − E_after / E_before, smallestDecrease): ε shrinks by at
  /// least about σ / 2 per round. Clean examples: 0.1 (0.3 made the corpus
  /// about 1.4 times faster but left 4 clean poses with 69 inverted tets,
  /// against 3 with 9, before the stall test counted inverted tets; 0.2 on
  /// 2026-11-29 left 16 clean frames of the lion's 48-frame gallop with
  /// tets instead of none, and took 154 s instead of 53).
  double smallestDecrease = 0.1;
  /// An attempt gives up after this many rounds in a row that end with no
  /// fewer inverted tets than it started with (0: no such limit). Clean
  /// examples: no limit (the count first rises while the region relaxes,
  /// then falls; see firstAttemptStallRounds). Examples whose surface
  /// intersects itself: 8. Their smallest det F sits in the fold, which no
  /// placement repairs, and creeps up there by more than minDetProgress
  /// while the count grows: bench_meshing's 1 M-tet elbow went from 13 395
  /// inverted tets to 32 669 in 25 rounds (7 s) and kept its start.
  int roundsToFallBelowStart = 0;
  /// An attempt gives up after this many rounds in a row that each end
  /// with more inverted tets than the round before (the first: than the
  /// start), unless its count has fallen below its start (0: no such
  /// limit). Clean examples: no limit (see firstAttemptStallRounds).
  /// Examples whose surface intersects itself: 4. Per-round counts over the
  /// README's five prepare sets (529 attempts; 2026-12-02, scratch build):
  /// none of the 35 attempts that rose 4 rounds in a row ended below its
  /// start, while 4 that rose 3 in a row did (the elk's 291 -> 107); a
  /// rise in the first round alone said nothing (an armadillo frame's 825
  /// became 1634, then 26). bench_meshing's 1 M-tet elbow rises from its
  /// first round to its 25th.
  int risingRoundsToGiveUp = 0;
  /// The largest first ε (untangle.cpp starts at twice |min det F|, at most
  /// this). Clean examples: 1, the start of Garanzha et al. (2021), Alg. 1.
  /// Examples whose surface intersects itself: 0.4. Their fold keeps
  /// min det F far below −0.5, so every attempt started at ε = 1 and let
  /// the whole free region relax before the fold's tets were pushed back.
  double largestStartEpsilon = 1.0;
};

/// Options of CompatibleTetBuilder, with their defaults.
struct CompatibleTetOptions {
  /// Maximum number of ARAP local–global iterations (0 = harmonic only, or
  /// the propagated-rotation start when propagateRotations is true). On the
  /// hard-pose corpus 15 leave the same tets inverted as 50 (the untangler
  /// finishes the job), at half the time of the hard bench_meshing set.
  int arapIterations = 15;
  /// ARAP stops when no interior vertex moved more than this fraction of the
  /// rest bounding-box diagonal in one iteration (relative, unitless).
  double arapRelativeTolerance = 1e-7;
  /// ARAP also stops after an iteration that lowers its energy by less than
  /// this fraction (unitless): the search has converged. bench_meshing's
  /// 10 k twist sat at energy 0.4126 from its first iteration to its 15th;
  /// over the README's sets of The untangler 3 % less time, the same clean
  /// frames, 0.2 % more excluded tets.
  double arapStallFall = 1e-4;
  /// Accept the first placement without inverted tets: the harmonic
  /// extension when it has none (no ARAP iteration), else the first ARAP
  /// candidate with none. false: ARAP runs to convergence even from a valid
  /// harmonic extension (lower distortion, many times slower).
  bool stopWhenValid = true;
  /// Also try the start from rotations propagated from the boundary (step 2
  /// above); ARAP starts from it when its ARAP energy beats the harmonic's.
  bool propagateRotations = true;
  /// Run the untangling step when tets are still inverted after ARAP.
  bool untangle = true;
  /// Untangling frees the interior vertices within this many tet-rings of
  /// the inverted tets first; the ring count doubles while tets stay
  /// inverted, until the whole interior is free.
  int untangleRings = 3;
  /// Free region, rounds and Newton steps of each attempt.
  UntangleEffort untangleEffort;
};

/// One example's compatible tet mesh.
struct CompatibleTetResult {
  Vertices vertices;                    ///< #V by 3: rows 0..#S-1 equal the example surface
  std::vector<int> invertedTets;        ///< indices of tets with signed volume <= 0, ascending
  std::vector<double> invertedVolumes;  ///< their signed volumes (units of length³)
  int harmonicInvertedCount = 0;        ///< inverted tets of the harmonic extension alone
  int arapIterations = 0;               ///< ARAP iterations performed
  int untangleRounds = 0;               ///< untangling rounds performed (0 if not needed)
  /// ARAP energy Σ_t vol_t ‖∇_t x − R_t‖² / Σ_t vol_t (unitless) of the result.
  double arapEnergy = 0.0;
  /// Smallest det(∇_t x) over the tets (unitless volume ratio example/rest).
  double minVolumeRatio = 0.0;
};

/// Factor-once builder of compatible tet meshes for one rest mesh
/// (geometry-central style: build once, call place() for every example).
/// Its const methods may be called from several threads at once (the
/// examples of buildCompatibleTetMeshes are placed that way).
class CompatibleTetBuilder {
 public:
  /// `rest`: #V by 3 vertices and #T by 4 positively oriented tets whose
  /// first `surfaceVertexCount` (#S) vertices are the surface vertices (the
  /// ones on boundary faces); the remaining #V−#S are interior. The P1
  /// stiffness matrix is assembled and its interior block factored
  /// (Cholesky) on the first call that needs it (place, harmonicExtension),
  /// not by repair and evaluate.
  /// Throws InputError if a tet is not positively oriented, an index is out of
  /// range, #S is out of [1, #V], a vertex ≥ #S lies on a boundary face, or
  /// a face is shared by more than 2 tets. (place and harmonicExtension throw
  /// NumericalError if the factorisation fails.)
  /// `interiorOrder`, when valid, is an elimination order of the interior
  /// vertices of a mesh that `rest` extends (its vertices first, in the same
  /// order, then new interior vertices; order[k] = the k-th eliminated, as
  /// vertex − #S). The factorisation waits for it and eliminates the new
  /// vertices last, when they are few; otherwise it orders the interior
  /// itself. With CHOLMOD only.
  CompatibleTetBuilder(const TetMesh& rest, int surfaceVertexCount,
                       const CompatibleTetOptions& options = {},
                       std::shared_future<std::vector<int>> interiorOrder = {});
  ~CompatibleTetBuilder();
  CompatibleTetBuilder(CompatibleTetBuilder&&) noexcept;
  CompatibleTetBuilder& operator=(CompatibleTetBuilder&&) noexcept;

  /// Assembles the interior's stiffness and factors it now, as the first
  /// placement would: for callers about to place examples on several
  /// threads, so that none waits for the factorisation beside it (a waiting
  /// thread takes cycles from the factorisation's own threads).
  void factor() const;

  /// Frees the interior's factorisation (the largest block of memory a
  /// builder holds: 536 MiB at 1 M tets), for callers done placing examples
  /// that go on to repair them; the next placement factors again. Not
  /// concurrently with any other call on this builder.
  void releaseFactor() const;

  /// Places the interior for the example surface positions `exampleSurface`
  /// (#S by 3, same vertex order as the rest surface) by steps 1–3 above.
  /// Throws InputError on a wrong row count or non-finite positions.
  CompatibleTetResult place(const Vertices& exampleSurface) const;
  /// place() with at most `arapIterations` ARAP iterations instead of the
  /// options' and, with `arapRings` > 0, ARAP only over the interior
  /// vertices within that many tet-rings of the harmonic map's inverted
  /// tets, the other vertices kept where the harmonic map put them, unless
  /// that region holds more than half of the interior (then the whole
  /// interior, as without it). Examples whose surface intersects itself take
  /// fewer iterations, locally (ExampleAwareOptions).
  CompatibleTetResult place(const Vertices& exampleSurface, int arapIterations,
                            int arapRings = 0) const;

  /// Step 1 only: the harmonic extension (#V by 3), exact for affine maps.
  Vertices harmonicExtension(const Vertices& exampleSurface) const;

  /// Step 3 only, from `start` (#V by 3; rows 0..#S-1 the example surface,
  /// kept): untangles the interior around the inverted tets with `effort`
  /// (starting at the options' untangleRings). Returns the result
  /// measured as by place (harmonicInvertedCount and arapIterations are 0).
  /// Throws InputError on a wrong row count or non-finite positions.
  CompatibleTetResult repair(const Vertices& start, const UntangleEffort& effort) const;

  /// The inverted tets, ARAP energy and smallest volume ratio of `positions`
  /// (#V by 3), without moving anything.
  CompatibleTetResult evaluate(const Vertices& positions) const;

  int surfaceVertexCount() const;
  const TetMesh& restMesh() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Indices (ascending) of the tets of (vertices, tets) with signed volume <= 0.
std::vector<int> invertedTets(const Vertices& vertices, const Tets& tets);

}  // namespace tetblend
