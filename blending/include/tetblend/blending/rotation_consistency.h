#pragma once
// Consistent rotation logarithms over a tet mesh: Kaji–Ochiai §4.3, Alg. 1
// (so3LogClosest) propagated breadth-first over face adjacency, so that a bar
// twisted by 4 pi keeps its two turns in parameter space (a principal
// logarithm would see only the rotation modulo 2 pi in each tet).

#include <Eigen/Core>
#include <vector>

#include "tetblend/blending/tet_adjacency.h"

namespace tetblend {

/// Rotation vectors (radians) of #T per-tet rotations (3 by 3, SO(3)).
/// Consistent: in each face-connected component the seed is the tet with the
/// smallest principal rotation angle (lowest index on ties), which takes its
/// principal logarithm; every other tet, reached breadth-first from the seed,
/// takes the logarithm closest (Kaji–Ochiai Alg. 1) to a prediction: its
/// parent's prediction plus the principal log of the relative rotation
/// R_parent^T R_tet. The prediction snaps to the chosen logarithm when they
/// are within pi/2 (same branch); otherwise (a rotation with no logarithm on
/// the continued branch, e.g. I + tilt inside a 2 pi twist) the tet keeps its
/// closest logarithm and passes the prediction on, so one such tet does not
/// drop the turns of everything reached through it. Not consistent: principal
/// logarithms (|omega| <= pi).
/// `adjacency` and `components` describe the same #T tets.
std::vector<Eigen::Vector3d> rotationLogs(const std::vector<Eigen::Matrix3d>& rotations,
                                          const TetAdjacency& adjacency,
                                          const TetComponents& components, bool consistent);

}  // namespace tetblend
