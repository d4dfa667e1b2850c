// Medit ascii .mesh (INRIA libMeshb keywords): "MeshVersionFormatted v",
// "Dimension 3", "Vertices n" with n × (x y z ref), "Tetrahedra n" with
// n × (v0 v1 v2 v3 ref), 1-based, "End". Sections of boundary entities
// (Triangles, Edges, Corners, ...) are skipped; other volume cells are refused.

#include <string>
#include <string_view>

#include "formats.h"
#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend::detail {
namespace {

// Number of values per entry of the sections that are skipped.
int skippedEntrySize(std::string_view keyword) {
  static const struct {
    const char* keyword;
    int size;
  } kSections[] = {
      {"Edges", 3},   {"Triangles", 4},        {"Quadrilaterals", 5}, {"Corners", 1},
      {"Ridges", 1},  {"RequiredVertices", 1}, {"RequiredEdges", 1},  {"RequiredTriangles", 1},
      {"Normals", 3}, {"NormalAtVertices", 2}, {"Tangents", 3},       {"TangentAtVertices", 2}};
  for (const auto& s : kSections) {
    if (keyword == s.keyword) return s.size;
  }
  return -1;
}

}  // namespace

TetMesh readMedit(const std::string& path) {
  const std::string text = readFileBytes(path);
  TextTokens tokens(text);
  // `what` is a string or a callable giving one (built only on failure).
  const auto nextToken = [&](const auto& what) {
    std::string_view token;
    if (!tokens.next(token)) {
      throwAtLine(path, tokens.lineNumber(),
                  "file ends before " + describe(what) + ": the file is truncated");
    }
    return token;
  };
  const auto nextCount = [&](const std::string& what) {
    return parseCount(nextToken(what), path, tokens.lineNumber(), what);
  };
  TetMesh mesh;
  mesh.vertices.resize(0, 3);
  mesh.tets.resize(0, 4);
  // Line of each section read so far: a second Vertices section would leave
  // the tets read before it pointing past the vertices, a second Tetrahedra
  // section would drop the first one's tets.
  std::size_t verticesLine = 0;
  std::size_t tetrahedraLine = 0;
  const auto once = [&](std::size_t& first, std::string_view section, std::size_t line) {
    if (first != 0) {
      throwAtLine(path, line,
                  "a second " + std::string(section) + " section (first on line " +
                      std::to_string(first) + "): a file holds one; fix the file");
    }
    first = line;
  };
  std::string_view keyword;
  while (tokens.next(keyword)) {
    const std::size_t line = tokens.lineNumber();
    if (keyword == "End") break;
    if (keyword == "MeshVersionFormatted") {
      nextToken("the mesh version");
    } else if (keyword == "Dimension") {
      const std::string_view d = nextToken("the dimension");
      if (parseInteger(d, path, tokens.lineNumber(), "dimension") != 3) {
        throwAtLine(path, tokens.lineNumber(),
                    "Dimension " + printableToken(d) + ": only 3D meshes are supported");
      }
    } else if (keyword == "Vertices") {
      once(verticesLine, keyword, line);
      const int count = nextCount("the vertex count");
      // Each vertex has 4 values ("x y z ref") of at least one byte; the whole
      // file bounds what is left of it.
      constexpr std::size_t kMinVertexBytes = 4;
      mesh.vertices.resize(rowsToAllocate(count, kMinVertexBytes, text.size()), 3);
      for (int v = 0; v < count; ++v) {
        Eigen::RowVector3d p;
        for (int c = 0; c < 3; ++c) {
          p[c] = parseDouble(nextToken([v] { return "vertex " + std::to_string(v); }), path,
                             tokens.lineNumber(),
                             [v] { return "coordinate of vertex " + std::to_string(v); });
        }
        checkFiniteVertex(p, path, std::to_string(tokens.lineNumber()), v);
        growRows(mesh.vertices, v, count);
        mesh.vertices.row(v) = p;
        nextToken([v] { return "the reference of vertex " + std::to_string(v); });
      }
    } else if (keyword == "Tetrahedra") {
      if (verticesLine == 0) throwAtLine(path, line, "Tetrahedra before Vertices: fix the file");
      once(tetrahedraLine, keyword, line);
      const int count = nextCount("the tet count");
      constexpr std::size_t kMinTetBytes = 5;  // "a b c d ref"
      mesh.tets.resize(rowsToAllocate(count, kMinTetBytes, text.size()), 4);
      for (int t = 0; t < count; ++t) {
        growRows(mesh.tets, t, count);
        const auto element = [t] { return "tet " + std::to_string(t) + " (0-based)"; };
        for (int c = 0; c < 4; ++c) {
          const long long index = parseInteger(nextToken(element), path, tokens.lineNumber(),
                                               [&] { return "vertex index of " + element(); });
          mesh.tets(t, c) = checkedIndex(index, 1, static_cast<int>(mesh.vertices.rows()), path,
                                         tokens.lineNumber(), element);
        }
        nextToken([&] { return "the reference of " + element(); });
      }
    } else if (keyword == "Hexahedra" || keyword == "Prisms" || keyword == "Pyramids") {
      throwAtLine(path, line,
                  "section " + quoteToken(keyword) +
                      ": only tetrahedra are supported; convert the cells to tets");
    } else {
      const int size = skippedEntrySize(keyword);
      if (size < 0) {
        throwAtLine(path, line,
                    "unknown keyword " + quoteToken(keyword) +
                        ": not an ascii Medit .mesh file tetblend can read");
      }
      const int count = nextCount("the " + std::string(keyword) + " count");
      for (long long i = 0; i < static_cast<long long>(count) * size; ++i) {
        nextToken([keyword] { return "the end of section " + std::string(keyword); });
      }
    }
  }
  return mesh;
}

void writeMedit(const std::string& path, const TetMesh& mesh) {
  checkMeshForWriting(mesh, path);
  std::string out = "MeshVersionFormatted 2\nDimension 3\nVertices\n";
  appendInteger(out, mesh.vertices.rows());
  out += '\n';
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    for (int c = 0; c < 3; ++c) {
      appendDouble(out, mesh.vertices(v, c));
      out += ' ';
    }
    out += "0\n";
  }
  out += "Tetrahedra\n";
  appendInteger(out, mesh.tets.rows());
  out += '\n';
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      appendInteger(out, mesh.tets(t, c) + 1LL);
      out += ' ';
    }
    out += "0\n";
  }
  out += "End\n";
  writeBytesAtomically(path, out);
}

}  // namespace tetblend::detail
