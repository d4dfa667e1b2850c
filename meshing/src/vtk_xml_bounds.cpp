#include "vtk_xml_bounds.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <zlib.h>

#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend::detail {
namespace {

// Largest uncompressed/compressed ratio of one block: deflate (zlib) cannot
// exceed 1032:1 and LZ4 255:1; LZMA has no tight bound, so other compressors
// get a generous one.
constexpr std::uint64_t kZlibRatio = 1032;
constexpr std::uint64_t kLz4Ratio = 256;
constexpr std::uint64_t kOtherRatio = 1ULL << 16;

constexpr const char* kCountAttributes[] = {"NumberOfPoints", "NumberOfCells", "NumberOfVerts",
                                            "NumberOfLines",  "NumberOfStrips", "NumberOfPolys",
                                            "NumberOfTuples"};

[[noreturn]] void damaged(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what + ": the file is damaged or truncated");
}

// The value of attribute `name` in the tag that starts at `tag`, or "".
std::string_view attribute(std::string_view text, std::size_t tag, std::string_view name) {
  const std::size_t end = text.find('>', tag);
  const std::string_view element =
      text.substr(tag, end == std::string_view::npos ? end : end - tag);
  const std::string key = " " + std::string(name) + "=\"";
  const std::size_t at = element.find(key);
  if (at == std::string_view::npos) return {};
  const std::size_t first = at + key.size();
  const std::size_t last = element.find('"', first);
  return element.substr(first, last == std::string_view::npos ? last : last - first);
}

// A decimal attribute value; values beyond 2^64 count as the largest.
std::uint64_t decimal(std::string_view value) {
  std::uint64_t n = 0;
  for (const char c : value) {
    if (c < '0' || c > '9') break;
    const auto digit = static_cast<std::uint64_t>(c - '0');
    if (n > (UINT64_MAX - digit) / 10) return UINT64_MAX;
    n = 10 * n + digit;
  }
  return n;
}

// Decoded bytes of base64 text from `text`, skipping whitespace and padding,
// up to `limit` bytes.
std::string base64Prefix(std::string_view text, std::size_t limit) {
  static const std::string_view kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (out.size() >= limit || c == '<' || c == '_') break;
    const std::size_t value = kAlphabet.find(c);
    if (value == std::string_view::npos) continue;
    bits = (bits << 6) | static_cast<std::uint32_t>(value);
    if (++count == 4) {
      for (int shift = 16; shift >= 0; shift -= 8) out += static_cast<char>((bits >> shift) & 0xff);
      bits = 0;
      count = 0;
    }
  }
  return out;
}

struct Layout {
  std::size_t word = 4;  // header_type UInt32 or UInt64
  bool bigEndian = false;
  std::uint64_t ratio = kZlibRatio;
};

// The unsigned value of the `size`-byte integer at `bytes[at]`.
std::uint64_t integerAt(std::string_view bytes, std::size_t at, std::size_t size,
                        bool bigEndian) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[at + (bigEndian ? i : size - 1 - i)]);
  }
  return value;
}

// Header word `index` (UInt32 or UInt64, the file's byte order).
std::uint64_t word(std::string_view bytes, std::size_t index, const Layout& layout) {
  return integerAt(bytes, index * layout.word, layout.word, layout.bigEndian);
}

// Checks the compression header at the start of `header` (decoded bytes);
// `room` bytes (decoded) follow the header's start in the file.
void checkBlockHeader(const std::string& path, std::string_view header, std::uint64_t room,
                      const Layout& layout) {
  if (header.size() < 3 * layout.word) return;  // VTK reports the short header itself
  const std::uint64_t blocks = word(header, 0, layout);
  if (blocks > room / layout.word) {
    damaged(path, "a compressed array declares " + std::to_string(blocks) + " blocks in " +
                      std::to_string(room) + " bytes");
  }
  const std::uint64_t blockSize = word(header, 1, layout);
  const std::uint64_t lastSize = word(header, 2, layout);
  // VTK 9.1 computes the array's size as blocks × blockSize − blockSize +
  // lastSize: with no block and a partial last block that wraps around and
  // VTK reads a block table it never allocated.
  if (blocks == 0 && lastSize != 0) {
    damaged(path, "a compressed array declares no block but a last block of " +
                      std::to_string(lastSize) + " bytes");
  }
  // The nominal block size is only stored when some block is full: an array
  // shorter than one block has one partial block of lastSize bytes, and its
  // header still names the writer's 32 KB (which an LZ4 array of 60 bytes
  // cannot hold).
  const bool fullBlock = blocks > 1 || (blocks == 1 && lastSize == 0);
  if ((fullBlock && blockSize / layout.ratio > room) || lastSize / layout.ratio > room) {
    damaged(path, "a compressed array declares blocks of " + std::to_string(blockSize) +
                      " bytes in " + std::to_string(room) + " bytes");
  }
  const std::size_t listed = std::min<std::uint64_t>(blocks, header.size() / layout.word - 3);
  for (std::size_t b = 0; b < listed; ++b) {
    const std::uint64_t compressed = word(header, 3 + b, layout);
    const std::uint64_t size = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
    if (compressed > room || size / layout.ratio > compressed) {
      damaged(path, "compressed block " + std::to_string(b) + " of " + std::to_string(compressed) +
                        " bytes declares " + std::to_string(size) + " bytes uncompressed");
    }
  }
}


// Bytes of an integer of VTK type `type` (Int8 ... UInt64), 0 for others.
std::size_t integerSize(std::string_view type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32") return 4;
  if (type == "Int64" || type == "UInt64") return 8;
  return 0;
}


// Where an array's bytes are: raw (appended raw data) or base64.
struct ArrayBytes {
  std::string_view text;  // from the array's first header byte to the end of the file
  bool raw = false;
};

// The first `count` decoded bytes of an array (header included).
std::string decodedPrefix(const ArrayBytes& array, std::size_t count) {
  return array.raw ? std::string(array.text.substr(0, count)) : base64Prefix(array.text, count);
}

// The largest of the `size`-byte values in `bytes[from, to)` (unsigned: a
// negative value counts as huge), into `largest`.
void takeLargest(std::string_view bytes, std::size_t from, std::size_t to, std::size_t size,
                 bool bigEndian, std::uint64_t& largest) {
  for (std::size_t at = from; at + size <= to; at += size) {
    largest = std::max(largest, integerAt(bytes, at, size, bigEndian));
  }
}

// The largest `size`-byte value an array holds, where it can be read
// cheaply: uncompressed (VTK encodes its header and data as one base64 run),
// or zlib-compressed raw appended data; nothing otherwise (VTK judges). VTK
// reads as many values as the piece needs, wherever the header says the
// array ends, so every value the header covers counts.
std::optional<std::uint64_t> largestValue(const ArrayBytes& array, std::size_t size,
                                          bool compressed, bool zlib, const Layout& layout) {
  const std::size_t room = array.text.size();
  std::uint64_t largest = 0;
  if (!compressed) {
    const std::string header = decodedPrefix(array, layout.word);
    if (header.size() < layout.word) return std::nullopt;
    const std::uint64_t count = std::min<std::uint64_t>(word(header, 0, layout), room);
    const std::string bytes = decodedPrefix(array, layout.word + count);
    takeLargest(bytes, layout.word, bytes.size(), size, layout.bigEndian, largest);
    return largest;
  }
  if (!zlib || !array.raw || room < 3 * layout.word) return std::nullopt;
  const std::uint64_t blocks = word(array.text, 0, layout);
  const std::uint64_t blockSize = word(array.text, 1, layout);
  const std::uint64_t lastSize = word(array.text, 2, layout);
  if (blocks == 0 || blocks > room / layout.word - 3 || blockSize % size != 0) return std::nullopt;
  std::size_t at = (3 + blocks) * layout.word;  // the first block's compressed bytes
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressedSize = word(array.text, 3 + b, layout);
    uLongf inflated = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
    if (compressedSize > room - at || inflated / layout.ratio > compressedSize) return std::nullopt;
    std::string out(inflated, '\0');
    if (uncompress(reinterpret_cast<Bytef*>(out.data()), &inflated,
                   reinterpret_cast<const Bytef*>(array.text.data() + at),
                   compressedSize) != Z_OK) {
      return std::nullopt;
    }
    takeLargest(out, 0, inflated, size, layout.bigEndian, largest);
    at += compressedSize;
  }
  return largest;
}

// The largest value of an ascii integer array whose values start at
// `values` (a negative one counts as 0: VTK refuses it itself).
std::uint64_t largestAsciiValue(std::string_view text, std::size_t values) {
  const std::size_t end = text.find('<', values);
  const std::string_view body =
      text.substr(values, end == std::string_view::npos ? end : end - values);
  std::uint64_t largest = 0;
  std::size_t at = 0;
  while ((at = body.find_first_not_of(" \t\r\n", at)) != std::string_view::npos) {
    const std::size_t next = body.find_first_of(" \t\r\n", at);
    largest = std::max(largest, decimal(body.substr(at, next == std::string_view::npos
                                                            ? next
                                                            : next - at)));
    at = next;
  }
  return largest;
}

}  // namespace

void checkVtkXmlBounds(const std::string& path, const std::string& bytes) {
  const std::string_view text(bytes);
  const std::size_t appended = text.find("<AppendedData");
  const std::string_view xml = text.substr(0, appended);
  const std::size_t file = xml.find("<VTKFile");
  if (file == std::string_view::npos) return;  // VTK refuses it itself
  const std::string_view compressor = attribute(xml, file, "compressor");
  Layout layout;
  layout.word = attribute(xml, file, "header_type") == "UInt64" ? 8 : 4;
  layout.bigEndian = attribute(xml, file, "byte_order") == "BigEndian";
  layout.ratio = compressor == "vtkZLibDataCompressor"  ? kZlibRatio
                 : compressor == "vtkLZ4DataCompressor" ? kLz4Ratio
                                                        : kOtherRatio;
  const std::uint64_t limit = bytes.size() * (compressor.empty() ? 1 : layout.ratio);
  std::uint64_t largestCount = 0;
  for (const char* name : kCountAttributes) {
    const std::string key = std::string(" ") + name + "=\"";
    for (std::size_t at = xml.find(key); at != std::string_view::npos; at = xml.find(key, at + 1)) {
      const std::uint64_t count = decimal(xml.substr(at + key.size()));
      if (count > limit) {
        damaged(path, std::string(name) + " " + std::to_string(count) + " is more than its " +
                          std::to_string(bytes.size()) + " bytes can hold");
      }
      largestCount = std::max(largestCount, count);
    }
  }
  // VTK sizes an array as tuples × components before reading its values.
  const std::string componentsKey = " NumberOfComponents=\"";
  for (std::size_t at = xml.find(componentsKey); at != std::string_view::npos;
       at = xml.find(componentsKey, at + 1)) {
    const std::uint64_t components = decimal(xml.substr(at + componentsKey.size()));
    if (components > limit || (components > 0 && largestCount > limit / components)) {
      damaged(path, "NumberOfComponents " + std::to_string(components) + " for " +
                        std::to_string(largestCount) + " tuples is more than its " +
                        std::to_string(bytes.size()) + " bytes can hold");
    }
  }
  // Appended data starts after the '_' that follows the AppendedData tag.
  // VTK skips the first character after the tag and its white space without
  // looking at it, so anything but '_' there shifts every header it reads.
  std::size_t underscore = std::string_view::npos;
  if (appended != std::string_view::npos) {
    const std::size_t tagEnd = text.find('>', appended);
    underscore = tagEnd == std::string_view::npos
                     ? tagEnd
                     : text.find_first_not_of(" \t\r\n", tagEnd + 1);
    if (underscore != std::string_view::npos && text[underscore] != '_') {
      damaged(path, "the appended data does not start with '_'");
    }
  }
  const std::size_t data = underscore == std::string_view::npos ? text.size() : underscore + 1;
  const bool rawAppended =
      appended != std::string_view::npos && attribute(text, appended, "encoding") == "raw";
  const bool compressed = !compressor.empty();
  const std::size_t maxHeader = 3 * layout.word + 64 * layout.word;  // enough blocks to judge
  for (std::size_t tag = xml.find("<DataArray"); tag != std::string_view::npos;
       tag = xml.find("<DataArray", tag + 1)) {
    const std::string_view format = attribute(xml, tag, "format");
    // VTK sizes a cell array's connectivity from its last offset, a value in
    // the data: bound the offsets where they can be read cheaply.
    const bool offsets = attribute(xml, tag, "Name") == "offsets";
    const std::size_t valueSize = integerSize(attribute(xml, tag, "type"));
    std::optional<std::uint64_t> lastOffset;
    std::size_t start = 0;
    // VTK reads an array with an offset from the appended data unless its
    // format says otherwise, also when the format attribute is missing.
    const bool inAppended =
        format == "appended" ||
        (format != "binary" && format != "ascii" && !attribute(xml, tag, "offset").empty());
    if (inAppended) {
      const std::uint64_t offset = decimal(attribute(xml, tag, "offset"));
      if (offset >= text.size() - data) continue;  // VTK reports the bad offset itself
      start = data + offset;
    } else if (format == "binary") {
      start = xml.find('>', tag);
      if (start == std::string_view::npos) continue;
      ++start;
    } else {
      const std::size_t values = xml.find('>', tag);
      if (offsets && values != std::string_view::npos) {
        lastOffset = largestAsciiValue(xml, values + 1);
      }
      start = std::string_view::npos;
    }
    if (start != std::string_view::npos) {
      const ArrayBytes array{text.substr(start), inAppended && rawAppended};
      const std::uint64_t left = text.size() - start;
      if (compressed && array.raw) {
        checkBlockHeader(path, text.substr(start, maxHeader), left, layout);
      } else if (compressed) {
        checkBlockHeader(path, base64Prefix(text.substr(start), maxHeader), left / 4 * 3, layout);
      }
      if (offsets && valueSize > 0) {
        lastOffset = largestValue(array, valueSize, compressed,
                                  compressor == "vtkZLibDataCompressor", layout);
      }
    }
    if (lastOffset && *lastOffset > limit) {
      damaged(path, "a cell offset " + std::to_string(*lastOffset) + " is more than its " +
                        std::to_string(bytes.size()) + " bytes can hold");
    }
  }
}

}  // namespace tetblend::detail
