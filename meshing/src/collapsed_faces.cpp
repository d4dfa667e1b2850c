#include "tetblend/meshing/collapsed_faces.h"

#include <vector>

#include <Eigen/Geometry>

namespace tetblend {
namespace {

// A face counts as collapsed below this area relative to the squared
// bounding-box diagonal (collapsedFaces).
constexpr double kCollapsedArea = 1e-12;

// Per triangle: whether its area in `v` is below kCollapsedArea times the
// squared diagonal of `v`'s bounding box (or not a number).
std::vector<char> collapsedIn(const Vertices& v, const Triangles& triangles) {
  const double diagonal = (v.colwise().maxCoeff() - v.colwise().minCoeff()).norm();
  const double floor = kCollapsedArea * diagonal * diagonal;
  std::vector<char> small(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Eigen::RowVector3d a = v.row(triangles(f, 0));
    const Eigen::RowVector3d e1 = v.row(triangles(f, 1)) - a, e2 = v.row(triangles(f, 2)) - a;
    small[static_cast<std::size_t>(f)] = !(0.5 * e1.cross(e2).norm() > floor);
  }
  return small;
}

}  // namespace

std::vector<int> collapsedFaces(const Vertices& reference, const Vertices& pose,
                                const Triangles& triangles) {
  const std::vector<char> inReference = collapsedIn(reference, triangles);
  const std::vector<char> inPose = collapsedIn(pose, triangles);
  std::vector<int> result;
  for (std::size_t f = 0; f < inReference.size(); ++f) {
    if (inPose[f] && !inReference[f]) result.push_back(static_cast<int>(f));
  }
  return result;
}

}  // namespace tetblend
