#pragma once
// The prepared shape blender (Kaji–Ochiai §6.2): built once from a rest tet
// mesh and n compatible examples, it parametrises every example's per-tet
// maps once per method and factors the stitch once; then each weight vector
// costs one per-tet blend, one right-hand side and one back-substitution.
//
// Weights: one per example, any reals; the rest has weight 1 - sum(w), so
// weights 0 give the rest and the k-th unit vector gives example k.

#include <Eigen/Core>
#include <map>
#include <memory>
#include <vector>

#include "tetblend/blending/blend_cache.h"
#include "tetblend/blending/blend_method.h"
#include "tetblend/blending/nonlinear_stitch.h"
#include "tetblend/blending/stitch_solver.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Options of ShapeBlender, with their defaults.
struct ShapeBlenderOptions {
  /// Methods parametrised at construction; the first is the default of
  /// blend(weights). More can be added later with ShapeBlender::prepare.
  std::vector<BlendMethod> methods = {BlendMethod::kKaji};
  /// Consistent rotation logarithms across neighbouring tets
  /// (rotation_consistency.h) for kaji and liebodies.
  bool rotationConsistency = true;
  /// Factorisation of the stitch.
  StitchOptions stitch;
  /// Keep the #T blended maps in BlendResult::targets (72 bytes per tet; what
  /// tetQuality's stitch residual needs). Off: each chunk of maps is added to
  /// the stitch's right-hand side as soon as it is blended and none is kept
  /// (targets empty; the vertices are bitwise the same either way). Implied
  /// by nonlinearStitch, which needs the maps.
  bool keepTargets = false;
  /// Run the nonlinear stitch (nonlinear_stitch.h) after the linear one when
  /// the linear result has inverted tets. Off by default (it costs Ceres
  /// solves); not used by vertex-linear.
  bool nonlinearStitch = false;
  NonlinearStitchOptions nonlinear;
};

/// Wall-clock seconds of the parts of one blend.
struct BlendTimings {
  /// Per-tet target maps (or vertex blend). Without keepTargets the maps are
  /// blended inside the right-hand-side pass, whose wall time is split
  /// between this and rhsSeconds in the ratio of the threads' times.
  double blendSeconds = 0.0;
  double rhsSeconds = 0.0;        ///< stitch right-hand side
  double solveSeconds = 0.0;      ///< back-substitution and centroid placement
  double nonlinearSeconds = 0.0;  ///< nonlinear stitch, when enabled
};

/// One blended shape.
struct BlendResult {
  BlendMethod method = BlendMethod::kKaji;
  Vertices vertices;  ///< #V by 3, the rest's vertex order
  /// #T blended maps B_j when options.keepTargets or options.nonlinearStitch
  /// is set; empty otherwise and for vertex-linear.
  std::vector<Eigen::Matrix3d> targets;
  BlendTimings timings;
  /// Filled when options.nonlinearStitch is set (zeros otherwise).
  NonlinearStitchReport nonlinear;
};

/// A rest mesh and its examples, parametrised and factored once.
class ShapeBlender {
 public:
  /// `rest`: #V vertices, #T positively oriented tets; `examples`: n >= 1
  /// vertex sets (#V by 3 each) with the rest's tets. Throws InputError for an
  /// empty example list, a size mismatch, a rest tet with volume <= 0 or an
  /// example tet with volume <= 0 (naming example, tet and volume), and
  /// DomainError when a method cannot parametrise an example tet.
  ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
               const ShapeBlenderOptions& options = {});
  /// As above, starting from `cache`: what exportCache() gave for the same
  /// rest and examples. Its factor is used when options.stitch asks for the
  /// supernodal backend, its kaji parameters when options.methods has kKaji
  /// and they were made with options.rotationConsistency; the rest is
  /// computed. Blends are then bit for bit those of the exporting blender.
  /// InputError also when the cache does not fit the rest and examples.
  ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
               const ShapeBlenderOptions& options, BlendCache cache);
  ~ShapeBlender();
  ShapeBlender(ShapeBlender&&) noexcept;
  ShapeBlender& operator=(ShapeBlender&&) noexcept;

  /// Parametrises the examples for `method` (no-op if already prepared).
  void prepare(BlendMethod method);
  /// True if blend(weights, method) can run without prepare(method).
  bool isPrepared(BlendMethod method) const;
  /// The stitch's factor and the kaji parameters, for the constructor that
  /// takes a cache (blend_cache.h). InputError unless kKaji is prepared and
  /// the backend is CHOLMOD's supernodal one.
  BlendCache exportCache() const;

  /// Blended shape for `weights` with the first method of the options.
  BlendResult blend(const std::vector<double>& weights) const;
  /// Blended shape for `weights` with `method`. Throws InputError for a wrong
  /// weight count or an unprepared method, DomainError (naming the tet) where
  /// the method cannot blend these weights.
  BlendResult blend(const std::vector<double>& weights, BlendMethod method) const;
  /// As blend, reusing the storage of `result`. blend and blendInto are safe
  /// to call from several threads at once (each with its own `result`): the
  /// prepared data and the factor are only read, and each call solves in its
  /// own StitchWorkspace (no lock).
  void blendInto(const std::vector<double>& weights, BlendMethod method, BlendResult& result) const;

  int exampleCount() const;
  /// The rest mesh (the stitch solver's copy; the blender keeps no other).
  const TetMesh& rest() const;
  const StitchSolver& stitch() const;
  const ShapeBlenderOptions& options() const;

  /// Blended component centroids (1 - sum w) c_rest + sum_k w_k c_k (#C by 3).
  Centroids blendedCentroids(const std::vector<double>& weights) const;

 private:
  // The public constructors' checks, then build(rest, cache).
  ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
               const ShapeBlenderOptions& options, BlendCache* cache);
  // Factor the stitch and parametrise the methods
  // side by side, each from `cache` where it fits (null: no cache).
  void build(const TetMesh& rest, BlendCache* cache);
  // The parametrisation of `method` for the examples on `rest` (the
  // stitch's mesh): what prepare() stores.
  std::unique_ptr<TetMapBlender> parametrise(const TetMesh& rest, BlendMethod method) const;

  std::vector<Vertices> examples_;  // kept for vertex-linear and later prepare()
  ShapeBlenderOptions options_;
  std::unique_ptr<StitchSolver> stitch_;  // set by the constructor
  Centroids restCentroids_;
  std::vector<Centroids> exampleCentroids_;
  std::map<BlendMethod, std::unique_ptr<TetMapBlender>> blenders_;
};

/// One-shot blend: prepares a ShapeBlender for options.methods[0] and blends
/// `weights` once. Prefer ShapeBlender for more than one weight vector.
BlendResult blendShapes(const TetMesh& rest, const std::vector<Vertices>& examples,
                        const std::vector<double>& weights,
                        const ShapeBlenderOptions& options = {});

}  // namespace tetblend
