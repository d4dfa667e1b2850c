// A CGAL translation unit (see meshing/CMakeLists.txt).
#include "surface_interior.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_tree/internal/AABB_node.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <initializer_list>
#include <vector>

namespace tetblend {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct SurfaceInterior::Impl {
  Mesh mesh;
  std::vector<Point> points;
  Triangles triangles;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel, CGAL::Default, Tree>> side;
  bool usable = false;  // the surface built as a closed mesh

  // Visits the faces whose bounding box overlaps `box`, calling visit(f)
  // until it returns true; returns whether one did. Boxes are compared in
  // doubles, so faces that share a corner with the query (which touch it, a
  // degenerate case for the filtered predicates: exact arithmetic every
  // time) reach the caller untested, to be skipped by their corners.
  template <typename Visit>
  bool anyFaceNear(const CGAL::Bbox_3& box, const Visit& visit) const {
    struct Traits {
      const CGAL::Bbox_3& box;
      const Visit& visit;
      bool found = false;
      bool go_further() const { return !found; }
      void intersection(const CGAL::Bbox_3&, const Primitive& primitive) {
        found = visit(static_cast<Eigen::Index>(primitive.id().idx()));
      }
      bool do_intersect(const CGAL::Bbox_3&, const CGAL::AABB_node<Tree::AABB_traits>& node) const {
        return CGAL::do_overlap(box, node.bbox());
      }
    } traits{box, visit};
    tree->traversal(box, traits);
    return traits.found;
  }

  // True when the query meets a face that has none of `corners` as a vertex.
  template <typename Query>
  bool meetsOtherFace(const Query& query, std::initializer_list<int> corners) const {
    return anyFaceNear(query.bbox(), [&](Eigen::Index f) {
      return sharedCorners(f, corners) == 0 && CGAL::do_intersect(query, triangle(f));
    });
  }

  int sharedCorners(Eigen::Index f, std::initializer_list<int> corners) const {
    int shared = 0;
    for (int c = 0; c < 3; ++c) {
      for (int corner : corners) shared += triangles(f, c) == corner ? 1 : 0;
    }
    return shared;
  }

  const Point& point(int v) const { return points[static_cast<std::size_t>(v)]; }
  Kernel::Triangle_3 triangle(Eigen::Index f) const {
    return {point(triangles(f, 0)), point(triangles(f, 1)), point(triangles(f, 2))};
  }

  // True when the triangle (a, b, c) and a face sharing exactly one corner
  // with it meet elsewhere: two triangles sharing one vertex meet beyond it
  // exactly when either's opposite edge meets the other triangle.
  bool meetsFaceAtOneCorner(int a, int b, int c) const {
    const Kernel::Triangle_3 query(point(a), point(b), point(c));
    return anyFaceNear(query.bbox(), [&](Eigen::Index f) {
      if (sharedCorners(f, {a, b, c}) != 1) return false;
      int k = 0;
      while (triangles(f, k) != a && triangles(f, k) != b && triangles(f, k) != c) ++k;
      const int shared = triangles(f, k);
      const Point& p = point(triangles(f, (k + 1) % 3));
      const Point& q = point(triangles(f, (k + 2) % 3));
      if (CGAL::do_intersect(Kernel::Segment_3(p, q), query)) return true;
      const int u = shared == a ? b : a;
      const int w = shared == c ? b : c;
      return CGAL::do_intersect(Kernel::Segment_3(point(u), point(w)),
                                Kernel::Triangle_3(point(shared), p, q));
    });
  }

  bool inside(const Point& p) const { return (*side)(p) != CGAL::ON_UNBOUNDED_SIDE; }
};

SurfaceInterior::SurfaceInterior(const Vertices& vertices, const Triangles& triangles)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.triangles = triangles;
  std::vector<Mesh::Vertex_index> handles;
  for (Eigen::Index i = 0; i < vertices.rows(); ++i) {
    m.points.emplace_back(vertices(i, 0), vertices(i, 1), vertices(i, 2));
    handles.push_back(m.mesh.add_vertex(m.points.back()));
  }
  // On a clean closed manifold surface add_face succeeds for every face, and
  // face f of the mesh is row f of `triangles`; otherwise nothing is claimed.
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Mesh::Face_index face =
        m.mesh.add_face(handles[static_cast<std::size_t>(triangles(f, 0))],
                        handles[static_cast<std::size_t>(triangles(f, 1))],
                        handles[static_cast<std::size_t>(triangles(f, 2))]);
    if (face == Mesh::null_face()) return;
  }
  m.usable = true;
  m.tree = std::make_unique<Tree>(faces(m.mesh).first, faces(m.mesh).second, m.mesh);
  m.side =
      std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel, CGAL::Default, Tree>>(*m.tree);
}

SurfaceInterior::~SurfaceInterior() = default;

bool SurfaceInterior::segmentInside(int a, int b) const {
  const Impl& m = *impl_;
  if (!m.usable) return true;
  const Point& p = m.points[static_cast<std::size_t>(a)];
  const Point& q = m.points[static_cast<std::size_t>(b)];
  if (m.meetsOtherFace(Kernel::Segment_3(p, q), {a, b})) return false;
  return m.inside(CGAL::midpoint(p, q));
}

bool SurfaceInterior::triangleInside(int a, int b, int c) const {
  const Impl& m = *impl_;
  if (!m.usable) return true;
  const Point& p = m.points[static_cast<std::size_t>(a)];
  const Point& q = m.points[static_cast<std::size_t>(b)];
  const Point& r = m.points[static_cast<std::size_t>(c)];
  if (CGAL::collinear(p, q, r)) return segmentInside(a, b) && segmentInside(b, c);
  if (m.meetsOtherFace(Kernel::Triangle_3(p, q, r), {a, b, c})) return false;
  if (m.meetsFaceAtOneCorner(a, b, c)) return false;
  return m.inside(CGAL::centroid(p, q, r));
}

}  // namespace tetblend
