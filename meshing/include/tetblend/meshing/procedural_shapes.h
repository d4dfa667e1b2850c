#pragma once
// Procedural tetrahedral meshes and procedural deformations of their vertices:
// the test shapes of the project (bars, cylinders, limbs) and the large
// deformations the blending methods must survive (twists beyond 2π, 180°
// bends, skinned limbs at 170°; Kaji–Ochiai §6.2 Fig. 2, Kavan et al. §4).
// Eigen only: no CGAL, no VTK, no TetGen.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tetblend/core/mesh_types.h"

namespace tetblend {

/// Structured grid of nx*ny*nz cubes spanning the box [-size/2, size/2]
/// (centred at the origin, units of `size`), each cube split into 6 tets
/// along its main diagonal (Freudenthal/Kuhn split), so neighbouring cubes
/// agree on every shared face: the mesh is conforming. Vertex (i,j,k) has
/// index i + (nx+1)*(j + (ny+1)*k). Every tet is positively oriented.
/// Returns (nx+1)(ny+1)(nz+1) vertices and 6*nx*ny*nz tets.
/// Throws InputError if a count is < 1 or a size component is <= 0.
TetMesh boxTetMesh(int nx, int ny, int nz, const Eigen::Vector3d& size);

/// Solid circular cylinder with axis along x, centred at the origin, spanning
/// x in [-length/2, length/2], radius `radius`. The disc section is a
/// hexagonal-ring triangulation (centre plus `rings` concentric rings, ring r
/// having 6r vertices on a circle of radius radius*r/rings), extruded into
/// `layers` prism layers, each prism split into 3 tets by the global-vertex-
/// order rule (conforming). Every tet is positively oriented. Its volume
/// converges to π radius² length from below (the section is a polygon
/// inscribed in the circle). Throws InputError on a count < 1 or a size <= 0.
TetMesh cylinderTetMesh(int rings, int layers, double radius, double length);

/// Area of the polygonal disc section used by cylinderTetMesh (rings >= 1,
/// units of radius²): the exact section area, so volume = area * length.
double cylinderSectionArea(int rings, double radius);

/// Twists `vertices` (#V by 3) about the line through `origin` along
/// `direction` (normalised here): a point at signed axial distance s from
/// `origin` rotates by angle totalAngle * s / length (radians, right-hand rule
/// about `direction`). Any angle is allowed, e.g. 4π over the bar's length.
/// Throws InputError if `direction` is zero or length <= 0.
Vertices twistAboutAxis(const Vertices& vertices, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& direction, double totalAngle, double length);

/// Bends a bar lying along `lengthDirection` (from `origin`, axial coordinate
/// s in [0, length]) into a circular arc of total angle `totalAngle`
/// (radians, e.g. π for a U shape), curving towards `bendDirection`
/// (orthogonalised against `lengthDirection`). The neutral fibre (through
/// `origin` along `lengthDirection`) keeps its length; the arc radius is
/// R = length / totalAngle, and a point at offset y towards the centre lands
/// at radius R - y, so R must exceed the bar's half-thickness. Points with
/// s < 0 or s > length continue along the end tangents (rigidly).
/// totalAngle = 0 returns the input. Throws InputError on zero directions
/// or length <= 0.
Vertices bendAboutAxis(const Vertices& vertices, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& lengthDirection, const Eigen::Vector3d& bendDirection,
                       double totalAngle, double length);

/// Skinning weights of a two-bone limb (#V by 2, rows sum to 1): bone 0 on the
/// side of `joint` opposite to `boneDirection`, bone 1 along it. The weight of
/// bone 1 is a C¹ smoothstep of the axial coordinate s = (p - joint)·d over
/// [-blendHalfWidth, blendHalfWidth] (0 before, 1 after). blendHalfWidth > 0.
Eigen::MatrixXd twoBoneWeights(const Vertices& vertices, const Eigen::Vector3d& joint,
                               const Eigen::Vector3d& boneDirection, double blendHalfWidth);

/// Rigid motion that rotates by `angle` (radians) about the line through
/// `joint` along `axis` (normalised here): a bone pose for the skinning below.
Eigen::Isometry3d rotationAboutLine(const Eigen::Vector3d& joint, const Eigen::Vector3d& axis,
                                    double angle);

/// Linear blend skinning: p' = Σ_b w(p,b) T_b p. `weights` is #V by #B,
/// `bones` has #B rigid motions. Throws InputError on mismatched sizes.
Vertices linearBlendSkinning(const Vertices& vertices, const Eigen::MatrixXd& weights,
                             const std::vector<Eigen::Isometry3d>& bones);

/// Dual-quaternion skinning (Kavan et al., DLB of §3.4 applied per vertex as
/// in §4): blend the bones' unit dual quaternions with the weights, each sign
/// aligned with the first bone's quaternion (shortest path), normalise, apply.
/// Same shapes and errors as linearBlendSkinning.
Vertices dualQuaternionSkinning(const Vertices& vertices, const Eigen::MatrixXd& weights,
                                const std::vector<Eigen::Isometry3d>& bones);

}  // namespace tetblend
