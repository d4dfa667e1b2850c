#pragma once
// C^1 interpolation of a sequence of Lie bodies (Bansal & Tatu §4.1, after
// Li & Hao 2006), per component of M = SE(3) x G_A x R+ (lie_bodies.h):
//
//   N_i(t) = p_i exp(t B_i) exp(t^2 C_i),   t in [0, 1], i = 0 .. n-1,
//   C_i     = log(exp(-B_i) p_i^-1 p_{i+1})                      (eq. 5),
//   B_{i+1} = p_{i+1}^-1 p_i B_i p_i^-1 p_{i+1} + 2 C_i
//           = exp(-C_i) B_i exp(C_i) + 2 C_i                     (eq. 6),
//   B_0     = log(p_0^-1 p_1)        (the paper's choice in its experiments).
//
// N_i(0) = p_i, N_i(1) = p_{i+1}, and d/dt N_i(1) = d/dt N_{i+1}(0): the curve
// is continuous with a continuous first derivative at every key. With two
// keys it is the geodesic of eq. 4. Logarithms are principal (rotation angle
// of each step at most pi).

#include <vector>

#include "tetblend/core/lie_bodies.h"

namespace tetblend {

class LieBodySpline {
 public:
  /// Builds B_i, C_i for `keys` (at least 2; else InputError). Throws
  /// DomainError if a key is not a valid Lie body.
  explicit LieBodySpline(std::vector<LieBody> keys);

  /// Number of segments n = keys - 1.
  int segmentCount() const { return static_cast<int>(keys_.size()) - 1; }

  /// The curve at parameter u: segment i = floor(u) clamped to [0, n-1],
  /// local t = u - i, so key k sits at u = k; u outside [0, n] extrapolates
  /// the first or last segment.
  LieBody evaluate(double u) const;

  /// B_i of segment i in [0, n-1] (eq. 6): the tangent whose exponential
  /// carries key i along its segment; C_i is the remaining log of eq. 5.
  const LieBodyTangent& segmentVelocity(int i) const { return b_.at(i); }

  /// Corners of the tet of evaluate(u).
  TetCorners evaluateCorners(double u) const;

 private:
  std::vector<LieBody> keys_;
  std::vector<LieBodyTangent> b_;
  std::vector<LieBodyTangent> c_;
};

}  // namespace tetblend
