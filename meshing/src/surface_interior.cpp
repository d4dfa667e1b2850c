// A CGAL translation unit (see meshing/CMakeLists.txt).
#include "surface_interior.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <initializer_list>
#include <iterator>
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

  // True when a face found by the query has none of `corners` as a vertex.
  template <typename Query>
  bool meetsOtherFace(const Query& query, std::initializer_list<int> corners) const {
    std::vector<Primitive::Id> faces;
    tree->all_intersected_primitives(query, std::back_inserter(faces));
    for (const Primitive::Id& face : faces) {
      if (sharedCorners(static_cast<Eigen::Index>(face.idx()), corners) == 0) return true;
    }
    return false;
  }

  int sharedCorners(Eigen::Index f, std::initializer_list<int> corners) const {
    int shared = 0;
    for (int c = 0; c < 3; ++c) {
      for (int corner : corners) shared += triangles(f, c) == corner ? 1 : 0;
    }
    return shared;
  }

  // True when the triangle (a, b, c) and a face sharing exactly one corner
  // with it meet elsewhere: two triangles sharing one vertex meet beyond it
  // exactly when either's opposite edge meets the other triangle.
  bool meetsFaceAtOneCorner(int a, int b, int c) const {
    const Kernel::Triangle_3 query(points[static_cast<std::size_t>(a)],
                                   points[static_cast<std::size_t>(b)],
                                   points[static_cast<std::size_t>(c)]);
    std::vector<Primitive::Id> faces;
    tree->all_intersected_primitives(query, std::back_inserter(faces));
    for (const Primitive::Id& face : faces) {
      const auto f = static_cast<Eigen::Index>(face.idx());
      if (sharedCorners(f, {a, b, c}) != 1) continue;
      int k = 0;
      while (triangles(f, k) != a && triangles(f, k) != b && triangles(f, k) != c) ++k;
      const int shared = triangles(f, k);
      const Point& p = points[static_cast<std::size_t>(triangles(f, (k + 1) % 3))];
      const Point& q = points[static_cast<std::size_t>(triangles(f, (k + 2) % 3))];
      if (CGAL::do_intersect(Kernel::Segment_3(p, q), query)) return true;
      const int u = shared == a ? b : a;
      const int w = shared == c ? b : c;
      const Kernel::Triangle_3 other(points[static_cast<std::size_t>(shared)], p, q);
      if (CGAL::do_intersect(Kernel::Segment_3(points[static_cast<std::size_t>(u)],
                                               points[static_cast<std::size_t>(w)]),
                             other)) {
        return true;
      }
    }
    return false;
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
  m.side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel, CGAL::Default, Tree>>(*m.tree);
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
