// Geomview OFF: a header keyword (OFF, COFF, NOFF, CNOFF, STOFF, ...; the
// counts may follow on the same line), "#V #F #E", #V vertex lines (extra
// values such as colours or normals are ignored) and #F face lines
// "k i0 .. ik-1 [colour]" with 0-based indices, k >= 3 (polygons are split
// into triangles, polygon_fan.h).

#include <algorithm>
#include <string>

#include "formats.h"
#include "polygon_fan.h"
#include "text_parsing.h"

namespace tetblend::detail {

SurfaceMesh readOff(const std::string& path) {
  const std::string text = readFileBytes(path);
  TextLines lines(text);
  if (!lines.next()) throwAtLine(path, 1, "empty file: expected an OFF header");
  const std::string_view keyword = lines.tokens()[0];
  const bool isOff = keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF";
  if (!isOff || keyword.find('4') != std::string_view::npos ||
      (keyword.size() > 3 && keyword[keyword.size() - 4] == 'n')) {
    throwAtLine(path, lines.lineNumber(),
                "expected the header 'OFF' (3D), found " + quoteToken(keyword) +
                    ": only 3D OFF files are supported");
  }
  std::vector<std::string_view> counts(lines.tokens().begin() + 1, lines.tokens().end());
  std::size_t countLine = lines.lineNumber();
  if (counts.empty()) {
    if (!lines.next()) throwAtLine(path, lines.lineNumber(), "missing the '#V #F #E' counts line");
    counts = lines.tokens();
    countLine = lines.lineNumber();
  }
  if (counts.size() < 2) {
    throwAtLine(path, countLine,
                "expected '#vertices #faces #edges', found " + std::to_string(counts.size()) +
                    " value(s): fix the header");
  }
  const int vertexCount = parseCount(counts[0], path, countLine, "vertex count");
  const int faceCount = parseCount(counts[1], path, countLine, "face count");
  // Allocations are bounded by the data: in text each value takes at least one
  // byte, and a vertex line has 3 values. Faces grow as their lines are read.
  constexpr std::size_t kMinVertexBytes = 3;
  const std::size_t available = text.size() - std::min(text.size(), lines.endOffset());

  SurfaceMesh mesh;
  mesh.vertices.resize(rowsToAllocate(vertexCount, kMinVertexBytes, available), 3);
  for (int v = 0; v < vertexCount; ++v) {
    if (!lines.next()) {
      throwAtLine(path, lines.lineNumber(),
                  "file ends after " + std::to_string(v) + " of " + std::to_string(vertexCount) +
                      " vertices: fix the header or the data");
    }
    growRows(mesh.vertices, v, vertexCount);
    mesh.vertices.row(v) = parseVertex(lines.tokens(), 0, path, lines.lineNumber(), v);
  }
  PolygonFaces polygons;  // grows with the face lines actually read
  for (int f = 0; f < faceCount; ++f) {
    if (!lines.next()) {
      throwAtLine(path, lines.lineNumber(),
                  "file ends after " + std::to_string(f) + " of " + std::to_string(faceCount) +
                      " faces: fix the header or the data");
    }
    const auto& tokens = lines.tokens();
    const auto element = [f] { return "face " + std::to_string(f) + " (0-based)"; };
    const long long corners = parseInteger(tokens[0], path, lines.lineNumber(),
                                           [&] { return "vertex count of " + element(); });
    if (corners < 3) {
      throwAtLine(path, lines.lineNumber(),
                  element() + " has " + std::to_string(corners) + " vertices: a face needs 3");
    }
    if (static_cast<long long>(tokens.size()) - 1 < corners) {
      throwAtLine(path, lines.lineNumber(),
                  element() + ": expected " + std::to_string(corners) + " vertex indices, found " +
                      std::to_string(tokens.size() - 1));
    }
    for (long long c = 0; c < corners; ++c) {
      const long long index =
          parseInteger(tokens[static_cast<std::size_t>(1 + c)], path, lines.lineNumber(),
                       [&] { return "vertex index of " + element(); });
      polygons.corners.push_back(
          checkedIndex(index, 0, vertexCount, path, lines.lineNumber(), element));
    }
    polygons.closeFace();
  }
  mesh.triangles = fanTriangles(polygons);
  return mesh;
}

void writeOff(const std::string& path, const SurfaceMesh& mesh) {
  checkMeshForWriting(mesh, path);
  std::string out;
  out.reserve(static_cast<std::size_t>(mesh.vertices.rows() * 64 + mesh.triangles.rows() * 32));
  out += "OFF\n";
  appendInteger(out, mesh.vertices.rows());
  out += ' ';
  appendInteger(out, mesh.triangles.rows());
  out += " 0\n";
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    for (int c = 0; c < 3; ++c) {
      if (c > 0) out += ' ';
      appendDouble(out, mesh.vertices(v, c));
    }
    out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    out += '3';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      appendInteger(out, mesh.triangles(f, c));
    }
    out += '\n';
  }
  writeBytesAtomically(path, out);
}

}  // namespace tetblend::detail
