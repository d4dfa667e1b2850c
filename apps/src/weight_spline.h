#pragma once
// Curves through key weight vectors for `tetblend animate`.
//
// Kaji–Ochiai §6.3 interpolates poses by any Euclidean spline in their
// parameter space, A(t) = phi(Interpolate(t, {psi(A_j)})). The shape blender
// maps weights to parameters linearly (Blend, §5: sum_i w_i psi(A_ij)), and
// every spline below is a fixed linear combination of its knots, so splining
// the key weight vectors and blending is the same as splining the per-tet
// parameters: the curve is built in weight space and costs nothing extra.

#include <string>
#include <vector>

namespace tetblend::cli {

/// The kinds of curve through the keys.
enum class SplineKind {
  kLinear,      ///< piecewise linear, passes through every key
  kCatmullRom,  ///< uniform Catmull–Rom (C1), passes through every key;
                ///< end tangents by repeating the end keys
  kBSpline,     ///< uniform cubic B-spline (C2), approximates the inner keys;
                ///< end keys tripled so the curve starts and ends on them
};

/// Parses "linear", "catmull-rom" or "bspline"; InputError otherwise.
SplineKind parseSplineKind(const std::string& name);

/// The curve through `keys` (m >= 1 vectors of one length) evaluated at
/// `frames` >= 1 parameters spread evenly from the first key (frame 0) to the
/// last (frame frames-1). Returns frames vectors.
std::vector<std::vector<double>> splineFrames(const std::vector<std::vector<double>>& keys,
                                              int frames, SplineKind kind);

}  // namespace tetblend::cli
