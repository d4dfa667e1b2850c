// The only CGAL translation unit of tetblend (see meshing/CMakeLists.txt).
#include "tetblend/meshing/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;
using Interval = CGAL::Interval_nt<false>;  // under Protect_FPU_rounding

struct IntervalVector {
  Interval x, y, z;
};

IntervalVector operator-(const Point& a, const Point& b) {
  return {Interval(a.x()) - b.x(), Interval(a.y()) - b.y(), Interval(a.z()) - b.z()};
}

IntervalVector cross(const IntervalVector& a, const IntervalVector& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Interval dot(const IntervalVector& a, const IntervalVector& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// True when every point of `others` lies certainly (interval arithmetic) on
// the far side of the plane through the edge e0 e1 of triangle (e0, e1,
// opposite) that contains the triangle's normal n = e × w (e = e1 − e0,
// w = opposite − e0). The triangle lies on the closed near side: its corners
// measure 0, 0 and (n × e)·w = |n|² ≥ 0 along the plane's normal n × e.
bool farSideOfEdgePlane(const Point& e0, const Point& e1, const Point& opposite,
                        const std::array<const Point*, 3>& others, int count) {
  const IntervalVector edge = e1 - e0;
  const IntervalVector planeNormal = cross(cross(edge, opposite - e0), edge);
  for (int k = 0; k < count; ++k) {
    if (!CGAL::certainly(dot(planeNormal, *others[static_cast<std::size_t>(k)] - e0) < 0)) {
      return false;
    }
  }
  return true;
}

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
    if (certainlyApart(f, g)) return false;
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
  // True when an edge plane of f or g (farSideOfEdgePlane) certainly puts
  // the other's corners that are not on that edge on its far side: the faces
  // then meet at most in the corners they share. Decides in interval
  // arithmetic most pairs that the exact predicates would decide only in
  // exact arithmetic: neighbours in a flat or rigidly moved region are
  // coplanar or nearly so, which the kernel's floating-point filters cannot
  // settle (its exact coplanar orientations took 8 % of bench_meshing's 10 k
  // row).
  bool certainlyApart(int f, int g) const {
    const CGAL::Protect_FPU_rounding<true> upward;
    return edgePlaneSeparates(f, g) || edgePlaneSeparates(g, f);
  }

  // True when the plane through some edge of f containing f's normal has
  // every corner of g off that edge certainly on its far side (a corner g
  // shares with f off the edge lies on the near side, so that edge fails).
  bool edgePlaneSeparates(int f, int g) const {
    for (int i = 0; i < 3; ++i) {
      const int e0 = triangles_(f, i), e1 = triangles_(f, (i + 1) % 3);
      const int opposite = triangles_(f, (i + 2) % 3);
      std::array<const Point*, 3> others{};
      int count = 0;
      for (int j = 0; j < 3; ++j) {
        const int v = triangles_(g, j);
        if (v != e0 && v != e1) others[static_cast<std::size_t>(count++)] = &vertex(v);
      }
      if (count == 0) continue;
      if (farSideOfEdgePlane(vertex(e0), vertex(e1), vertex(opposite), others, count)) return true;
    }
    return false;
  }

  const Point& vertex(int v) const { return points_[static_cast<std::size_t>(v)]; }
  const Point& point(int f, int corner) const { return vertex(triangles_(f, corner)); }
  Triangle triangle(int f) const { return Triangle(point(f, 0), point(f, 1), point(f, 2)); }

  const Triangles& triangles_;
  std::vector<Point> points_;
};

// Candidate pairs tested per TBB task (about 0.3 µs each when interval
// arithmetic decides, microseconds when the exact predicates must).
constexpr std::size_t kPairGrain = 512;

// The intersecting pairs of faces, all of them or (with `faceGroup`) those
// of faces in the same group. The boxes' overlaps are listed first, then
// tested on TBB's threads: the tests took 4.3-7.5 ms of the 6-11 ms per
// example of bench_meshing's 10 k row (scratch timers), and its three
// examples ran on two threads.
SelfIntersections intersectingPairs(const Vertices& vertices, const Triangles& triangles,
                                    std::size_t maxReportedPairs,
                                    const std::vector<int>* faceGroup) {
  const SoupIntersector soup(vertices, triangles);
  std::vector<Box> boxes;
  boxes.reserve(static_cast<std::size_t>(triangles.rows()));
  for (int f = 0; f < static_cast<int>(triangles.rows()); ++f) {
    if (soup.usable(f)) boxes.push_back(soup.box(f));
  }
  std::vector<std::pair<int, int>> candidates;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const int f = std::min(a.info(), b.info());
    const int g = std::max(a.info(), b.info());
    if (faceGroup &&
        (*faceGroup)[static_cast<std::size_t>(f)] != (*faceGroup)[static_cast<std::size_t>(g)]) {
      return;
    }
    candidates.emplace_back(f, g);
  });
  std::vector<char> intersects(candidates.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), kPairGrain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        intersects[i] = soup.intersect(candidates[i].first, candidates[i].second);
                      }
                    });
  std::vector<std::pair<int, int>> found;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (intersects[i]) found.push_back(candidates[i]);
  }
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
