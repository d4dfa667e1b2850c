#pragma once
// Consistent rotation parameters over a tet mesh: Kaji–Ochiai §4.3, Alg. 1
// (so3LogClosest) propagated breadth-first over face adjacency, so that a bar
// twisted by 4 pi keeps its two turns in parameter space (a principal
// logarithm would see only the rotation modulo 2 pi in each tet), extended by
// a lift for the rotations that have no logarithm on the continued branch.
//
// Why the lift: in a twisted bar a tet's polar rotation is
// R = R_axis(theta) R_tilt(alpha h), the tilt alpha ~ twist rate * radius / 2
// about a horizontal axis h coming from the twist shear. Where theta is a
// non-zero multiple of 2 pi, R = R_tilt and all its logarithms
// (alpha + 2 pi k) h lie along h, far from the continuous ~2 pi axis: the
// exponential map is singular there (its right Jacobian at 2 pi a is a a^T),
// so no logarithm can follow the turns. Such a tet is represented as
// R = exp(base) exp(correction) with `base` the continuous prediction and
// `correction` the small principal log of exp(base)^T R.

#include <Eigen/Core>
#include <vector>

#include "tetblend/blending/tet_adjacency.h"

namespace tetblend {

/// A rotation R (3 by 3, SO(3)) as R = exp(base) exp(correction) exactly
/// (to round-off), both rotation vectors in radians. `base` may be any
/// length (e.g. ~4 pi along a twist axis); `correction` is a principal
/// logarithm (|correction| <= pi). correction = 0 means base is an exact
/// logarithm of R (the plain Kaji–Ochiai case).
struct RotationLift {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  Eigen::Vector3d correction = Eigen::Vector3d::Zero();
};

/// Lifts of #T per-tet rotations (3 by 3, SO(3)); `adjacency` and
/// `components` describe the same #T tets.
/// Consistent: in each face-connected component the seed is the tet with the
/// smallest principal rotation angle (lowest index on ties), lifted to its
/// principal logarithm; every other tet, reached breadth-first from the seed,
/// gets a prediction: its parent's prediction plus the principal log of the
/// relative rotation R_parent^T R_tet. If the logarithm of R_tet closest to the
/// prediction (Kaji–Ochiai Alg. 1) lies within pi/2 of it (same branch), the
/// lift is {that logarithm, 0} and the prediction snaps to it; otherwise
/// (e.g. I + tilt inside a 2 pi twist) the lift is {prediction,
/// log(exp(prediction)^T R_tet)} and the prediction is passed on unchanged.
/// Not consistent: {principal logarithm, 0}.
/// Blending lifts linearly, R(w) = exp(sum_k w_k base_k) exp(sum_k w_k
/// correction_k), reproduces each example at unit weights, gives I at zero
/// weights, and is Kaji–Ochiai's blend (eq. (2)) wherever corrections are 0.
std::vector<RotationLift> rotationLifts(const std::vector<Eigen::Matrix3d>& rotations,
                                        const TetAdjacency& adjacency,
                                        const TetComponents& components, bool consistent);

/// One rotation vector per tet (radians), base + correction of rotationLifts:
/// an exact logarithm where the correction is 0, elsewhere a continuous
/// first-order stand-in (for analyses that need a single vector per tet, such
/// as a principal component analysis of the parameters; blending uses the
/// lifts themselves).
std::vector<Eigen::Vector3d> rotationLogs(const std::vector<Eigen::Matrix3d>& rotations,
                                          const TetAdjacency& adjacency,
                                          const TetComponents& components, bool consistent);

}  // namespace tetblend
