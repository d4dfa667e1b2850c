// The only CGAL translation unit of tetblend (see meshing/CMakeLists.txt).
#include "tetblend/meshing/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <string>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

class SoupIntersector {
 public:
  SoupIntersector(const Vertices& vertices, const Triangles& triangles) : triangles_(triangles) {
    points_.reserve(static_cast<std::size_t>(vertices.rows()));
    for (Eigen::Index i = 0; i < vertices.rows(); ++i) {
      points_.emplace_back(vertices(i, 0), vertices(i, 1), vertices(i, 2));
    }
  }

  bool usable(int f) const {
    const auto t = triangles_.row(f);
    if (t(0) == t(1) || t(1) == t(2) || t(0) == t(2)) return false;
    return !CGAL::collinear(point(f, 0), point(f, 1), point(f, 2));
  }

  Box box(int f) const {
    const CGAL::Bbox_3 b = point(f, 0).bbox() + point(f, 1).bbox() + point(f, 2).bbox();
    return Box(b, f);
  }

  // True when faces f and g intersect other than along shared vertices/edges.
  bool intersect(int f, int g) const {
    // Corners of f that are also corners of g: positions in f and in g.
    std::array<int, 3> inF{}, inG{};
    int shared = 0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (triangles_(f, i) == triangles_(g, j)) {
          inF[shared] = i;
          inG[shared] = j;
          ++shared;
        }
      }
    }
    if (shared == 0) return CGAL::do_intersect(triangle(f), triangle(g));
    if (shared == 1) {
      const int i = inF[0], j = inG[0];
      const Segment oppositeF(point(f, (i + 1) % 3), point(f, (i + 2) % 3));
      const Segment oppositeG(point(g, (j + 1) % 3), point(g, (j + 2) % 3));
      return CGAL::do_intersect(oppositeF, triangle(g)) ||
             CGAL::do_intersect(oppositeG, triangle(f));
    }
    if (shared == 2) {
      const Point& p = point(f, inF[0]);
      const Point& q = point(f, inF[1]);
      const Point& r = point(f, 3 - inF[0] - inF[1]);
      const Point& s = point(g, 3 - inG[0] - inG[1]);
      return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
    }
    return false;  // same three vertices: a duplicate face, reported elsewhere
  }

 private:
  const Point& point(int f, int corner) const {
    return points_[static_cast<std::size_t>(triangles_(f, corner))];
  }
  Triangle triangle(int f) const { return Triangle(point(f, 0), point(f, 1), point(f, 2)); }

  const Triangles& triangles_;
  std::vector<Point> points_;
};

// The intersecting pairs of faces, all of them or (with `faceGroup`) those
// of faces in the same group.
SelfIntersections intersectingPairs(const Vertices& vertices, const Triangles& triangles,
                                    std::size_t maxReportedPairs,
                                    const std::vector<int>* faceGroup) {
  const SoupIntersector soup(vertices, triangles);
  std::vector<Box> boxes;
  boxes.reserve(static_cast<std::size_t>(triangles.rows()));
  for (int f = 0; f < static_cast<int>(triangles.rows()); ++f) {
    if (soup.usable(f)) boxes.push_back(soup.box(f));
  }
  std::vector<std::pair<int, int>> found;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const int f = std::min(a.info(), b.info());
    const int g = std::max(a.info(), b.info());
    if (faceGroup &&
        (*faceGroup)[static_cast<std::size_t>(f)] != (*faceGroup)[static_cast<std::size_t>(g)]) {
      return;
    }
    if (soup.intersect(f, g)) found.emplace_back(f, g);
  });
  std::sort(found.begin(), found.end());
  SelfIntersections result;
  result.pairCount = found.size();
  found.resize(std::min(found.size(), maxReportedPairs));
  result.pairs = std::move(found);
  return result;
}

}  // namespace

SelfIntersections findSelfIntersections(const Vertices& vertices, const Triangles& triangles,
                                        std::size_t maxReportedPairs) {
  return intersectingPairs(vertices, triangles, maxReportedPairs, nullptr);
}

SelfIntersections findSelfIntersections(const Vertices& vertices, const Triangles& triangles,
                                        std::size_t maxReportedPairs,
                                        const std::vector<int>& faceGroup) {
  if (faceGroup.size() != static_cast<std::size_t>(triangles.rows())) {
    throw InputError("findSelfIntersections: " + std::to_string(faceGroup.size()) +
                     " face groups for " + std::to_string(triangles.rows()) + " faces");
  }
  return intersectingPairs(vertices, triangles, maxReportedPairs, &faceGroup);
}

}  // namespace tetblend
