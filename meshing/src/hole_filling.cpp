// A CGAL translation unit (see meshing/CMakeLists.txt): CGAL stays inside.
#include "tetblend/meshing/hole_filling.h"

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <vector>

#include "cgal_points.h"
#include "half_edge_table.h"
#include "hole_fill_folds.h"
#include "hole_refill.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace {

using detail::Kernel;
using detail::pointAt;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

bool indicesInRange(const SurfaceMesh& surface) {
  const Eigen::Index n = surface.vertices.rows();
  for (Eigen::Index i = 0; i < surface.triangles.size(); ++i) {
    const int v = surface.triangles.data()[i];
    if (v < 0 || v >= n) return false;
  }
  return true;
}

// The borders of every boundary edge (edge of one face); faces with a
// repeated index are skipped (validateSurface reports them).
std::vector<Border> bordersOf(const Triangles& tri) {
  const detail::HalfEdgeTable table =
      detail::buildHalfEdgeTable(tri, detail::repeatedIndexFaces(tri));
  std::vector<Border> borders;
  for (const auto& [begin, end] : table.edges) {
    if (end - begin != 1) continue;
    const detail::HalfEdge& h = table.halfEdges[begin];
    borders.push_back(h.forward ? Border{h.hi, h.lo, h.face} : Border{h.lo, h.hi, h.face});
  }
  return borders;
}

// Boundary edges at each vertex.
std::vector<int> boundaryEdgesPerVertex(const std::vector<Border>& borders,
                                        Eigen::Index vertexCount) {
  std::vector<int> count(static_cast<std::size_t>(vertexCount), 0);
  for (const Border& b : borders) {
    ++count[static_cast<std::size_t>(b.from)];
    ++count[static_cast<std::size_t>(b.to)];
  }
  return count;
}

// One hole: its borders in order, each starting where the previous ends.
struct HoleLoop {
  std::vector<int> borders;
  bool pinched = false;  ///< passes a pinched vertex
};

// The vertex message of a boundary the fill cannot follow: more than two
// holes (or parts of one) touch at `v`, or its faces do not form two fans.
InputError touchingHolesError(const std::string& name, int v, int boundaryEdges) {
  return InputError(name + ": vertex " + std::to_string(v) + " lies on " +
                    std::to_string(boundaryEdges) +
                    " boundary edges: holes (or parts of one hole) touch there in a way the fill "
                    "cannot follow; duplicate the vertex once per fan of faces, or close the "
                    "holes yourself");
}

// Per face of `faces` (those around one vertex), its fan: faces joined
// through the edges at that vertex they share. Returns the fan count.
int fansAround(const Triangles& tri, const std::vector<int>& faces, std::vector<int>& fan) {
  detail::UnionFind join(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      int shared = 0;
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) shared += tri(faces[i], a) == tri(faces[j], b) ? 1 : 0;
      }
      if (shared == 2) join.unite(i, j);  // the vertex and one more: an edge at it
    }
  }
  fan.assign(faces.size(), -1);
  int count = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const std::size_t root = join.find(i);
    if (fan[root] < 0) fan[root] = count++;
    fan[i] = fan[root];
  }
  return count;
}

// Vertices on four boundary edges where two fans of faces meet, as where
// two holes touch (or one hole touches itself): per such vertex, the fan
// (0 or 1) of each face around it. Throws for any other vertex on more than
// two boundary edges.
std::map<int, std::map<int, int>> pinchedVertices(const SurfaceMesh& surface,
                                                  const std::vector<int>& boundaryEdges,
                                                  const std::string& name) {
  std::map<int, std::map<int, int>> pinched;
  for (std::size_t v = 0; v < boundaryEdges.size(); ++v) {
    if (boundaryEdges[v] <= 2) continue;
    if (boundaryEdges[v] != 4)
      throw touchingHolesError(name, static_cast<int>(v), boundaryEdges[v]);
    pinched[static_cast<int>(v)];
  }
  if (pinched.empty()) return pinched;
  std::map<int, std::vector<int>> faces;
  const Triangles& tri = surface.triangles;
  for (Eigen::Index f = 0; f < tri.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const auto it = pinched.find(tri(f, c));
      if (it != pinched.end()) faces[it->first].push_back(static_cast<int>(f));
    }
  }
  for (auto& [v, fanOfFace] : pinched) {
    std::vector<int> fan;
    if (fansAround(tri, faces[v], fan) != 2) throw touchingHolesError(name, v, 4);
    for (std::size_t i = 0; i < fan.size(); ++i) fanOfFace[faces[v][i]] = fan[i];
  }
  return pinched;
}

// The boundary loops. At a pinched vertex a hole goes on in the other fan:
// around the vertex, each gap between the two fans is one hole's corner.
std::vector<HoleLoop> holeLoops(const std::vector<Border>& borders,
                                const std::map<int, std::map<int, int>>& pinched,
                                Eigen::Index vertexCount, const std::string& name) {
  std::vector<int> firstOut(static_cast<std::size_t>(vertexCount) + 1, 0);
  for (const Border& b : borders) ++firstOut[static_cast<std::size_t>(b.from) + 1];
  for (std::size_t v = 1; v < firstOut.size(); ++v) firstOut[v] += firstOut[v - 1];
  std::vector<int> out(borders.size()), filled(firstOut.begin(), firstOut.end() - 1);
  for (std::size_t i = 0; i < borders.size(); ++i) {
    out[static_cast<std::size_t>(filled[static_cast<std::size_t>(borders[i].from)]++)] =
        static_cast<int>(i);
  }
  const auto next = [&](int arriving) {
    const int v = borders[static_cast<std::size_t>(arriving)].to;
    const int begin = firstOut[static_cast<std::size_t>(v)];
    const int count = firstOut[static_cast<std::size_t>(v) + 1] - begin;
    const auto it = pinched.find(v);
    if (it == pinched.end()) return count == 1 ? out[static_cast<std::size_t>(begin)] : -1;
    const int arrivingFan = it->second.at(borders[static_cast<std::size_t>(arriving)].face);
    for (int k = begin; k < begin + count; ++k) {
      const int leaving = out[static_cast<std::size_t>(k)];
      if (it->second.at(borders[static_cast<std::size_t>(leaving)].face) != arrivingFan) {
        return leaving;
      }
    }
    return -1;
  };
  std::vector<char> used(borders.size(), 0);
  std::vector<HoleLoop> loops;
  for (std::size_t start = 0; start < borders.size(); ++start) {
    if (used[start]) continue;
    HoleLoop loop;
    int at = static_cast<int>(start);
    do {
      used[static_cast<std::size_t>(at)] = 1;
      loop.borders.push_back(at);
      loop.pinched = loop.pinched || pinched.count(borders[static_cast<std::size_t>(at)].from) > 0;
      const int following = next(at);
      if (following < 0 ||
          (used[static_cast<std::size_t>(following)] && following != static_cast<int>(start))) {
        const int v = borders[static_cast<std::size_t>(at)].to;
        throw touchingHolesError(name, v,
                                 2 * (firstOut[static_cast<std::size_t>(v) + 1] -
                                      firstOut[static_cast<std::size_t>(v)]));
      }
      at = following;
    } while (at != static_cast<int>(start));
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The surface as a CGAL halfedge mesh, vertex i and face f keeping their
// indices, but that the faces of the second fan at each pinched vertex use
// a vertex of their own (appended), so that every vertex is manifold. The
// surface has passed validateSurface, so every face fits.
Mesh halfedgeMesh(const SurfaceMesh& surface, const std::map<int, std::map<int, int>>& pinched,
                  const std::string& name) {
  Mesh mesh;
  mesh.reserve(static_cast<Mesh::size_type>(surface.vertices.rows()),
               static_cast<Mesh::size_type>(3 * surface.triangles.rows()),
               static_cast<Mesh::size_type>(surface.triangles.rows()));
  for (Eigen::Index i = 0; i < surface.vertices.rows(); ++i) {
    mesh.add_vertex(pointAt(surface.vertices, static_cast<int>(i)));
  }
  std::map<int, Mesh::Vertex_index> secondFan;
  for (const auto& entry : pinched)
    secondFan[entry.first] = mesh.add_vertex(pointAt(surface.vertices, entry.first));
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    std::array<Mesh::Vertex_index, 3> corners;
    for (int c = 0; c < 3; ++c) {
      const int v = surface.triangles(f, c);
      const auto it = pinched.find(v);
      const bool second = it != pinched.end() && it->second.at(static_cast<int>(f)) == 1;
      corners[static_cast<std::size_t>(c)] = second ? secondFan[v] : Mesh::Vertex_index(v);
    }
    if (mesh.add_face(corners[0], corners[1], corners[2]) == Mesh::null_face()) {
      throw Error(name + ": face " + std::to_string(f) +
                  " does not fit a halfedge mesh although the surface passed validation");
    }
  }
  return mesh;
}

InputError noTriangulation(const std::string& name, std::size_t size, int vertex) {
  return InputError(name + ": the hole of " + std::to_string(size) + " boundary edges at vertex " +
                    std::to_string(vertex) +
                    " has no triangulation without new vertices that avoids the surface's "
                    "own edges; close it yourself, or use the per-face tetrisation");
}

// Whether two of `triangles` (at `positions`) intersect.
bool cutsItself(const Vertices& positions, const FillTriangles& triangles) {
  Triangles rows(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    for (int c = 0; c < 3; ++c) rows(static_cast<Eigen::Index>(i), c) = triangles[i][c];
  }
  return findSelfIntersections(positions, rows, 1).pairCount > 0;
}

// The boundary edges of `loop`, in order.
std::vector<Border> rimOf(const std::vector<Border>& borders, const HoleLoop& loop) {
  std::vector<Border> rim;
  for (const int b : loop.borders) rim.push_back(borders[static_cast<std::size_t>(b)]);
  return rim;
}

// Closes a hole through a pinched vertex, which the halfedge mesh cannot
// follow, by polylineFill at the rest.
FillTriangles fillAlongPolyline(const SurfaceMesh& surface, const std::vector<Border>& borders,
                                const HoleLoop& loop, const std::string& name) {
  const FillTriangles fill = polylineFill(surface, surface.vertices, rimOf(borders, loop));
  const int first = borders[static_cast<std::size_t>(loop.borders.front())].from;
  if (fill.empty()) throw noTriangulation(name, loop.borders.size(), first);
  for (const std::array<int, 3>& v : fill) {
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      throw touchingHolesError(name, v[0] == v[1] || v[0] == v[2] ? v[0] : v[1], 4);
    }
  }
  return fill;
}

}  // namespace

HoleFilling fillHoles(const SurfaceMesh& surface, const std::string& sourceName,
                      const std::vector<Vertices>& poses) {
  SurfaceValidationOptions openSurface;
  openSurface.requireClosed = false;
  openSurface.checkSelfIntersections = false;
  // An index out of range is validateSurface's first problem: this throws.
  if (!indicesInRange(surface)) requireValidRest(surface, sourceName, openSurface);
  const std::vector<Border> borders = bordersOf(surface.triangles);
  const std::vector<int> boundaryEdges = boundaryEdgesPerVertex(borders, surface.vertices.rows());
  HoleFilling result;
  if (std::all_of(boundaryEdges.begin(), boundaryEdges.end(), [](int n) { return n == 0; })) {
    return result;
  }
  const auto pinched = pinchedVertices(surface, boundaryEdges, sourceName);
  std::vector<SurfaceProblem> problems = validateSurface(surface, sourceName, openSurface).problems;
  problems.erase(std::remove_if(problems.begin(), problems.end(),
                                [&](const SurfaceProblem& p) {
                                  return p.kind == SurfaceProblemKind::kNonManifoldVertex &&
                                         pinched.count(static_cast<int>(p.element)) > 0;
                                }),
                 problems.end());
  requireNoProblems(problems);

  const std::vector<HoleLoop> loops =
      holeLoops(borders, pinched, surface.vertices.rows(), sourceName);
  Mesh mesh = halfedgeMesh(surface, pinched, sourceName);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    if (poses[k].rows() != surface.vertices.rows() || !poses[k].allFinite()) {
      throw InputError(sourceName + ": pose " + std::to_string(k + 1) + " has " +
                       std::to_string(poses[k].rows()) + " vertex positions (need " +
                       std::to_string(surface.vertices.rows()) + ", all finite)");
    }
  }
  // The rest's own fills, and the ones chosen for the poses as well.
  FillTriangles restTriangles, triangles;
  for (const HoleLoop& loop : loops) {
    ++result.holeCount;
    if (loop.pinched) {
      const FillTriangles fill = fillAlongPolyline(surface, borders, loop, sourceName);
      restTriangles.insert(restTriangles.end(), fill.begin(), fill.end());
      triangles.insert(triangles.end(), fill.begin(), fill.end());
      continue;
    }
    const Border& first = borders[static_cast<std::size_t>(loop.borders.front())];
    const Mesh::Halfedge_index border =
        mesh.halfedge(Mesh::Vertex_index(first.from), Mesh::Vertex_index(first.to));
    std::vector<Mesh::Face_index> added;
    CGAL::Polygon_mesh_processing::triangulate_hole(mesh, border, std::back_inserter(added));
    if (added.empty()) throw noTriangulation(sourceName, loop.borders.size(), first.from);
    FillTriangles fill;
    for (const Mesh::Face_index face : added) {
      std::array<int, 3> corners{};
      int k = 0;
      for (const Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(face))) {
        corners[static_cast<std::size_t>(k++)] = static_cast<int>(v.idx());
      }
      fill.push_back(corners);
    }
    restTriangles.insert(restTriangles.end(), fill.begin(), fill.end());
    if (!poses.empty())
      fill = leastFoldingFill(std::move(fill), surface, poses, rimOf(borders, loop));
    triangles.insert(triangles.end(), fill.begin(), fill.end());
  }
  // Each fill chosen for the poses cuts no face of the surface; should two
  // holes' fills cut each other, the rest's own fills are kept.
  if (triangles != restTriangles && cutsItself(surface.vertices, triangles)) {
    triangles = restTriangles;
  }
  result.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      result.triangles(static_cast<Eigen::Index>(i), c) = triangles[i][static_cast<std::size_t>(c)];
    }
  }
  return result;
}

}  // namespace tetblend
