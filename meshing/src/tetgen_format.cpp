// TetGen .node/.ele (TetGen manual §5.2.1, §5.2.4). .node: "#points 3
// #attributes #markers", then "index x y z [attributes] [marker]"; the first
// index (0 or 1) fixes the numbering of both files and indices must then be
// consecutive. .ele: "#tets 4 #attributes", then "index n0 n1 n2 n3 [attrs]".
// Quadratic (10-node) tets are refused.

#include <algorithm>
#include <filesystem>
#include <string>

#include "formats.h"
#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend::detail {
namespace {

std::string withExtension(const std::string& path, const char* extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

Vertices readNode(const std::string& path, long long& base) {
  const std::string text = readFileBytes(path);
  TextLines lines(text);
  if (!lines.next()) throwAtLine(path, 1, "empty file: expected '#points 3 #attributes #markers'");
  const auto& header = lines.tokens();
  const int count = parseCount(header[0], path, lines.lineNumber(), "point count");
  if (header.size() >= 2 && parseInteger(header[1], path, lines.lineNumber(), "dimension") != 3) {
    throwAtLine(path, lines.lineNumber(),
                "dimension " + quoteToken(header[1]) + " is not 3: only 3D meshes are supported");
  }
  // A point line has at least 4 values ("i x y z") of at least one byte each.
  constexpr std::size_t kMinPointBytes = 4;
  Vertices vertices(
      rowsToAllocate(count, kMinPointBytes, text.size() - std::min(text.size(), lines.endOffset())),
      3);
  base = 0;
  for (int v = 0; v < count; ++v) {
    if (!lines.next()) {
      throwAtLine(path, lines.lineNumber(),
                  "file ends after " + std::to_string(v) + " of " + std::to_string(count) +
                      " points: the file is truncated");
    }
    const auto& t = lines.tokens();
    const long long index = parseInteger(t[0], path, lines.lineNumber(), "point index");
    if (v == 0) {
      if (index != 0 && index != 1) {
        throwAtLine(path, lines.lineNumber(),
                    "first point index " + std::to_string(index) +
                        " is neither 0 nor 1: renumber the points");
      }
      base = index;
    } else if (index != base + v) {
      throwAtLine(path, lines.lineNumber(),
                  "point index " + std::to_string(index) + " where " + std::to_string(base + v) +
                      " was expected: indices must be consecutive");
    }
    growRows(vertices, v, count);
    vertices.row(v) = parseVertex(t, 1, path, lines.lineNumber(), v);
  }
  return vertices;
}

Tets readEle(const std::string& path, long long base, int vertexCount) {
  const std::string text = readFileBytes(path);
  TextLines lines(text);
  if (!lines.next()) throwAtLine(path, 1, "empty file: expected '#tets 4 #attributes'");
  const auto& header = lines.tokens();
  const int count = parseCount(header[0], path, lines.lineNumber(), "tet count");
  if (header.size() >= 2) {
    const long long nodes = parseInteger(header[1], path, lines.lineNumber(), "nodes per tet");
    if (nodes != 4) {
      throwAtLine(path, lines.lineNumber(),
                  std::to_string(nodes) +
                      " nodes per tet: only linear 4-node tets are "
                      "supported (mesh without the -o2 switch)");
    }
  }
  // A tet line has at least 5 values ("i a b c d") of at least one byte each.
  constexpr std::size_t kMinTetBytes = 5;
  Tets tets(
      rowsToAllocate(count, kMinTetBytes, text.size() - std::min(text.size(), lines.endOffset())),
      4);
  for (int e = 0; e < count; ++e) {
    if (!lines.next()) {
      throwAtLine(path, lines.lineNumber(),
                  "file ends after " + std::to_string(e) + " of " + std::to_string(count) +
                      " tets: the file is truncated");
    }
    growRows(tets, e, count);
    const auto& t = lines.tokens();
    const auto element = [e] { return "tet " + std::to_string(e) + " (0-based)"; };
    if (t.size() < 5) {
      throwAtLine(path, lines.lineNumber(),
                  element() +
                      ": expected an index and 4 vertex indices, "
                      "found " +
                      std::to_string(t.size()) + " values");
    }
    parseInteger(t[0], path, lines.lineNumber(), "tet index");
    for (int c = 0; c < 4; ++c) {
      const long long index = parseInteger(t[1 + c], path, lines.lineNumber(),
                                           [&] { return "vertex index of " + element(); });
      tets(e, c) = checkedIndex(index, base, vertexCount, path, lines.lineNumber(), element);
    }
  }
  return tets;
}

}  // namespace

TetMesh readTetGen(const std::string& path) {
  long long base = 0;
  TetMesh mesh;
  mesh.vertices = readNode(withExtension(path, ".node"), base);
  mesh.tets = readEle(withExtension(path, ".ele"), base, static_cast<int>(mesh.vertices.rows()));
  return mesh;
}

void writeTetGen(const std::string& path, const TetMesh& mesh) {
  checkMeshForWriting(mesh, path);
  std::string node;
  appendInteger(node, mesh.vertices.rows());
  node += " 3 0 0\n";
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    appendInteger(node, v);
    for (int c = 0; c < 3; ++c) {
      node += ' ';
      appendDouble(node, mesh.vertices(v, c));
    }
    node += '\n';
  }
  std::string ele;
  appendInteger(ele, mesh.tets.rows());
  ele += " 4 0\n";
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    appendInteger(ele, t);
    for (int c = 0; c < 4; ++c) {
      ele += ' ';
      appendInteger(ele, mesh.tets(t, c));
    }
    ele += '\n';
  }
  writeBytesAtomically(withExtension(path, ".node"), node);
  writeBytesAtomically(withExtension(path, ".ele"), ele);
}

}  // namespace tetblend::detail
