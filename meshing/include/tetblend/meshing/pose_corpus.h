#pragma once
// Hard poses of an arbitrary surface, generated procedurally: the corpus that
// tests and benchmarks hold `prepare` to (issue "prepare every pose users
// bring"). Each pose moves the vertices only; the triangles are the rest's.
// The deformations are the ones real data shows and the seeds' figures use:
// twists of several turns (Kaji–Ochiai Fig. 2), dual-quaternion and linear
// blend skinned limbs (Kavan et al. §4), bends, shears, and small noise.
// Some poses of some shapes self-intersect (a thin arm twisted by 1080°
// wraps into its neighbour); the caller checks the surface to know which.

#include <cstdint>
#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// One generated pose: its name (e.g. "twist720") and #V by 3 positions.
struct NamedPose {
  std::string name;
  Vertices vertices;
};

/// The poses of hardPoses, by name, in the order they are returned.
///   twist720, twist1080  twist about the longest bounding-box axis through
///                        the box centre, 4π and 6π end to end;
///   dqsTwist300          two bones split at the centre, the far one turned
///                        300° about that axis, dual-quaternion skinned
///                        (smoothstep weights over half the length);
///   dqsBend170           the far bone turned 170° about the second-longest
///                        axis, dual-quaternion skinned (blend over 1/8 of
///                        the length);
///   lbsBend90            the same joint turned 90°, linear blend skinned;
///   bend180              the length bent into a half circle (U);
///   shear                an affine map with shear 0.8 and scale 1.3 / 0.7;
///   taperedShear         shear growing along the length, section tapered
///                        to 40 % at the far end;
///   noisyTwist360        a 2π twist plus seeded noise of 15 % of the mean
///                        edge length per vertex.
std::vector<std::string> hardPoseNames();

/// All poses above for `rest` (#V by 3, #V >= 1, finite, not all equal).
/// Deterministic: the noise comes from `seed`. `triangles` (#F by 3) give
/// the mean edge length for the noise.
std::vector<NamedPose> hardPoses(const Vertices& rest, const Triangles& triangles,
                                 std::uint64_t seed = 1);

}  // namespace tetblend
