// The hard-pose corpus of pose_corpus.h, composed from the procedural
// deformations of procedural_shapes.h.

#include "tetblend/meshing/pose_corpus.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

constexpr double kDegree = kPi / 180.0;
// A bend keeps its arc radius this many times the half-thickness in the bend
// direction, so the inner side is compressed but never turned inside out.
constexpr double kBendRadiusMargin = 1.25;
// Noise amplitude of noisyTwist360, relative to the mean surface edge.
constexpr double kNoiseRelative = 0.15;

// The bounding box's axes sorted by extent, longest first, with its centre.
struct BoxFrame {
  Eigen::Vector3d centre;
  std::array<Eigen::Vector3d, 3> axes;  // unit coordinate axes, longest first
  std::array<double, 3> extents;        // matching extents
};

BoxFrame boxFrame(const Vertices& rest) {
  const Eigen::RowVector3d low = rest.colwise().minCoeff();
  const Eigen::RowVector3d high = rest.colwise().maxCoeff();
  BoxFrame frame;
  frame.centre = 0.5 * (low + high).transpose();
  std::array<int, 3> order{0, 1, 2};
  const Eigen::RowVector3d extent = high - low;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return extent(a) > extent(b); });
  for (int i = 0; i < 3; ++i) {
    frame.axes[i] = Eigen::Vector3d::Unit(order[i]);
    frame.extents[i] = extent(order[i]);
  }
  if (!(frame.extents[0] > 0.0) || !std::isfinite(frame.extents[0])) {
    throw InputError("hardPoses: the vertices are not finite or all equal");
  }
  return frame;
}

double meanEdgeLength(const Vertices& vertices, const Triangles& triangles) {
  double total = 0.0;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      total += (vertices.row(triangles(f, c)) - vertices.row(triangles(f, (c + 1) % 3))).norm();
    }
  }
  return triangles.rows() > 0 ? total / (3.0 * static_cast<double>(triangles.rows())) : 0.0;
}

Vertices skinned(const Vertices& rest, const BoxFrame& box, const Eigen::Vector3d& axis,
                 double angle, double halfWidth, bool dualQuaternion) {
  const Eigen::Vector3d along = box.axes[0];
  const Eigen::MatrixXd weights = twoBoneWeights(rest, box.centre, along, halfWidth);
  const std::vector<Eigen::Isometry3d> bones = {Eigen::Isometry3d::Identity(),
                                                rotationAboutLine(box.centre, axis, angle)};
  return dualQuaternion ? dualQuaternionSkinning(rest, weights, bones)
                        : linearBlendSkinning(rest, weights, bones);
}

Vertices affine(const Vertices& rest, const BoxFrame& box, const Eigen::Matrix3d& map) {
  Vertices result(rest.rows(), 3);
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    result.row(v) = (box.centre + map * (rest.row(v).transpose() - box.centre)).transpose();
  }
  return result;
}

// Shear along axes[1] growing linearly along axes[0], and the section scaled
// from 1 at the near end to 0.4 at the far end.
Vertices taperedShear(const Vertices& rest, const BoxFrame& box) {
  const double length = box.extents[0];
  Vertices result(rest.rows(), 3);
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    const Eigen::Vector3d p = rest.row(v).transpose() - box.centre;
    const double s = p.dot(box.axes[0]) / length + 0.5;  // 0 .. 1 along the length
    const double taper = 1.0 - 0.6 * s;
    Eigen::Vector3d q = p.dot(box.axes[0]) * box.axes[0];
    q += taper * (p.dot(box.axes[1]) * box.axes[1] + p.dot(box.axes[2]) * box.axes[2]);
    q += 0.6 * s * s * length * box.axes[1];
    result.row(v) = (box.centre + q).transpose();
  }
  return result;
}

}  // namespace

std::vector<std::string> hardPoseNames() {
  return {"twist720", "twist1080", "dqsTwist300",  "dqsBend170",   "lbsBend90",
          "bend180",  "shear",     "taperedShear", "noisyTwist360"};
}

std::vector<NamedPose> hardPoses(const Vertices& rest, const Triangles& triangles,
                                 std::uint64_t seed) {
  const BoxFrame box = boxFrame(rest);
  const double length = box.extents[0];
  const Eigen::Vector3d start = box.centre - 0.5 * length * box.axes[0];
  std::vector<NamedPose> poses;
  poses.push_back({"twist720", twistAboutAxis(rest, start, box.axes[0], 4 * kPi, length)});
  poses.push_back({"twist1080", twistAboutAxis(rest, start, box.axes[0], 6 * kPi, length)});
  poses.push_back({"dqsTwist300", skinned(rest, box, box.axes[0], 300 * kDegree, 0.25 * length,
                                          /*dualQuaternion=*/true)});
  poses.push_back({"dqsBend170", skinned(rest, box, box.axes[1], 170 * kDegree, 0.0625 * length,
                                         /*dualQuaternion=*/true)});
  poses.push_back({"lbsBend90", skinned(rest, box, box.axes[1], 90 * kDegree, 0.0625 * length,
                                        /*dualQuaternion=*/false)});
  // Bend towards the thinnest axis, the arc radius kept above the
  // half-thickness (a half circle when the shape is slender enough).
  const double halfThickness = 0.5 * box.extents[2];
  const double bendAngle = std::min(kPi, length / (kBendRadiusMargin * halfThickness));
  poses.push_back(
      {"bend180", bendAboutAxis(rest, start, box.axes[0], box.axes[2], bendAngle, length)});
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear += 0.8 * box.axes[1] * box.axes[0].transpose();
  shear =
      shear * (1.3 * box.axes[0] * box.axes[0].transpose() + box.axes[1] * box.axes[1].transpose() +
               0.7 * box.axes[2] * box.axes[2].transpose());
  poses.push_back({"shear", affine(rest, box, shear)});
  poses.push_back({"taperedShear", taperedShear(rest, box)});
  Vertices noisy = twistAboutAxis(rest, start, box.axes[0], 2 * kPi, length);
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double amplitude = kNoiseRelative * meanEdgeLength(rest, triangles);
  for (Eigen::Index v = 0; v < noisy.rows(); ++v) {
    for (int c = 0; c < 3; ++c) noisy(v, c) += amplitude * uniform(generator);
  }
  poses.push_back({"noisyTwist360", std::move(noisy)});
  return poses;
}

}  // namespace tetblend
