// A CGAL translation unit (see meshing/CMakeLists.txt): CGAL stays inside.
#include "tetblend/meshing/hole_filling.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <vector>

#include "half_edge_table.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

bool indicesInRange(const SurfaceMesh& surface) {
  const Eigen::Index n = surface.vertices.rows();
  for (Eigen::Index i = 0; i < surface.triangles.size(); ++i) {
    const int v = surface.triangles.data()[i];
    if (v < 0 || v >= n) return false;
  }
  return true;
}

// Boundary edges (edges of one face) at each vertex; faces with a repeated
// index are skipped (validateSurface reports them).
std::vector<int> boundaryEdgesPerVertex(const SurfaceMesh& surface) {
  const Triangles& tri = surface.triangles;
  std::vector<char> skip(static_cast<std::size_t>(tri.rows()), 0);
  for (Eigen::Index f = 0; f < tri.rows(); ++f) {
    skip[static_cast<std::size_t>(f)] =
        tri(f, 0) == tri(f, 1) || tri(f, 1) == tri(f, 2) || tri(f, 0) == tri(f, 2);
  }
  const detail::HalfEdgeTable table = detail::buildHalfEdgeTable(tri, skip);
  std::vector<int> count(static_cast<std::size_t>(surface.vertices.rows()), 0);
  for (const auto& [begin, end] : table.edges) {
    if (end - begin != 1) continue;
    ++count[static_cast<std::size_t>(table.halfEdges[begin].lo)];
    ++count[static_cast<std::size_t>(table.halfEdges[begin].hi)];
  }
  return count;
}

// Throws when a vertex is on more than one boundary loop, or on one twice:
// the holes then share a vertex and cannot be closed one by one.
void requireManifoldBoundary(const std::vector<int>& boundaryEdges, const std::string& name) {
  for (std::size_t v = 0; v < boundaryEdges.size(); ++v) {
    if (boundaryEdges[v] > 2) {
      throw InputError(name + ": vertex " + std::to_string(v) + " lies on " +
                       std::to_string(boundaryEdges[v]) +
                       " boundary edges: two holes (or two parts of one hole) touch there, so "
                       "the holes cannot be filled; duplicate the vertex once per fan of faces, "
                       "or close the holes yourself");
    }
  }
}

// The surface as a CGAL halfedge mesh, vertex i and face f keeping their
// indices. The surface has passed validateSurface, so every face fits.
Mesh halfedgeMesh(const SurfaceMesh& surface, const std::string& name) {
  Mesh mesh;
  mesh.reserve(static_cast<Mesh::size_type>(surface.vertices.rows()),
               static_cast<Mesh::size_type>(3 * surface.triangles.rows()),
               static_cast<Mesh::size_type>(surface.triangles.rows()));
  for (Eigen::Index i = 0; i < surface.vertices.rows(); ++i) {
    mesh.add_vertex(
        Kernel::Point_3(surface.vertices(i, 0), surface.vertices(i, 1), surface.vertices(i, 2)));
  }
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Mesh::Face_index added = mesh.add_face(Mesh::Vertex_index(surface.triangles(f, 0)),
                                                 Mesh::Vertex_index(surface.triangles(f, 1)),
                                                 Mesh::Vertex_index(surface.triangles(f, 2)));
    if (added == Mesh::null_face()) {
      throw Error(name + ": face " + std::to_string(f) +
                  " does not fit a halfedge mesh although the surface passed validation");
    }
  }
  return mesh;
}

// One border halfedge per boundary loop, with the loop's edge count.
std::vector<std::pair<Mesh::Halfedge_index, int>> boundaryLoops(const Mesh& mesh) {
  std::vector<char> seen(mesh.number_of_halfedges(), 0);
  std::vector<std::pair<Mesh::Halfedge_index, int>> loops;
  for (const Mesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen[h.idx()]) continue;
    int size = 0;
    Mesh::Halfedge_index g = h;
    do {
      seen[g.idx()] = 1;
      ++size;
      g = mesh.next(g);
    } while (g != h);
    loops.emplace_back(h, size);
  }
  return loops;
}

}  // namespace

HoleFilling fillHoles(const SurfaceMesh& surface, const std::string& sourceName) {
  SurfaceValidationOptions openSurface;
  openSurface.requireClosed = false;
  openSurface.checkSelfIntersections = false;
  // An index out of range is validateSurface's first problem: this throws.
  if (!indicesInRange(surface)) requireValidRest(surface, sourceName, openSurface);
  const std::vector<int> boundaryEdges = boundaryEdgesPerVertex(surface);
  HoleFilling result;
  if (std::all_of(boundaryEdges.begin(), boundaryEdges.end(), [](int n) { return n == 0; })) {
    return result;
  }
  requireManifoldBoundary(boundaryEdges, sourceName);
  requireValidRest(surface, sourceName, openSurface);

  Mesh mesh = halfedgeMesh(surface, sourceName);
  std::vector<Mesh::Face_index> added;
  for (const auto& [border, size] : boundaryLoops(mesh)) {
    const std::size_t before = added.size();
    CGAL::Polygon_mesh_processing::triangulate_hole(mesh, border, std::back_inserter(added));
    if (added.size() == before) {
      throw InputError(sourceName + ": the hole of " + std::to_string(size) +
                       " boundary edges at vertex " + std::to_string(mesh.source(border).idx()) +
                       " has no triangulation without new vertices that avoids the surface's "
                       "own edges; close it yourself, or use the per-face tetrisation");
    }
    ++result.holeCount;
  }
  result.triangles.resize(static_cast<Eigen::Index>(added.size()), 3);
  for (std::size_t i = 0; i < added.size(); ++i) {
    int k = 0;
    for (const Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(added[i]))) {
      result.triangles(static_cast<Eigen::Index>(i), k++) = static_cast<int>(v.idx());
    }
  }
  return result;
}

}  // namespace tetblend
