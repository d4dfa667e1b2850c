// Stanford PLY: ascii, binary_little_endian and binary_big_endian. The
// "vertex" element must have x, y, z properties (any numeric type; others are
// ignored); the "face" element must have a list property "vertex_indices" (or
// "vertex_index") whose lists have 3 or more entries (polygons are split into
// triangles, polygon_fan.h). Other elements are skipped.
// Errors in binary data name the byte offset instead of a line.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "formats.h"
#include "polygon_fan.h"
#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend::detail {
namespace {

enum class Scalar { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

struct Property {
  std::string name;
  Scalar type = Scalar::Float32;
  bool isList = false;
  Scalar countType = Scalar::Uint8;
};

struct Element {
  std::string name;
  int count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  ///< header line of the declaration
};

bool scalarFromName(std::string_view name, Scalar& type) {
  static const struct {
    const char* name;
    Scalar type;
  } kNames[] = {
      {"char", Scalar::Int8},      {"int8", Scalar::Int8},       {"uchar", Scalar::Uint8},
      {"uint8", Scalar::Uint8},    {"short", Scalar::Int16},     {"int16", Scalar::Int16},
      {"ushort", Scalar::Uint16},  {"uint16", Scalar::Uint16},   {"int", Scalar::Int32},
      {"int32", Scalar::Int32},    {"uint", Scalar::Uint32},     {"uint32", Scalar::Uint32},
      {"float", Scalar::Float32},  {"float32", Scalar::Float32}, {"double", Scalar::Float64},
      {"float64", Scalar::Float64}};
  for (const auto& entry : kNames) {
    if (name == entry.name) {
      type = entry.type;
      return true;
    }
  }
  return false;
}

std::size_t scalarSize(Scalar type) {
  switch (type) {
    case Scalar::Int8:
    case Scalar::Uint8:
      return 1;
    case Scalar::Int16:
    case Scalar::Uint16:
      return 2;
    case Scalar::Int32:
    case Scalar::Uint32:
    case Scalar::Float32:
      return 4;
    case Scalar::Float64:
      return 8;
  }
  return 0;
}

bool hostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Reads binary scalars of either byte order from the data section.
class BinaryCursor {
 public:
  BinaryCursor(const std::string& path, std::string_view data, std::size_t offset, bool little)
      : path_(path), data_(data), offset_(offset), swap_(little != hostIsLittleEndian()) {}

  template <typename What>
  double read(Scalar type, const What& what) {
    const std::size_t size = scalarSize(type);
    if (offset_ + size > data_.size()) {
      throw InputError(path_ + ": byte offset " + std::to_string(offset_) + ": file ends inside " +
                       describe(what) + ": the file is truncated");
    }
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + offset_, size);
    if (swap_) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
    }
    offset_ += size;
    switch (type) {
      case Scalar::Int8:
        return static_cast<double>(load<std::int8_t>(bytes));
      case Scalar::Uint8:
        return static_cast<double>(load<std::uint8_t>(bytes));
      case Scalar::Int16:
        return static_cast<double>(load<std::int16_t>(bytes));
      case Scalar::Uint16:
        return static_cast<double>(load<std::uint16_t>(bytes));
      case Scalar::Int32:
        return static_cast<double>(load<std::int32_t>(bytes));
      case Scalar::Uint32:
        return static_cast<double>(load<std::uint32_t>(bytes));
      case Scalar::Float32:
        return static_cast<double>(load<float>(bytes));
      case Scalar::Float64:
        return load<double>(bytes);
    }
    return 0.0;
  }
  std::size_t offset() const { return offset_; }

 private:
  template <typename T>
  static T load(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }
  const std::string& path_;
  std::string_view data_;
  std::size_t offset_;
  bool swap_;
};

enum class Encoding { Ascii, BinaryLittle, BinaryBig };

// Parses the header; `lines` is left on the end_header line.
std::vector<Element> parseHeader(const std::string& path, TextLines& lines, Encoding& encoding) {
  if (!lines.next() || lines.tokens()[0] != "ply") {
    throwAtLine(path, lines.lineNumber(), "missing the 'ply' magic line: not a PLY file");
  }
  bool haveFormat = false;
  std::vector<Element> elements;
  while (lines.next()) {
    const auto& t = lines.tokens();
    const std::size_t line = lines.lineNumber();
    if (t[0] == "end_header") {
      if (!haveFormat) throwAtLine(path, line, "the header has no 'format' line: fix the header");
      return elements;
    }
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format") {
      if (t.size() < 2) throwAtLine(path, line, "incomplete 'format' line: fix the header");
      if (t[1] == "ascii") {
        encoding = Encoding::Ascii;
      } else if (t[1] == "binary_little_endian") {
        encoding = Encoding::BinaryLittle;
      } else if (t[1] == "binary_big_endian") {
        encoding = Encoding::BinaryBig;
      } else {
        throwAtLine(path, line,
                    "unknown PLY format " + quoteToken(t[1]) +
                        ": expected ascii, binary_little_endian or binary_big_endian");
      }
      haveFormat = true;
    } else if (t[0] == "element") {
      if (t.size() < 3)
        throwAtLine(path, line, "expected 'element <name> <count>': fix the header");
      for (const Element& earlier : elements) {
        if (earlier.name == t[1]) {
          throwAtLine(path, line,
                      "element " + quoteToken(t[1]) + " is declared again (first on line " +
                          std::to_string(earlier.line) +
                          "): each element may be declared once; fix the header");
        }
      }
      elements.push_back(
          {std::string(t[1]), parseCount(t[2], path, line, "element count"), {}, line});
    } else if (t[0] == "property") {
      if (elements.empty()) throwAtLine(path, line, "'property' before any 'element'");
      Property p;
      const bool list = t.size() >= 2 && t[1] == "list";
      const std::size_t expected = list ? 5 : 3;
      if (t.size() < expected ||
          (list ? !scalarFromName(t[2], p.countType) || !scalarFromName(t[3], p.type)
                : !scalarFromName(t[1], p.type))) {
        throwAtLine(path, line,
                    "malformed property line: expected 'property <type> <name>' or "
                    "'property list <count type> <type> <name>' with PLY types");
      }
      p.isList = list;
      p.name = std::string(t[expected - 1]);
      elements.back().properties.push_back(p);
    } else {
      throwAtLine(path, line, "unknown header keyword " + quoteToken(t[0]) + ": fix the header");
    }
  }
  throwAtLine(path, lines.lineNumber(), "the header has no 'end_header' line: fix the header");
}

// Reads one value at a time from either encoding, tracking where it is.
class ValueSource {
 public:
  ValueSource(const std::string& path, const std::string& text, TextLines& lines, Encoding encoding)
      : path_(path),
        lines_(lines),
        ascii_(encoding == Encoding::Ascii),
        binary_(path, text, lines.endOffset(), encoding == Encoding::BinaryLittle) {}

  // Starts a new element instance (one line in ascii).
  template <typename What>
  void beginRow(const What& what) {
    if (!ascii_) return;
    if (!lines_.next()) {
      throwAtLine(path_, lines_.lineNumber(),
                  "file ends before " + describe(what) + ": the file is truncated");
    }
    column_ = 0;
  }
  template <typename What>
  double value(Scalar type, const What& what) {
    if (!ascii_) return binary_.read(type, what);
    if (column_ >= lines_.tokens().size()) {
      throwAtLine(path_, lines_.lineNumber(), "too few values on the line for " + describe(what));
    }
    const std::string_view token = lines_.tokens()[column_++];
    return type == Scalar::Float32 || type == Scalar::Float64
               ? parseDouble(token, path_, lines_.lineNumber(), what)
               : static_cast<double>(parseInteger(token, path_, lines_.lineNumber(), what));
  }
  // The current line (ascii) or byte offset (binary).
  std::size_t position() const { return ascii_ ? lines_.lineNumber() : binary_.offset(); }
  // The "<line>" or " byte offset <n>" part of a message for `position`.
  std::string where(std::size_t position) const {
    return ascii_ ? std::to_string(position) : " byte offset " + std::to_string(position);
  }

 private:
  const std::string& path_;
  TextLines& lines_;
  bool ascii_;
  BinaryCursor binary_;
  std::size_t column_ = 0;
};

bool isIndexList(const Property& p) {
  return p.isList && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// Checks, before anything is allocated, that a vertex element with rows has
// x, y and z and a face element with rows its index list.
void checkElements(const std::string& path, const std::vector<Element>& elements) {
  for (const Element& e : elements) {
    if (e.count == 0) continue;
    int axes = 0;
    bool indices = false;
    for (const Property& p : e.properties) {
      if (!p.isList) axes |= p.name == "x" ? 1 : p.name == "y" ? 2 : p.name == "z" ? 4 : 0;
      indices = indices || isIndexList(p);
    }
    if (e.name == "vertex" && axes != 7) {
      throw InputError(path + ": the vertex element lacks x, y or z properties");
    }
    if (e.name == "face" && !indices) {
      throw InputError(path + ": the face element has no 'vertex_indices' list property");
    }
  }
}

// The fewest bytes one row of `e` takes: in binary its fixed-size properties
// plus the count of each list, in ascii one byte per property (at least one:
// a row is a line with a token).
std::size_t minimumRowBytes(const Element& e, Encoding encoding) {
  std::size_t bytes = 0;
  for (const Property& p : e.properties) {
    bytes += encoding == Encoding::Ascii ? 1 : scalarSize(p.isList ? p.countType : p.type);
  }
  return encoding == Encoding::Ascii ? std::max<std::size_t>(bytes, 1) : bytes;
}

}  // namespace

SurfaceMesh readPly(const std::string& path) {
  const std::string text = readFileBytes(path);
  TextLines lines(text, '\0');
  Encoding encoding = Encoding::Ascii;
  const std::vector<Element> elements = parseHeader(path, lines, encoding);
  int vertexCount = -1;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertexCount = e.count;
  }
  if (vertexCount < 0) throw InputError(path + ": no 'vertex' element in the header");
  checkElements(path, elements);
  // Rows are allocated for what the data after the header can hold, not for
  // the header's counts (which may be wrong by billions).
  const std::size_t available = text.size() - std::min(text.size(), lines.endOffset());

  SurfaceMesh mesh;
  mesh.vertices.resize(0, 3);
  PolygonFaces polygons;  // grows with the lists actually read
  ValueSource source(path, text, lines, encoding);
  for (const Element& e : elements) {
    // Rows without properties hold no bytes (binary) or no tokens (ascii):
    // nothing to read, however large the count.
    if (e.properties.empty()) continue;
    const bool isVertex = e.name == "vertex";
    const bool isFace = e.name == "face";
    const Eigen::Index rows = rowsToAllocate(e.count, minimumRowBytes(e, encoding), available);
    if (isVertex) mesh.vertices.resize(rows, 3);
    std::vector<int> axes;
    for (const Property& p : e.properties) {
      axes.push_back(p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1);
    }
    // The face's corners: its first index list (checkElements: it has one).
    std::size_t cornerList = e.properties.size();
    for (std::size_t k = 0; k < e.properties.size() && isFace; ++k) {
      if (isIndexList(e.properties[k])) {
        cornerList = k;
        break;
      }
    }
    for (int i = 0; i < e.count; ++i) {
      const auto element = [&e, i] {
        return printableToken(e.name) + " " + std::to_string(i) + " (0-based)";
      };
      source.beginRow(element);
      if (isVertex) growRows(mesh.vertices, i, e.count);
      const std::size_t rowPosition = source.position();
      const auto where = [&] { return source.where(rowPosition); };
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        const int axis = axes[k];
        if (!p.isList) {
          const double value = source.value(
              p.type, [&] { return "property " + quoteToken(p.name) + " of " + element(); });
          if (isVertex && axis >= 0) {
            mesh.vertices(i, axis) = value;
          }
          continue;
        }
        const double corners =
            source.value(p.countType, [&] { return "list length of " + element(); });
        // NaN, fractions and 1e30 (float count types) are refused before the
        // conversion to int; a large whole count fails where the data ends.
        constexpr double kMaxListLength = 2147483647.0;  // the int loop counter's range
        if (!(corners <= kMaxListLength) || corners != std::floor(corners)) {
          std::string length;
          appendDouble(length, corners);
          throw InputError(path + ":" + where() + ": list length " + length + " of " + element() +
                           " is not a whole number of entries: fix the file");
        }
        if (corners < 0) throw InputError(path + ":" + where() + ": negative list length");
        const bool indices = k == cornerList;
        if (indices && corners < 3) {
          throw InputError(path + ":" + where() + ": face " + std::to_string(i) +
                           " (0-based) has " + std::to_string(static_cast<long long>(corners)) +
                           " vertices: a face needs 3");
        }
        for (int c = 0; c < static_cast<int>(corners); ++c) {
          const double value = source.value(p.type, [&] { return "list entry of " + element(); });
          if (!indices) continue;
          // NaN, fractions and values beyond int (float index types) are
          // refused before the conversion to int.
          if (!(value >= 0 && value < vertexCount) || value != std::floor(value)) {
            std::string index;
            appendDouble(index, value);
            throw InputError(path + ":" + where() + ": " + element() + ": index " + index +
                             (value != std::floor(value) && std::isfinite(value)
                                  ? " is not a whole number: fix the file"
                                  : " out of range 0.." + std::to_string(vertexCount - 1) +
                                        ": it refers to a vertex that does not exist"));
          }
          polygons.corners.push_back(static_cast<int>(value));
        }
        if (indices) polygons.closeFace();
      }
      if (isVertex) checkFiniteVertex(mesh.vertices.row(i), path, where(), i);
    }
  }
  mesh.triangles = fanTriangles(polygons);
  return mesh;
}

void writePly(const std::string& path, const SurfaceMesh& mesh, bool binary) {
  checkMeshForWriting(mesh, path);
  std::string out = "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by tetblend\nelement vertex ";
  appendInteger(out, mesh.vertices.rows());
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  appendInteger(out, mesh.triangles.rows());
  out += "\nproperty list uchar int vertex_indices\nend_header\n";
  const bool swap = !hostIsLittleEndian();
  const auto appendRaw = [&](const auto value) {
    char bytes[sizeof(value)];
    std::memcpy(bytes, &value, sizeof(value));
    if (swap) {
      for (std::size_t i = 0; i < sizeof(value) / 2; ++i)
        std::swap(bytes[i], bytes[sizeof(value) - 1 - i]);
    }
    out.append(bytes, sizeof(value));
  };
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    for (int c = 0; c < 3; ++c) {
      if (binary) {
        appendRaw(mesh.vertices(v, c));
      } else {
        if (c > 0) out += ' ';
        appendDouble(out, mesh.vertices(v, c));
      }
    }
    if (!binary) out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    if (binary) {
      appendRaw(std::uint8_t{3});
      for (int c = 0; c < 3; ++c) appendRaw(std::int32_t{mesh.triangles(f, c)});
    } else {
      out += '3';
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        appendInteger(out, mesh.triangles(f, c));
      }
      out += '\n';
    }
  }
  writeBytesAtomically(path, out);
}

}  // namespace tetblend::detail
