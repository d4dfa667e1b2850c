#include "tetblend/meshing/surface_validation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>

#include "half_edge_table.h"
#include "surface_messages.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/surface_orientation.h"

namespace tetblend {
namespace {

using detail::faceText;
using detail::numberText;

class Collector {
 public:
  Collector(std::vector<SurfaceProblem>& problems, const std::string& file)
      : problems_(problems), file_(file) {}
  void add(SurfaceProblemKind kind, long long element, double value, const std::string& text) {
    problems_.push_back({kind, element, value, file_ + ": " + text});
  }

 private:
  std::vector<SurfaceProblem>& problems_;
  const std::string& file_;
};

bool checkIndicesAndCoordinates(const SurfaceMesh& mesh, Collector& out) {
  bool ok = true;
  const Eigen::Index n = mesh.vertices.rows();
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      if (v >= 0 && v < n) continue;
      ok = false;
      out.add(SurfaceProblemKind::kIndexOutOfRange, f, v,
              "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                  " but the file has vertices 0.." + std::to_string(n - 1) +
                  ": fix the face list (indices are zero-based here)");
    }
  }
  for (Eigen::Index v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.vertices(v, k);
      if (std::isfinite(x)) continue;
      ok = false;
      out.add(SurfaceProblemKind::kNonFiniteCoordinate, v, x,
              "vertex " + std::to_string(v) + " has coordinate " + "xyz"[k] + " = " +
                  numberText(x) + ": replace it with a finite value");
      break;
    }
  }
  return ok;
}

void checkFaces(const SurfaceMesh& mesh, const SurfaceValidationOptions& options, Collector& out) {
  const Triangles& tri = mesh.triangles;
  const double diagonal = boundingBoxDiagonal(mesh.vertices);
  std::vector<std::pair<std::array<int, 3>, int>> keys;
  for (int f = 0; f < static_cast<int>(tri.rows()); ++f) {
    const int a = tri(f, 0), b = tri(f, 1), c = tri(f, 2);
    if (a == b || b == c || a == c) {
      out.add(SurfaceProblemKind::kRepeatedIndex, f, a == b || a == c ? a : b,
              "face " + std::to_string(f) + " " + faceText(tri, f) +
                  " repeats a vertex: remove the face or merge its neighbours");
      continue;
    }
    const Eigen::Vector3d p0 = mesh.vertices.row(a), p1 = mesh.vertices.row(b),
                          p2 = mesh.vertices.row(c);
    const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    const double relative = diagonal > 0.0 ? area / (diagonal * diagonal) : 0.0;
    if (relative < options.zeroAreaRelTol) {
      out.add(SurfaceProblemKind::kZeroAreaFace, f, relative,
              "face " + std::to_string(f) + " " + faceText(tri, f) + " has area " +
                  numberText(relative) + " x (bounding-box diagonal)^2, below the tolerance " +
                  numberText(options.zeroAreaRelTol) +
                  ": collapse or remove the degenerate face (e.g. MeshLab 'remove zero area "
                  "faces')");
    }
    std::array<int, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    keys.push_back({key, f});
  }
  std::sort(keys.begin(), keys.end());
  std::size_t runStart = 0;  // keys sorted by (vertex set, face): the run's first is the original
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].first != keys[runStart].first) {
      runStart = i;
      continue;
    }
    const int f = keys[i].second, g = keys[runStart].second;
    out.add(SurfaceProblemKind::kDuplicateFace, f, g,
            "face " + std::to_string(f) + " " + faceText(tri, f) +
                " uses the same three vertices as face " + std::to_string(g) + " " +
                faceText(tri, g) + ": remove the duplicate");
  }
}

void checkUnreferenced(const SurfaceMesh& mesh, Collector& out) {
  for (int v : unreferencedVertices(mesh)) {
    out.add(SurfaceProblemKind::kUnreferencedVertex, v, 0.0,
            "vertex " + std::to_string(v) +
                " is used by no face: it would float free in the output; remove the unused "
                "vertices from the rest and every example alike (MeshLab: 'Remove "
                "Unreferenced Vertices'; C++: removeVertices with unreferencedVertices) or "
                "fix the faces");
  }
}

void checkEdges(const SurfaceMesh& mesh, const SurfaceValidationOptions& options, Collector& out) {
  const Triangles& tri = mesh.triangles;
  const detail::HalfEdgeTable table =
      detail::buildHalfEdgeTable(tri, detail::repeatedIndexFaces(tri));
  const auto& he = table.halfEdges;
  std::size_t boundaryCount = 0;
  for (const auto& [begin, end] : table.edges) boundaryCount += end - begin == 1 ? 1 : 0;
  for (const auto& [begin, end] : table.edges) {
    const std::string edge =
        "edge (" + std::to_string(he[begin].lo) + ", " + std::to_string(he[begin].hi) + ")";
    const int f = he[begin].face;
    if (end - begin == 1 && options.requireClosed) {
      out.add(SurfaceProblemKind::kBoundaryEdge, f, static_cast<double>(boundaryCount),
              edge + " of face " + std::to_string(f) + " is a boundary edge (" +
                  std::to_string(boundaryCount) +
                  " in total): the surface is open, but a volume mesh needs a closed "
                  "surface; let prepare fill the holes (its default, no new vertices), close "
                  "them yourself, or use the per-face tetrisation");
    } else if (!options.requireSolid) {
      continue;
    } else if (end - begin > 2) {
      out.add(SurfaceProblemKind::kNonManifoldEdge, f, static_cast<double>(end - begin),
              edge + " is shared by " + std::to_string(end - begin) + " faces (first face " +
                  std::to_string(f) + "): make it manifold (split the edge or remove faces)");
    } else if (end - begin == 2 && he[begin].forward == he[begin + 1].forward) {
      const int g = he[begin + 1].face;
      out.add(SurfaceProblemKind::kInconsistentOrientation, g, f,
              "faces " + std::to_string(f) + " " + faceText(tri, f) + " and " + std::to_string(g) +
                  " " + faceText(tri, g) + " both run " + edge +
                  " the same way: orientation is inconsistent; call orientConsistently or "
                  "reverse one of them");
    }
  }
}

void checkVertexFans(const SurfaceMesh& mesh, Collector& out) {
  const Triangles& tri = mesh.triangles;
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(mesh.vertices.rows()));
  for (int f = 0; f < static_cast<int>(tri.rows()); ++f) {
    if (detail::repeatsAVertex(tri, f)) continue;
    for (int k = 0; k < 3; ++k) incident[tri(f, k)].push_back(f);
  }
  for (std::size_t v = 0; v < incident.size(); ++v) {
    const std::vector<int>& faces = incident[v];
    detail::UnionFind fans(faces.size());
    std::vector<std::pair<int, std::size_t>> firstFaceOfNeighbour;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        const int u = tri(faces[i], k);
        if (u == static_cast<int>(v)) continue;
        auto it = std::find_if(firstFaceOfNeighbour.begin(), firstFaceOfNeighbour.end(),
                               [u](const auto& entry) { return entry.first == u; });
        if (it == firstFaceOfNeighbour.end()) {
          firstFaceOfNeighbour.emplace_back(u, i);
        } else {
          fans.unite(it->second, i);
        }
      }
    }
    std::size_t fanCount = 0;
    for (std::size_t i = 0; i < faces.size(); ++i) fanCount += fans.find(i) == i ? 1 : 0;
    if (fanCount > 1) {
      out.add(SurfaceProblemKind::kNonManifoldVertex, static_cast<long long>(v),
              static_cast<double>(fanCount),
              "vertex " + std::to_string(v) + " joins " + std::to_string(fanCount) +
                  " separate fans of faces (e.g. two cones touching at a tip): duplicate "
                  "the vertex once per fan or move the parts apart");
    }
  }
}

int checkComponents(const SurfaceMesh& mesh, const SurfaceValidationOptions& options,
                    Collector& out) {
  const std::vector<SurfaceComponent> components = surfaceComponents(mesh);
  for (std::size_t c = 0; c < components.size(); ++c) {
    const SurfaceComponent& comp = components[c];
    if (!comp.closed || !comp.consistent) continue;
    const bool cavity = !options.componentsAreSolids && comp.nestingDepth % 2 == 1;
    if ((cavity ? -comp.signedVolume : comp.signedVolume) >= 0.0) continue;
    out.add(SurfaceProblemKind::kInwardOrientation, comp.firstFace, comp.signedVolume,
            "component " + std::to_string(c) + " (first face " + std::to_string(comp.firstFace) +
                ", " + std::to_string(comp.faceCount) + " faces, nesting depth " +
                std::to_string(comp.nestingDepth) + ") encloses signed volume " +
                numberText(comp.signedVolume) + ": its faces " +
                (cavity ? "point away from the cavity" : "point inwards") +
                "; call orientConsistently or reverse every face of the component");
  }
  return static_cast<int>(components.size());
}

void checkSelfIntersections(const SurfaceMesh& mesh, const SurfaceValidationOptions& options,
                            Collector& out) {
  const SelfIntersections found =
      findSelfIntersections(mesh.vertices, mesh.triangles, options.maxSelfIntersectionPairs);
  for (const auto& [f, g] : found.pairs) {
    out.add(SurfaceProblemKind::kSelfIntersection, f, g,
            "faces " + std::to_string(f) + " " + faceText(mesh.triangles, f) + " and " +
                std::to_string(g) + " " + faceText(mesh.triangles, g) + " intersect (" +
                std::to_string(found.pairCount) +
                " intersecting pairs in total): the surface does not bound a solid; repair "
                "it (e.g. CGAL's autorefine or MeshLab) before meshing");
  }
}

}  // namespace

SurfaceValidation validateSurface(const SurfaceMesh& mesh, const std::string& sourceName,
                                  const SurfaceValidationOptions& options) {
  SurfaceValidation result;
  Collector out(result.problems, sourceName);
  if (mesh.triangles.rows() == 0) {
    out.add(SurfaceProblemKind::kEmpty, -1, 0.0,
            "the surface has no faces (" + std::to_string(mesh.vertices.rows()) +
                " vertices): check the file format and content");
    return result;
  }
  if (!checkIndicesAndCoordinates(mesh, out)) return result;
  checkFaces(mesh, options, out);
  checkUnreferenced(mesh, out);
  checkEdges(mesh, options, out);
  if (options.requireSolid) {
    checkVertexFans(mesh, out);
    result.componentCount = checkComponents(mesh, options, out);
  } else {
    result.componentCount = static_cast<int>(surfaceComponents(mesh).size());
  }
  if (options.checkSelfIntersections) checkSelfIntersections(mesh, options, out);
  std::stable_sort(result.problems.begin(), result.problems.end(),
                   [](const SurfaceProblem& a, const SurfaceProblem& b) {
                     return std::make_pair(a.kind, a.element) < std::make_pair(b.kind, b.element);
                   });
  return result;
}

}  // namespace tetblend
