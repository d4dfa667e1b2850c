// STL, ascii ("solid ... facet normal ... outer loop vertex x y z ...") and
// binary (80-byte header, uint32 count, 50 bytes per triangle, little endian
// float32). A file is binary when its size is exactly 84 + 50 * count, since
// binary files may also start with "solid". STL repeats each corner per
// triangle: exactly coincident corners are merged, and vertices are numbered
// in order of first appearance.

#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "formats.h"
#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend::detail {
namespace {

// Merges bitwise-equal positions (with -0 == +0), numbering new ones in order.
class VertexWelder {
 public:
  int add(Eigen::RowVector3d p) {
    Key key{};
    for (int c = 0; c < 3; ++c) {
      const double value = p[c] + 0.0;  // -0.0 + 0.0 == +0.0
      std::memcpy(&key.bits[c], &value, sizeof(double));
    }
    const auto [it, inserted] = index_.emplace(key, static_cast<int>(positions_.size()));
    if (inserted) positions_.push_back(p);
    return it->second;
  }
  Vertices vertices() const {
    Vertices v(static_cast<Eigen::Index>(positions_.size()), 3);
    for (std::size_t i = 0; i < positions_.size(); ++i)
      v.row(static_cast<Eigen::Index>(i)) = positions_[i];
    return v;
  }
  int count() const { return static_cast<int>(positions_.size()); }

 private:
  struct Key {
    std::uint64_t bits[3];
    bool operator==(const Key& o) const {
      return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ULL;
      for (std::uint64_t b : k.bits) h = (h ^ b) * 1099511628211ULL;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_map<Key, int, KeyHash> index_;
  std::vector<Eigen::RowVector3d> positions_;
};

SurfaceMesh readBinaryStl(const std::string& path, const std::string& bytes, std::uint32_t count) {
  VertexWelder welder;
  SurfaceMesh mesh;
  mesh.triangles.resize(static_cast<Eigen::Index>(count), 3);
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::size_t offset = 84 + 50 * static_cast<std::size_t>(f);
    for (int c = 0; c < 3; ++c) {
      Eigen::RowVector3d p;
      for (int k = 0; k < 3; ++k) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, bytes.data() + offset + 12 + 12 * c + 4 * k, 4);
        // STL is little endian; assemble the value independently of the host.
        unsigned char b[4];
        std::memcpy(b, &bits, 4);
        const std::uint32_t le =
            static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
            static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
        float value = 0.0f;
        std::memcpy(&value, &le, 4);
        p[k] = static_cast<double>(value);
      }
      checkFiniteVertex(p, path, " byte offset " + std::to_string(offset + 12 + 12 * c),
                        welder.count());
      mesh.triangles(static_cast<Eigen::Index>(f), c) = welder.add(p);
    }
  }
  mesh.vertices = welder.vertices();
  return mesh;
}

SurfaceMesh readAsciiStl(const std::string& path, const std::string& text) {
  TextLines lines(text, '\0');
  VertexWelder welder;
  std::vector<Eigen::RowVector3i> triangles;
  Eigen::RowVector3i triangle;
  int corner = -1;  // -1: outside a facet's loop
  std::size_t facetLine = 0;
  while (lines.next()) {
    const auto& t = lines.tokens();
    const std::size_t line = lines.lineNumber();
    if (t[0] == "outer") {
      corner = 0;
      facetLine = line;
    } else if (t[0] == "vertex") {
      if (corner < 0) throwAtLine(path, line, "'vertex' outside 'outer loop': fix the file");
      if (corner == 3) {
        throwAtLine(path, line,
                    "facet " + std::to_string(triangles.size()) +
                        " (0-based) has more than 3 vertices: triangulate it first");
      }
      if (t.size() != 4) {
        throwAtLine(path, line,
                    "expected 3 coordinates after 'vertex', found " + std::to_string(t.size() - 1) +
                        ": fix the line");
      }
      const Eigen::RowVector3d p = parseVertex(t, 1, path, line, welder.count());
      triangle[corner++] = welder.add(p);
    } else if (t[0] == "endloop") {
      if (corner != 3) {
        throwAtLine(path, line,
                    "facet " + std::to_string(triangles.size()) + " (0-based) has " +
                        std::to_string(std::max(corner, 0)) + " vertices: a facet needs 3");
      }
      triangles.push_back(triangle);
      corner = -1;
    } else if (t[0] != "solid" && t[0] != "facet" && t[0] != "endfacet" && t[0] != "endsolid") {
      throwAtLine(path, line, "unexpected keyword " + quoteToken(t[0]) + " in ascii STL");
    }
  }
  if (corner >= 0)
    throwAtLine(path, facetLine, "facet not closed by 'endloop': the file is truncated");
  SurfaceMesh mesh;
  mesh.vertices = welder.vertices();
  mesh.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    mesh.triangles.row(static_cast<Eigen::Index>(f)) = triangles[f];
  return mesh;
}

}  // namespace

SurfaceMesh readStl(const std::string& path) {
  const std::string bytes = readFileBytes(path);
  if (bytes.size() >= 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + 80);
    const std::uint32_t count =
        static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
        static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
    if (bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) {
      return readBinaryStl(path, bytes, count);
    }
  }
  if (bytes.compare(0, 5, "solid") == 0) return readAsciiStl(path, bytes);
  throw InputError(path + ":1: neither ascii STL (starts with 'solid') nor binary STL (size " +
                   std::to_string(bytes.size()) + " bytes is not 84 + 50 * triangle count): " +
                   "the file is truncated or not STL");
}

}  // namespace tetblend::detail
