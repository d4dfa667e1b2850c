// A CGAL translation unit (see meshing/CMakeLists.txt): CGAL stays inside.
#include "hole_refill.h"

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <set>
#include <utility>

#include "cgal_points.h"
#include "tetblend/core/constants.h"
#include "tetblend/meshing/self_intersection.h"

namespace tetblend {
namespace {

using detail::Kernel;
using detail::pointAt;

// A fill folding at most this much in every pose is kept: each of its edges
// then leaves the solid a dihedral angle of at least 90° (as at a box's
// edges) and at most 270°, room for the tets along it.
constexpr double kHarmlessFold = kPi / 2;
// Fills of other poses tried per hole at most. Each is one CGAL
// triangulation (cubic in the hole's size at worst, milliseconds for
// hundreds of edges), its folds in every pose and, if it folds less, local
// self-intersection checks in every pose. The search stops at the first
// fill that does not qualify: going on to the pose where the current fill
// folds next most (at most 3 fills) let the fill of CGAL's lion's open base
// cut its surface in 9 instead of 19 of 48 gallop-like frames, but 12
// frames that no longer intersect themselves kept tets inverted (3 before)
// and preparing took 328 s instead of 83 s.
constexpr int kMaxRefills = 3;

std::pair<int, int> undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// The surface's edges with both ends on `rim`'s vertices: the ones a fill
// edge could repeat.
std::set<std::pair<int, int>> edgesAmongRim(const Triangles& triangles,
                                            const std::vector<Border>& rim) {
  std::set<int> onRim;
  for (const Border& b : rim) onRim.insert(b.from);
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      if (onRim.count(a) > 0 && onRim.count(b) > 0) edges.insert(undirected(a, b));
    }
  }
  return edges;
}

// Whether an edge of `fill` that is not on the rim is an edge of the
// surface (the closed surface would be non-manifold there).
bool repeatsASurfaceEdge(const FillTriangles& fill, const std::vector<Border>& rim,
                         const std::set<std::pair<int, int>>& surfaceEdges) {
  std::set<std::pair<int, int>> rimEdges;
  for (const Border& b : rim) rimEdges.insert(undirected(b.from, b.to));
  for (const std::array<int, 3>& t : fill) {
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e = undirected(t[k], t[(k + 1) % 3]);
      if (rimEdges.count(e) == 0 && surfaceEdges.count(e) > 0) return true;
    }
  }
  return false;
}

// Whether a triangle of `fill` intersects another or a face of the surface
// (`triangles`) at `p` (only the faces whose bounding boxes overlap the
// fill's are checked).
bool cutsTheSurface(const FillTriangles& fill, const Triangles& triangles, const Vertices& p) {
  Eigen::RowVector3d lo = Eigen::RowVector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::RowVector3d hi = -lo;
  for (const std::array<int, 3>& t : fill) {
    for (const int v : t) {
      lo = lo.cwiseMin(p.row(v));
      hi = hi.cwiseMax(p.row(v));
    }
  }
  std::vector<Eigen::Index> nearby;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    Eigen::RowVector3d faceLo = p.row(triangles(f, 0)), faceHi = faceLo;
    for (int c = 1; c < 3; ++c) {
      faceLo = faceLo.cwiseMin(p.row(triangles(f, c)));
      faceHi = faceHi.cwiseMax(p.row(triangles(f, c)));
    }
    if ((faceLo.array() <= hi.array()).all() && (lo.array() <= faceHi.array()).all()) {
      nearby.push_back(f);
    }
  }
  const Eigen::Index first = static_cast<Eigen::Index>(nearby.size());
  Triangles local(first + static_cast<Eigen::Index>(fill.size()), 3);
  for (Eigen::Index i = 0; i < first; ++i) {
    local.row(i) = triangles.row(nearby[static_cast<std::size_t>(i)]);
  }
  for (std::size_t i = 0; i < fill.size(); ++i) {
    for (int c = 0; c < 3; ++c) local(first + static_cast<Eigen::Index>(i), c) = fill[i][c];
  }
  const SelfIntersections found =
      findSelfIntersections(p, local, std::numeric_limits<std::size_t>::max());
  return std::any_of(found.pairs.begin(), found.pairs.end(),
                     [&](const std::pair<int, int>& pair) { return pair.second >= first; });
}

}  // namespace

FillTriangles polylineFill(const SurfaceMesh& surface, const Vertices& positions,
                           const std::vector<Border>& rim) {
  std::vector<int> corner;
  std::vector<Kernel::Point_3> points, third;
  for (const Border& border : rim) {
    corner.push_back(border.from);
    points.push_back(pointAt(positions, border.from));
    int other = 0;
    for (int c = 0; c < 3; ++c) {
      const int v = surface.triangles(border.face, c);
      if (v != border.from && v != border.to) other = v;
    }
    third.push_back(pointAt(positions, other));
  }
  std::vector<CGAL::Triple<int, int, int>> patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(points, third,
                                                           std::back_inserter(patch));
  // The border runs corner 0 -> corner 1, so the fill's triangle at that
  // edge must too; CGAL orients its patch consistently.
  bool reversed = false;
  for (const auto& t : patch) {
    const std::array<int, 3> c{t.first, t.second, t.third};
    for (int k = 0; k < 3; ++k) {
      if (c[k] == 1 && c[(k + 1) % 3] == 0) reversed = true;
    }
  }
  FillTriangles fill;
  for (const auto& t : patch) {
    std::array<int, 3> v{corner[static_cast<std::size_t>(t.first)],
                         corner[static_cast<std::size_t>(t.second)],
                         corner[static_cast<std::size_t>(t.third)]};
    if (reversed) std::swap(v[1], v[2]);
    fill.push_back(v);
  }
  return fill;
}

FillTriangles leastFoldingFill(FillTriangles fill, const SurfaceMesh& surface,
                               const std::vector<Vertices>& poses, const std::vector<Border>& rim) {
  // Per pose, the sharpest fold of `triangles` there.
  const auto foldsOf = [&](const FillTriangles& triangles) {
    std::vector<double> folds;
    for (const Vertices& pose : poses) {
      folds.push_back(sharpestFold(triangles, rim, surface.triangles, pose));
    }
    return folds;
  };
  // The sharpest fold of `triangles` over the rest and the poses.
  const auto worstOf = [&](const FillTriangles& triangles, const std::vector<double>& folds) {
    const double atRest = sharpestFold(triangles, rim, surface.triangles, surface.vertices);
    return std::max(atRest, folds.empty() ? 0.0 : *std::max_element(folds.begin(), folds.end()));
  };
  // The poses where `triangles` cut the surface (or each other): each
  // makes that example intersect itself, and its tets there are excluded.
  const auto posesCut = [&](const FillTriangles& triangles) {
    return std::count_if(poses.begin(), poses.end(), [&](const Vertices& pose) {
      return cutsTheSurface(triangles, surface.triangles, pose);
    });
  };
  std::vector<double> folds = foldsOf(fill);
  double worst = worstOf(fill, folds);
  std::ptrdiff_t cut = -1;  // posesCut(fill), once needed
  std::set<std::pair<int, int>> surfaceEdges;
  std::vector<char> tried(poses.size(), 0);
  for (int refill = 0; refill < kMaxRefills && worst > kHarmlessFold; ++refill) {
    // The pose where the current fill folds most (its fill was not tried).
    const auto most = std::max_element(folds.begin(), folds.end());
    if (most == folds.end() || !(*most > kHarmlessFold)) break;
    const std::size_t where = static_cast<std::size_t>(most - folds.begin());
    if (tried[where]) break;
    tried[where] = 1;
    FillTriangles candidate = polylineFill(surface, poses[where], rim);
    if (candidate.empty()) break;
    const std::vector<double> candidateFolds = foldsOf(candidate);
    const double candidateWorst = worstOf(candidate, candidateFolds);
    if (!(candidateWorst < worst)) break;
    if (surfaceEdges.empty()) surfaceEdges = edgesAmongRim(surface.triangles, rim);
    if (repeatsASurfaceEdge(candidate, rim, surfaceEdges) ||
        cutsTheSurface(candidate, surface.triangles, surface.vertices)) {
      break;
    }
    if (cut < 0) cut = posesCut(fill);
    const std::ptrdiff_t candidateCut = posesCut(candidate);
    if (candidateCut > cut) break;
    cut = candidateCut;
    fill = std::move(candidate);
    folds = candidateFolds;
    worst = candidateWorst;
  }
  return fill;
}

}  // namespace tetblend
