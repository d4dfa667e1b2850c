// Wavefront OBJ: "v x y z [w | r g b]" vertices and "f a b c" faces, where a
// corner may be written i, i/t, i//n or i/t/n and negative indices count back
// from the last vertex read so far. Every other statement (vt, vn, o, g, s,
// usemtl, mtllib, l, ...) is ignored.

#include <string>
#include <vector>

#include "formats.h"
#include "polygon_fan.h"
#include "text_parsing.h"

namespace tetblend::detail {

SurfaceMesh readObj(const std::string& path) {
  const std::string text = readFileBytes(path);
  TextLines lines(text);
  std::vector<Eigen::RowVector3d> positions;
  struct Face {
    std::size_t firstCorner;  // into `corners`
    std::size_t line;
    std::size_t verticesBefore;
  };
  std::vector<Face> faces;
  std::vector<long long> corners;  // as written: 1-based or relative
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    if (tokens[0] == "v") {
      positions.push_back(
          parseVertex(tokens, 1, path, lines.lineNumber(), static_cast<int>(positions.size())));
    } else if (tokens[0] == "f") {
      const std::size_t count = tokens.size() - 1;
      if (count < 3) {
        throwAtLine(path, lines.lineNumber(),
                    "face " + std::to_string(faces.size()) + " (0-based) has " +
                        std::to_string(count) + " vertices: a face needs 3");
      }
      faces.push_back(Face{corners.size(), lines.lineNumber(), positions.size()});
      for (std::size_t c = 0; c < count; ++c) {
        const std::string_view corner = tokens[1 + c];
        corners.push_back(parseInteger(
            corner.substr(0, corner.find('/')), path, lines.lineNumber(),
            [&] { return "vertex index of face " + std::to_string(faces.size() - 1); }));
      }
    }
  }
  SurfaceMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    mesh.vertices.row(static_cast<Eigen::Index>(v)) = positions[v];
  }
  const int count = static_cast<int>(positions.size());
  PolygonFaces polygons;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto element = [f] { return "face " + std::to_string(f) + " (0-based)"; };
    const std::size_t end = f + 1 < faces.size() ? faces[f + 1].firstCorner : corners.size();
    for (std::size_t c = faces[f].firstCorner; c < end; ++c) {
      long long index = corners[c];
      if (index < 0) {
        // Relative index: -1 is the last vertex defined before this face.
        const long long resolved = static_cast<long long>(faces[f].verticesBefore) + index + 1;
        if (resolved < 1) {
          throwAtLine(path, faces[f].line,
                      element() + ": relative index " + std::to_string(index) + " reaches before " +
                          "the first vertex (only " + std::to_string(faces[f].verticesBefore) +
                          " defined so far): fix the face");
        }
        index = resolved;
      }
      polygons.corners.push_back(checkedIndex(index, 1, count, path, faces[f].line, element));
    }
    polygons.closeFace();
  }
  mesh.triangles = fanTriangles(polygons);
  return mesh;
}

void writeObj(const std::string& path, const SurfaceMesh& mesh) {
  checkMeshForWriting(mesh, path);
  std::string out;
  out.reserve(static_cast<std::size_t>(mesh.vertices.rows() * 64 + mesh.triangles.rows() * 32));
  out += "# written by tetblend\n";
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    out += 'v';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      appendDouble(out, mesh.vertices(v, c));
    }
    out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    out += 'f';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      appendInteger(out, mesh.triangles(f, c) + 1LL);
    }
    out += '\n';
  }
  writeBytesAtomically(path, out);
}

}  // namespace tetblend::detail
