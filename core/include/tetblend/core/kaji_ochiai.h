#pragma once
// The Kaji–Ochiai parametrisation of Aff+(3) (Kaji & Ochiai, "A concise
// parametrisation of affine transformation"): the 12-dimensional Euclidean
// parameter space R^3 x so(3) x sym(3), the map phi (eq. (2)) to 4x4
// homogeneous matrices, its inverse psi (eq. (3)) with the consistent rotation
// logarithm (Alg. 1), Blend (§5) and the refined weighted Fréchet sum (Alg. 2).

#include <Eigen/Core>

#include <vector>

namespace tetblend {

/// A point of R^3 x so(3) x sym(3). Plain vector space: every value is valid.
struct AffineParams {
  Eigen::Vector3d translation;  ///< L, in the length unit of the maps.
  Eigen::Vector3d rotationLog;  ///< X = hat(rotationLog), radians.
  Eigen::Matrix3d stretchLog;   ///< Y, symmetric, dimensionless.

  /// The parameters of the identity map.
  static AffineParams Zero() {
    return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()};
  }
  AffineParams& operator+=(const AffineParams& o) {
    translation += o.translation;
    rotationLog += o.rotationLog;
    stretchLog += o.stretchLog;
    return *this;
  }
  AffineParams& operator-=(const AffineParams& o) {
    translation -= o.translation;
    rotationLog -= o.rotationLog;
    stretchLog -= o.stretchLog;
    return *this;
  }
  AffineParams& operator*=(double s) {
    translation *= s;
    rotationLog *= s;
    stretchLog *= s;
    return *this;
  }
};

inline AffineParams operator+(AffineParams a, const AffineParams& b) { return a += b; }
inline AffineParams operator-(AffineParams a, const AffineParams& b) { return a -= b; }
inline AffineParams operator-(AffineParams a) { return a *= -1.0; }
inline AffineParams operator*(double s, AffineParams a) { return a *= s; }
inline AffineParams operator*(AffineParams a, double s) { return a *= s; }

/// phi(L, X, Y) = L iota(exp(X) exp(Y)) (eq. (2)): 4x4 homogeneous matrix with
/// top-left block so3Exp(rotationLog) * symExp(stretchLog), last column the
/// translation, bottom row (0 0 0 1). Finite whenever the result is
/// representable; throws DomainError (from symExp) naming the largest
/// eigenvalue of the stretch log if it overflows double.
Eigen::Matrix4d phi(const AffineParams& params);

/// psi(A) = (rho(A), log(R), log(S)) with A_hat = R S the polar decomposition
/// (eq. (3)); the rotation log is principal (angle in [0, pi]). A is 4x4
/// homogeneous; its bottom row is not read. Any scale: psi(c A) = psi(A) +
/// (0, 0, log(c) I) for every c > 0 the double range holds (polarDecomposeLog
/// rescales by a power of two). Throws DomainError if det A_hat <= 0.
AffineParams psi(const Eigen::Matrix4d& a);

/// psi(A) with the rotation log closest to `rotationReference` (Alg. 1), so
/// that rotations by more than 2 pi stay representable along a chain of
/// references (neighbouring elements, previous frame). Throws InputError if
/// the reference is not finite, DomainError like psi(a).
AffineParams psi(const Eigen::Matrix4d& a, const Eigen::Vector3d& rotationReference);

/// Weighted sum sum_i w_i p_i in the parameter space (the argument of phi in
/// Blend). Weights need not sum to 1: the identity implicitly takes the rest.
/// Throws InputError if the two vectors differ in size.
AffineParams weightedSum(const std::vector<double>& weights,
                         const std::vector<AffineParams>& params);

/// Blend(w, A) = phi(sum_i w_i psi(A_i)) (§5), given the psi(A_i).
/// Throws InputError if the two vectors differ in size.
Eigen::Matrix4d kajiBlend(const std::vector<double>& weights,
                          const std::vector<AffineParams>& params);

/// Options of the refined weighted Fréchet sum.
struct FrechetBlendOptions {
  /// Stop when the Frobenius norm of the mean log step W (radians for the
  /// rotation, log-stretch units for the stretch) is at most this. Default
  /// 1e-12: the iteration converges linearly, so this is a few ulps above the
  /// attainable accuracy of unit-scale logs.
  double tolerance = 1e-12;
  /// Cap on the iterations of each of the two loops (rotation, stretch).
  /// Default 100; well-clustered inputs need fewer than 20.
  int maxIterations = 100;
};

/// Result of the refined weighted Fréchet sum.
struct FrechetBlendResult {
  Eigen::Matrix4d matrix;  ///< L Z_R Z_S, 4x4 homogeneous.
  int iterations = 0;      ///< Rotation plus stretch iterations used.
  bool converged = false;  ///< Both loops reached the tolerance.
};

/// Refined weighted Fréchet sum (Alg. 2, after Manton): the rotation mean
/// Z_R and the stretch mean Z_S are iterated separately to the weighted
/// Karcher means sum_i w_i log(Z^{-1} X_i) = 0 under the bi-invariant metric of
/// SO(3) and the affine-invariant metric of Sym+(3) (the stretch step uses the
/// symmetric form Z^{1/2} exp(sum w_i log(Z^{-1/2} S_i Z^{-1/2})) Z^{1/2} so Z_S
/// stays symmetric), the translation is sum_i w_i rho(A_i). The rotation loop
/// starts at the input of largest weight (Alg. 2: A_1), the stretch loop at
/// the Blend of the stretches (Sym+(3) has a unique mean). As in Blend, the
/// identity takes the weight
/// 1 - sum_i w_i. Inputs are 4x4 homogeneous with det > 0 (DomainError
/// otherwise); InputError if the sizes differ.
FrechetBlendResult kajiFrechetBlend(const std::vector<double>& weights,
                                    const std::vector<Eigen::Matrix4d>& transforms,
                                    const FrechetBlendOptions& options = {});

/// Subgroups of Aff+(3) that the parametrisation restricts to (property (V),
/// §3): their parameters are linear subspaces, so Blend is closed in each.
enum class AffineSubgroup {
  Translation,  ///< (L, 0, 0): R^3.
  Rotation,     ///< (0, X, 0): SO(3).
  Stretch,      ///< (0, 0, Y): Sym+(3).
  Rigid,        ///< (L, X, 0): SE(3).
  Similarity,   ///< (L, X, c I): Sim+(3).
  General,      ///< (L, X, Y): Aff+(3).
};

/// Orthogonal projection of the parameters onto the subspace of `subgroup`
/// (drops components; Similarity keeps the trace part (tr Y / 3) I of Y).
AffineParams projectToSubgroup(const AffineParams& params, AffineSubgroup subgroup);

/// Whether `params` lies in the subspace of `subgroup`: every component the
/// projection drops is at most `tolerance` in absolute value (translation in
/// length units, logs dimensionless).
bool inSubgroup(const AffineParams& params, AffineSubgroup subgroup, double tolerance);

}  // namespace tetblend
