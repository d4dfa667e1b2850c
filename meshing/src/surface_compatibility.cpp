// Example compatibility, the throwing wrappers, unreferenced vertices and the
// message helpers of surface_validation.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <sstream>
#include <utility>

#include "surface_messages.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_validation.h"

namespace tetblend {
namespace detail {

std::string faceText(const Triangles& triangles, Eigen::Index f) {
  return "(" + std::to_string(triangles(f, 0)) + ", " + std::to_string(triangles(f, 1)) + ", " +
         std::to_string(triangles(f, 2)) + ")";
}

std::string numberText(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

}  // namespace detail

void requireNoProblems(const std::vector<SurfaceProblem>& problems) {
  if (problems.empty()) return;
  std::string message = problems.front().message;
  if (problems.size() > 1) {
    message += " (and " + std::to_string(problems.size() - 1) + " other problem" +
               (problems.size() > 2 ? "s" : "") + ")";
  }
  throw InputError(message);
}

const char* problemKindName(SurfaceProblemKind kind) {
  switch (kind) {
    case SurfaceProblemKind::kEmpty:
      return "empty surface";
    case SurfaceProblemKind::kIndexOutOfRange:
      return "index out of range";
    case SurfaceProblemKind::kNonFiniteCoordinate:
      return "non-finite coordinate";
    case SurfaceProblemKind::kRepeatedIndex:
      return "repeated index";
    case SurfaceProblemKind::kZeroAreaFace:
      return "zero-area face";
    case SurfaceProblemKind::kDuplicateFace:
      return "duplicate face";
    case SurfaceProblemKind::kUnreferencedVertex:
      return "unreferenced vertex";
    case SurfaceProblemKind::kNonManifoldEdge:
      return "non-manifold edge";
    case SurfaceProblemKind::kNonManifoldVertex:
      return "non-manifold vertex";
    case SurfaceProblemKind::kBoundaryEdge:
      return "boundary edge";
    case SurfaceProblemKind::kInconsistentOrientation:
      return "inconsistent orientation";
    case SurfaceProblemKind::kInwardOrientation:
      return "inward orientation";
    case SurfaceProblemKind::kSelfIntersection:
      return "self-intersection";
    case SurfaceProblemKind::kVertexCountMismatch:
      return "vertex count mismatch";
    case SurfaceProblemKind::kFaceCountMismatch:
      return "face count mismatch";
    case SurfaceProblemKind::kConnectivityMismatch:
      return "connectivity mismatch";
  }
  return "unknown problem";
}

std::vector<SurfaceProblem> validateExample(const SurfaceMesh& rest, const SurfaceMesh& example,
                                            const std::string& exampleName) {
  std::vector<SurfaceProblem> problems;
  const std::string prefix = exampleName + ": ";
  const Eigen::Index nv = example.vertices.rows(), nf = example.triangles.rows();
  if (nv != rest.vertices.rows()) {
    problems.push_back({SurfaceProblemKind::kVertexCountMismatch, -1, static_cast<double>(nv),
                        prefix + "the example has " + std::to_string(nv) +
                            " vertices but the rest surface has " +
                            std::to_string(rest.vertices.rows()) +
                            ": examples must share the rest surface's vertices and faces "
                            "(same mesh, moved vertices)"});
  }
  if (nf != rest.triangles.rows()) {
    problems.push_back({SurfaceProblemKind::kFaceCountMismatch, -1, static_cast<double>(nf),
                        prefix + "the example has " + std::to_string(nf) +
                            " faces but the rest surface has " +
                            std::to_string(rest.triangles.rows()) +
                            ": examples must share the rest surface's faces"});
  }
  const Eigen::Index common = std::min(nf, rest.triangles.rows());
  for (Eigen::Index f = 0; f < common; ++f) {
    if (example.triangles.row(f) == rest.triangles.row(f)) continue;
    if (nf == rest.triangles.rows() &&
        flippedQuadDiagonals(rest.triangles, example.triangles) >= 0) {
      break;
    }
    problems.push_back({SurfaceProblemKind::kConnectivityMismatch, f, 0.0,
                        prefix + "face " + std::to_string(f) + " is " +
                            detail::faceText(example.triangles, f) +
                            " but the rest surface's face " + std::to_string(f) + " is " +
                            detail::faceText(rest.triangles, f) +
                            ": the example's connectivity differs from the rest (first "
                            "differing face, after order, corner rotation and quad diagonals); "
                            "export every example from the same mesh"});
    break;
  }
  for (Eigen::Index v = 0; v < nv; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = example.vertices(v, k);
      if (std::isfinite(x)) continue;
      problems.push_back({SurfaceProblemKind::kNonFiniteCoordinate, v, x,
                          prefix + "vertex " + std::to_string(v) + " has coordinate " + "xyz"[k] +
                              " = " + detail::numberText(x) + ": replace it with a finite value"});
      break;
    }
  }
  return problems;
}

namespace {

using Corners = std::array<int, 3>;

// The triangle with its smallest index first, its cyclic order kept.
Corners canonical(int a, int b, int c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

std::vector<Corners> canonicalRows(const Triangles& triangles) {
  std::vector<Corners> rows;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    rows.push_back(canonical(triangles(f, 0), triangles(f, 1), triangles(f, 2)));
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

}  // namespace

int flippedQuadDiagonals(const Triangles& rest, const Triangles& example) {
  if (rest.rows() != example.rows()) return -1;
  const std::vector<Corners> restRows = canonicalRows(rest), exampleRows = canonicalRows(example);
  std::vector<Corners> restOnly, exampleOnly;
  std::set_difference(restRows.begin(), restRows.end(), exampleRows.begin(), exampleRows.end(),
                      std::back_inserter(restOnly));
  std::set_difference(exampleRows.begin(), exampleRows.end(), restRows.begin(), restRows.end(),
                      std::back_inserter(exampleOnly));
  // Pair the rest's own triangles across a shared edge u-v, t1 = (u, v, a)
  // and t2 = (v, u, b): their quad a-u-b-v split along a-b is (a, u, b) and
  // (b, v, a), which the example must have instead.
  std::map<std::pair<int, int>, std::size_t> byDirectedEdge;
  for (std::size_t i = 0; i < restOnly.size(); ++i) {
    for (int k = 0; k < 3; ++k) byDirectedEdge[{restOnly[i][k], restOnly[i][(k + 1) % 3]}] = i;
  }
  std::map<Corners, int> wanted;  // the example's own triangles, not yet paired
  for (const Corners& t : exampleOnly) ++wanted[t];
  std::vector<char> paired(restOnly.size(), 0);
  int flips = 0;
  for (std::size_t i = 0; i < restOnly.size(); ++i) {
    for (int k = 0; k < 3 && !paired[i]; ++k) {
      const int u = restOnly[i][k], v = restOnly[i][(k + 1) % 3], a = restOnly[i][(k + 2) % 3];
      const auto other = byDirectedEdge.find({v, u});
      if (other == byDirectedEdge.end() || paired[other->second] || other->second == i) continue;
      const Corners& t2 = restOnly[other->second];
      const int b = t2[0] + t2[1] + t2[2] - u - v;
      const Corners first = canonical(a, u, b), second = canonical(b, v, a);
      auto f = wanted.find(first), s = wanted.find(second);
      if (f == wanted.end() || s == wanted.end() || f->second == 0 || s->second == 0) continue;
      --f->second;
      --s->second;
      paired[i] = paired[other->second] = 1;
      ++flips;
    }
    if (!paired[i]) return -1;
  }
  return flips;
}

void requireValidRest(const SurfaceMesh& mesh, const std::string& sourceName,
                      const SurfaceValidationOptions& options) {
  requireNoProblems(validateSurface(mesh, sourceName, options).problems);
}

void requireCompatibleExample(const SurfaceMesh& rest, const SurfaceMesh& example,
                              const std::string& exampleName) {
  requireNoProblems(validateExample(rest, example, exampleName));
}

std::vector<int> unreferencedVertices(const SurfaceMesh& mesh) {
  std::vector<char> used(static_cast<std::size_t>(mesh.vertices.rows()), 0);
  for (Eigen::Index i = 0; i < mesh.triangles.size(); ++i) {
    const int v = mesh.triangles.data()[i];
    if (v >= 0 && v < mesh.vertices.rows()) used[static_cast<std::size_t>(v)] = 1;
  }
  std::vector<int> unused;
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) unused.push_back(static_cast<int>(v));
  }
  return unused;
}

SurfaceMesh removeVertices(const SurfaceMesh& mesh, const std::vector<int>& vertices) {
  const Eigen::Index n = mesh.vertices.rows();
  std::vector<int> newIndex(static_cast<std::size_t>(n), 0);
  for (int v : vertices) {
    if (v < 0 || v >= n) {
      throw InputError("removeVertices: vertex " + std::to_string(v) + " is outside 0.." +
                       std::to_string(n - 1) + ": pass indices of this mesh");
    }
    newIndex[static_cast<std::size_t>(v)] = -1;
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      if (v < 0 || v >= n) {
        throw InputError("removeVertices: face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(v) + ", outside 0.." + std::to_string(n - 1) +
                         ": fix the face indices first");
      }
      if (newIndex[static_cast<std::size_t>(v)] < 0) {
        throw InputError("removeVertices: vertex " + std::to_string(mesh.triangles(f, k)) +
                         " is used by face " + std::to_string(f) +
                         ": only unreferenced vertices can be dropped");
      }
    }
  }
  SurfaceMesh out;
  int kept = 0;
  for (int& index : newIndex) index = index < 0 ? -1 : kept++;
  out.vertices.resize(kept, 3);
  for (Eigen::Index v = 0; v < n; ++v) {
    if (newIndex[static_cast<std::size_t>(v)] >= 0) {
      out.vertices.row(newIndex[static_cast<std::size_t>(v)]) = mesh.vertices.row(v);
    }
  }
  out.triangles.resize(mesh.triangles.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      out.triangles(f, k) = newIndex[static_cast<std::size_t>(mesh.triangles(f, k))];
    }
  }
  return out;
}

}  // namespace tetblend
