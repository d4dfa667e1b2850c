#include "text_parsing.h"

#include "formats.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"

namespace tetblend::detail {

std::string readFileBytes(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path + ": no such file; check the path");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path + ": cannot open the file for reading; check its permissions");
  }
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    throw InputError(path + ": read error; check the file system");
  }
  return bytes;
}

void throwAtLine(const std::string& path, std::size_t line, const std::string& message) {
  throw InputError(path + ":" + std::to_string(line) + ": " + message);
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

TextLines::TextLines(std::string_view text, char comment) : text_(text), comment_(comment) {}

bool TextLines::next() {
  while (position_ < text_.size()) {
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    std::string_view line = text_.substr(position_, end - position_);
    position_ = end + 1;
    ++lineNumber_;
    const std::size_t hash = line.find(comment_);
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    tokens_.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const std::size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) tokens_.push_back(line.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  position_ = text_.size();
  return false;
}

bool TextTokens::next(std::string_view& token) {
  while (!started_ || index_ >= lines_.tokens().size()) {
    if (!lines_.next()) return false;
    started_ = true;
    index_ = 0;
  }
  token = lines_.tokens()[index_++];
  return true;
}

bool tryParseDouble(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return !token.empty() && ec == std::errc() && end == token.data() + token.size();
}

bool tryParseInteger(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return !token.empty() && ec == std::errc() && end == token.data() + token.size();
}

std::string printableToken(std::string_view token) {
  // Long enough for any number or keyword of the formats read here, short
  // enough that the error stays one readable line.
  constexpr std::size_t kMaxQuotedBytes = 40;
  const bool shortened = token.size() > kMaxQuotedBytes;
  if (shortened) token = token.substr(0, kMaxQuotedBytes);
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char c : token) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && byte != '\\') {
      out += c;
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    }
  }
  return shortened ? out + "..." : out;
}

std::string quoteToken(std::string_view token) { return "'" + printableToken(token) + "'"; }

void throwBadNumber(std::string_view token, const std::string& path, std::size_t line,
                    const std::string& what, bool integer) {
  double ignored = 0.0;
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), ignored);
  if (!integer && ec == std::errc::result_out_of_range && end == digits.data() + digits.size()) {
    throwAtLine(path, line,
                what + " " + quoteToken(token) + " is out of the double range: rescale the data");
  }
  throwAtLine(path, line,
              std::string("expected ") + (integer ? "an integer" : "a number") + " for " + what +
                  ", found " + quoteToken(token) + ": fix the file");
}

void throwIndexOutOfRange(long long value, long long base, int count, const std::string& path,
                          std::size_t line, const std::string& element) {
  throwAtLine(path, line,
              element + ": index " + std::to_string(value) + " out of range " +
                  std::to_string(base) + ".." + std::to_string(base + count - 1) +
                  ": it refers to a vertex that does not exist");
}

int parseCount(std::string_view token, const std::string& path, std::size_t line,
               const std::string& what) {
  const long long value = parseInteger(token, path, line, what);
  if (value < 0 || value > 2147483647LL) {
    throwAtLine(path, line,
                what + " " + std::to_string(value) +
                    " is not a valid count (0..2147483647): fix the header");
  }
  return static_cast<int>(value);
}

Eigen::Index rowsToAllocate(long long count, std::size_t bytesEach, std::size_t available) {
  if (count <= 0) return 0;
  if (bytesEach == 0) return static_cast<Eigen::Index>(count);
  return static_cast<Eigen::Index>(
      std::min<unsigned long long>(static_cast<unsigned long long>(count), available / bytesEach));
}

void checkFiniteVertex(const Eigen::RowVector3d& position, const std::string& path,
                       const std::string& where, int vertex) {
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(position[c])) {
      const std::string kind = std::isnan(position[c]) ? "NaN" : "infinite";
      throw InputError(path + ":" + where + ": " + kind + " coordinate at vertex " +
                       std::to_string(vertex) + " (0-based): fix or remove the vertex");
    }
  }
}

Eigen::RowVector3d parseVertex(const std::vector<std::string_view>& tokens, std::size_t first,
                               const std::string& path, std::size_t line, int vertex) {
  if (tokens.size() < first + 3) {
    throwAtLine(
        path, line,
        "expected 3 coordinates for vertex " + std::to_string(vertex) + " (0-based), found " +
            std::to_string(tokens.size() > first ? tokens.size() - first : 0) + ": fix the line");
  }
  Eigen::RowVector3d p;
  for (int c = 0; c < 3; ++c) {
    p[c] = parseDouble(tokens[first + c], path, line,
                       [vertex] { return "coordinate of vertex " + std::to_string(vertex); });
  }
  checkFiniteVertex(p, path, std::to_string(line), vertex);
  return p;
}

void appendDouble(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

void appendInteger(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

void writeFileBytes(const std::string& tempPath, const std::string& bytes,
                    const std::string& target) {
  std::ofstream out(tempPath, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(target + ": cannot open a file for writing; check permissions");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw InputError(target + ": write failed (disk full?); check the file system");
}

void writeBytesAtomically(const std::string& path, const std::string& bytes) {
  writeFileAtomically(path,
                      [&](const std::string& tempPath) { writeFileBytes(tempPath, bytes, path); });
}

}  // namespace tetblend::detail

namespace tetblend::detail {
namespace {

template <typename Elements>
void checkForWriting(const Vertices& vertices, const Elements& elements, const std::string& path,
                     const char* elementName) {
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    checkFiniteVertex(vertices.row(v), path, " cannot write", static_cast<int>(v));
  }
  for (Eigen::Index e = 0; e < elements.rows(); ++e) {
    for (Eigen::Index c = 0; c < elements.cols(); ++c) {
      const int index = elements(e, c);
      if (index < 0 || index >= vertices.rows()) {
        throw InputError(path + ": cannot write " + elementName + " " + std::to_string(e) +
                         ": index " + std::to_string(index) + " out of range 0.." +
                         std::to_string(vertices.rows() - 1) + "; fix the mesh");
      }
    }
  }
}

}  // namespace

void checkMeshForWriting(const SurfaceMesh& mesh, const std::string& path) {
  checkForWriting(mesh.vertices, mesh.triangles, path, "triangle");
}

void checkMeshForWriting(const TetMesh& mesh, const std::string& path) {
  checkForWriting(mesh.vertices, mesh.tets, path, "tet");
}

}  // namespace tetblend::detail
