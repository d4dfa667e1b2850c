#pragma once
// The blend methods of the shape blender, selectable by name, and the common
// interface of a method prepared for one rest mesh and its examples: given a
// weight vector, produce the target linear map B_j of every tet for the
// stitch (Kaji–Ochiai §6.2: A'_j(w) = Blend(w, A_1j, ..., A_nj)).
//
// Weight convention for every method: with n examples and weights w (any
// reals), the rest shape has weight 1 - sum(w). Weights 0 give the rest and
// the k-th unit vector gives example k.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "tetblend/blending/tet_adjacency.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Every blend method. Names (blendMethodName) are those of the command line.
enum class BlendMethod {
  kKaji,            ///< "kaji": phi(sum_k w_k psi(F_k)), Kaji–Ochiai §5 Blend
  kKajiFrechet,     ///< "kaji-frechet": refined weighted Fréchet sum, Kaji–Ochiai Alg. 2
  kLieBodies,       ///< "liebodies": p0 exp(sum_k w_k log(p0^-1 p_k)), Bansal–Tatu
  kDualQuaternion,  ///< "dq": polar; rotation by DLB (Kavan et al. §3.4), stretch in log space
  kDib,             ///< "dib": as dq with dual-quaternion iterative blending (Kavan et al. §3.3)
  kAlexa,           ///< "alexa": exp(sum_k w_k log F_k), Alexa's matrix-log blend
  kPolarSlerp,      ///< "polar-slerp": polar; quaternion slerp-type rotation blend, linear stretch
  kLinear,          ///< "linear": (1 - sum w) I + sum_k w_k F_k, then the stitch
  kVertexLinear,    ///< "vertex-linear": (1 - sum w) x_rest + sum_k w_k x_k, no stitch
};

/// All methods, in the order above.
const std::vector<BlendMethod>& allBlendMethods();

/// The command-line name of `method` (e.g. "kaji-frechet").
std::string blendMethodName(BlendMethod method);

/// The method called `name` (or an alias of it, canonicalMethodName).
/// Throws InputError listing the valid names.
BlendMethod blendMethodFromName(const std::string& name);

/// `name` with an alias of a method name replaced by that name; any other
/// name unchanged. The one alias: "dqs" (dual quaternion skinning, the name
/// `tetblend deform` used) for "dq", so that both spellings name the dual
/// quaternion method of `blend` and of `deform` (handle_deformer.h).
std::string canonicalMethodName(const std::string& name);

/// The aliases for help texts and error messages: "dqs = dq".
std::string methodAliasNote();

/// True for the methods that take logarithms of rotations and so depend on
/// the rotation-consistency option (kaji, liebodies). kaji-frechet takes
/// principal logarithms relative to its running mean (kaji_blend.h).
bool usesRotationLogs(BlendMethod method);

/// What a method needs to parametrise the examples once.
struct BlendInput {
  const TetMesh* rest = nullptr;                    ///< #V vertices, #T tets
  const RestTetData* restData = nullptr;            ///< from restTetData(*rest)
  const std::vector<Vertices>* examples = nullptr;  ///< n examples, #V by 3 each
  /// n fields of #T deformation gradients F_kj (deformationGradients()).
  const std::vector<std::vector<Eigen::Matrix3d>>* gradients = nullptr;
  const TetAdjacency* adjacency = nullptr;    ///< face adjacency of rest->tets
  const TetComponents* components = nullptr;  ///< its components
  /// Choose each tet's rotation logarithm closest to its neighbour's
  /// (rotation_consistency.h); false takes principal logarithms.
  bool rotationConsistency = true;
};

/// Tets per chunk of a prepared method's blend: blendTargets blends the fixed
/// ranges [c kTetMapChunk, min((c + 1) kTetMapChunk, #T)), and blendRange
/// gives bitwise the same maps for the same ranges (a batched method's
/// rounding may depend on a tet's place in its batch).
constexpr int kTetMapChunk = 1024;

/// A method prepared for one rest mesh and its examples.
class TetMapBlender {
 public:
  virtual ~TetMapBlender() = default;
  /// The method this object implements.
  virtual BlendMethod method() const = 0;
  /// Number of tets #T and of examples n it was prepared for.
  virtual int tetCount() const = 0;
  virtual int exampleCount() const = 0;
  /// Writes the target linear maps B_j (3 by 3) of tets j in [begin, end)
  /// into out[0 .. end - begin) for `weights` (one per example, finite
  /// reals). Sequential; safe to call concurrently on disjoint ranges. Throws
  /// InputError for a wrong weight count or a range outside [0, #T], and
  /// DomainError naming the tet where the method cannot blend these weights.
  /// Pass the chunks of kTetMapChunk for results identical to blendTargets.
  void blendRange(const std::vector<double>& weights, int begin, int end,
                  Eigen::Matrix3d* out) const;
  /// Writes the #T target linear maps B_j (3 by 3) for `weights` (one per
  /// example, any reals) into `targets` (resized): blendRange on every chunk
  /// of kTetMapChunk tets, in parallel, deterministic. Throws InputError for a
  /// wrong weight count and DomainError naming the tet where the method
  /// cannot blend these weights.
  void blendTargets(const std::vector<double>& weights,
                    std::vector<Eigen::Matrix3d>& targets) const;

 protected:
  /// blendRange after its checks: 0 <= begin <= end <= #T and n weights.
  virtual void blendChunk(const std::vector<double>& weights, int begin, int end,
                          Eigen::Matrix3d* out) const = 0;
};

/// Parametrises the examples of `input` once for `method` (all but
/// kVertexLinear, which has no per-tet maps: InputError). Throws DomainError
/// naming the example and tet where an example map has no parameters in the
/// method (e.g. alexa without a real logarithm).
std::unique_ptr<TetMapBlender> prepareTetMapBlender(BlendMethod method, const BlendInput& input);

/// Throws InputError unless `weights` has `exampleCount` finite entries.
void checkWeights(const std::vector<double>& weights, int exampleCount);

}  // namespace tetblend
