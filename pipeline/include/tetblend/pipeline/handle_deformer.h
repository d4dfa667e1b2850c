#pragma once
// The probe/skinning deformer of `tetblend deform` (Kaji–Ochiai §6.1; Kavan
// et al. §6, skinning): each vertex u moves by a blend of the handles'
// affine transforms A_i with per-vertex weights w_i(u):
//   u -> Blend(w_1(u), ..., w_n(u), A_1, ..., A_n) u.
//
// Handles are given in world coordinates either as a 4x4 matrix or as
// Kaji–Ochiai parameters (translation, rotation vector in radians of any
// length, log-stretch), so a probe turned by 2 pi or more is representable
// (a matrix would forget whole turns; §6.1 Fig. 2).
//
// Weights: given per vertex, or from distance to the handle centres c_i:
//   w~_i(u) = (|u - c_i| + delta)^(-p),  w_i = w~_i / sum_j w~_j,
// with delta = 1e-3 times the mesh's bounding-box diagonal (keeps the weight
// finite at a centre) and falloff exponent p (default 2).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "tetblend/core/kaji_ochiai.h"
#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// One handle: its transform as parameters (phi(params) is its matrix) and
/// the centre used by distance weights.
struct Handle {
  std::string name;
  AffineParams params = AffineParams::Zero();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// The methods that blend handle transforms per vertex.
enum class HandleBlend {
  kLbs,          ///< "lbs": sum_i w_i A_i (linear blend skinning)
  kDqs,          ///< "dq" (alias "dqs"): DLB of the rigid parts' dual quaternions (Kavan
                 ///< §3.4; core's dlb: antipodes aligned with the handle of largest
                 ///< weight); handles must be rigid (no stretch)
  kKaji,         ///< "kaji": phi(sum_i w_i psi(A_i)) (Kaji–Ochiai §5)
  kKajiFrechet,  ///< "kaji-frechet": refined weighted Fréchet sum (Alg. 2)
};

/// Parses "lbs", "dq", "kaji" or "kaji-frechet", or an alias of one
/// (canonicalMethodName: "dqs"); InputError otherwise.
HandleBlend parseHandleBlend(const std::string& name);

/// The names parseHandleBlend takes and their aliases, for help texts:
/// "lbs, dq, kaji, kaji-frechet (dqs = dq)".
std::string handleBlendNames();

/// Handles and optional per-vertex weights read from a JSON file:
///   {"handles": [{"name": "tip", "centre": [x,y,z],
///                 "matrix": [[4 rows of 4]]  or  "translation": [..],
///                 "rotation": [rotation vector, radians], "stretch_log": [[3x3]]}],
///    "weights": [[w_1 .. w_n] per vertex]  (optional)}
struct HandleSpec {
  std::vector<Handle> handles;
  Eigen::MatrixXd weights;  ///< #V by n, or empty when not given
};

/// The spec in JSON `text`; InputError naming `what` (a file name) and the
/// entry at fault.
HandleSpec parseHandleSpec(const std::string& text, const std::string& what);

/// Reads `path` (parseHandleSpec); InputError naming the file and the entry
/// at fault.
HandleSpec readHandleSpec(const std::string& path);

/// Distance weights (see the file comment), #V by n, rows summing to 1.
Eigen::MatrixXd distanceWeights(const Vertices& vertices, const std::vector<Handle>& handles,
                                double falloff);

/// Deformed positions (#V by 3) of `vertices` under `handles` with `weights`
/// (#V by n). DomainError naming the handle for dqs with a non-rigid handle,
/// and naming the vertex where its weights cancel the blended rotation (dlb).
Vertices deformByHandles(const Vertices& vertices, const std::vector<Handle>& handles,
                         const Eigen::MatrixXd& weights, HandleBlend method);

}  // namespace tetblend
