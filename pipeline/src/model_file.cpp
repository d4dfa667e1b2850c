#include "tetblend/pipeline/model_file.h"

#include <cstring>
#include <fstream>

#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"

namespace tetblend {

namespace {

constexpr char kMagic[8] = {'T', 'B', 'M', 'O', 'D', 'E', 'L', '\0'};
constexpr std::size_t kHeaderSize = 8 + 4 + 8;
constexpr std::size_t kTrailerSize = 8;
// Sanity cap on counts read from a file, far above any mesh this tool handles,
// so that a corrupt count fails cleanly instead of allocating wildly.
constexpr std::uint64_t kMaxCount = 1ULL << 31;
// Arrays are copied as they are in memory where that is the file's byte order.
constexpr bool kLittleEndianHost = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

class ByteWriter {
 public:
  void u32(std::uint32_t v) { little(v, 4); }
  void u64(std::uint64_t v) { little(v, 8); }
  void i32(std::int32_t v) { little(static_cast<std::uint32_t>(v), 4); }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    little(bits, 8);
  }
  void text(const std::string& s) {
    u64(s.size());
    raw(reinterpret_cast<const unsigned char*>(s.data()), s.size());
  }
  void raw(const unsigned char* data, std::size_t size) {
    bytes_.insert(bytes_.end(), data, data + size);
  }
  // A count, then the values (i32, i64 or f64), little-endian.
  template <typename T>
  void array(const std::vector<T>& values) {
    static_assert(sizeof(T) == 4 || sizeof(T) == 8, "i32, i64 or f64 values");
    u64(values.size());
    if constexpr (kLittleEndianHost) {
      // An empty vector's data() may be null, which memcpy must not get.
      if (!values.empty()) {
        raw(reinterpret_cast<const unsigned char*>(values.data()), sizeof(T) * values.size());
      }
    } else {
      for (const T& v : values) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof(T));
        little(bits, sizeof(T));
      }
    }
  }
  std::vector<unsigned char>& bytes() { return bytes_; }

 private:
  void little(std::uint64_t v, int count) {
    for (int i = 0; i < count; ++i) bytes_.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
  std::vector<unsigned char> bytes_;
};

class ByteReader {
 public:
  ByteReader(const unsigned char* data, std::size_t size, std::string path)
      : data_(data), size_(size), path_(std::move(path)) {}
  std::uint64_t u64() { return little(8); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(little(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(little(4))); }
  double f64() {
    const std::uint64_t bits = little(8);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::uint64_t count(const char* what) {
    const std::uint64_t n = u64();
    if (n > kMaxCount) {
      throw InputError(path_ + ": damaged model file (" + what + " = " + std::to_string(n) +
                       "); re-run 'tetblend prepare'");
    }
    return n;
  }
  // A u64 that must be 0 or 1.
  bool flag(const char* what) {
    const std::uint64_t v = u64();
    if (v > 1) {
      throw InputError(path_ + ": damaged model file (" + what + " = " + std::to_string(v) +
                       "); re-run 'tetblend prepare'");
    }
    return v == 1;
  }
  std::string text() {
    const std::uint64_t n = count("string length");
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += n;
    return s;
  }
  bool atEnd() const { return pos_ == size_; }
  // ByteWriter::array's values: the count checked against the bytes left.
  template <typename T>
  std::vector<T> array(const char* what) {
    const std::uint64_t n = count(what);
    requireRoom(n, sizeof(T), what);
    std::vector<T> values(n);
    if constexpr (kLittleEndianHost) {
      if (n > 0) std::memcpy(values.data(), data_ + pos_, sizeof(T) * n);  // data() may be null
      pos_ += sizeof(T) * n;
    } else {
      for (T& v : values) {
        const std::uint64_t bits = little(sizeof(T));
        std::memcpy(&v, &bits, sizeof(T));
      }
    }
    return values;
  }
  // Refuses `n` items of `bytesEach` bytes before anything is allocated for
  // them, when the rest of the payload cannot hold them.
  void requireRoom(std::uint64_t n, std::uint64_t bytesEach, const char* what) const {
    if (bytesEach > 0 && n > (size_ - pos_) / bytesEach) {
      throw InputError(path_ + ": damaged model file (" + what + " " + std::to_string(n) +
                       " needs more than the " + std::to_string(size_ - pos_) +
                       " bytes left); re-run 'tetblend prepare'");
    }
  }

 private:
  void need(std::uint64_t n) const {
    if (n > size_ - pos_) {
      throw InputError(path_ +
                       ": damaged model file (payload ends early); re-run 'tetblend prepare'");
    }
  }
  std::uint64_t little(int n) {
    need(static_cast<std::uint64_t>(n));
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(data_[pos_ + i]) << (8 * i);
    pos_ += static_cast<std::size_t>(n);
    return v;
  }
  const unsigned char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string path_;
};

void writeVertices(ByteWriter& w, const Vertices& v) {
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    for (int c = 0; c < 3; ++c) w.f64(v(i, c));
}

Vertices readVertices(ByteReader& r, std::uint64_t rows) {
  Vertices v(static_cast<Eigen::Index>(rows), 3);
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    for (int c = 0; c < 3; ++c) v(i, c) = r.f64();
  return v;
}

std::vector<unsigned char> encodePayload(const ModelData& m) {
  ByteWriter w;
  w.u64(static_cast<std::uint64_t>(m.rest.vertices.rows()));
  w.u64(static_cast<std::uint64_t>(m.rest.tets.rows()));
  w.u64(static_cast<std::uint64_t>(m.surfaceTriangles.rows()));
  w.u64(static_cast<std::uint64_t>(m.surfaceVertexCount));
  w.u64(m.examples.size());
  writeVertices(w, m.rest.vertices);
  for (Eigen::Index i = 0; i < m.rest.tets.rows(); ++i)
    for (int c = 0; c < 4; ++c) w.i32(m.rest.tets(i, c));
  for (Eigen::Index i = 0; i < m.surfaceTriangles.rows(); ++i)
    for (int c = 0; c < 3; ++c) w.i32(m.surfaceTriangles(i, c));
  for (const Vertices& e : m.examples) writeVertices(w, e);
  w.text(m.restSource);
  for (const std::string& s : m.exampleSources) w.text(s);
  w.array(m.excludedTets);
  w.array(m.inputVertexRows);
  w.u64(m.blendCache ? 1 : 0);
  if (m.blendCache) {
    const StitchFactorData& f = m.blendCache->factor;
    w.array(f.perm);
    w.array(f.super);
    w.array(f.rowStart);
    w.array(f.rows);
    w.array(f.valueStart);
    w.array(f.values);
    const KajiParameterData& k = m.blendCache->kaji;
    w.u64(static_cast<std::uint64_t>(k.tets));
    w.u64(static_cast<std::uint64_t>(k.examples));
    w.u64(k.rotationConsistency ? 1 : 0);
    w.array(k.params);
    w.array(k.correctedTets);
    w.array(k.correctionStart);
    w.array(k.correctionExample);
    w.array(k.corrections);
  }
  return std::move(w.bytes());
}

ModelData decodePayload(const unsigned char* data, std::size_t size, const std::string& path,
                        std::uint32_t version) {
  ByteReader r(data, size, path);
  const std::uint64_t nv = r.count("vertex count");
  const std::uint64_t nt = r.count("tet count");
  const std::uint64_t nf = r.count("triangle count");
  const std::uint64_t ns = r.count("surface vertex count");
  const std::uint64_t ne = r.count("example count");
  ModelData m;
  m.formatVersion = version;
  m.surfaceVertexCount = static_cast<int>(ns);
  constexpr std::uint64_t kVertexBytes = 3 * 8, kTetBytes = 4 * 4, kTriangleBytes = 3 * 4;
  r.requireRoom(nv, kVertexBytes, "vertex count");
  m.rest.vertices = readVertices(r, nv);
  r.requireRoom(nt, kTetBytes, "tet count");
  m.rest.tets.resize(static_cast<Eigen::Index>(nt), 4);
  for (Eigen::Index i = 0; i < m.rest.tets.rows(); ++i)
    for (int c = 0; c < 4; ++c) m.rest.tets(i, c) = r.i32();
  r.requireRoom(nf, kTriangleBytes, "triangle count");
  m.surfaceTriangles.resize(static_cast<Eigen::Index>(nf), 3);
  for (Eigen::Index i = 0; i < m.surfaceTriangles.rows(); ++i)
    for (int c = 0; c < 3; ++c) m.surfaceTriangles(i, c) = r.i32();
  // Each example holds its vertices and, after them, its source name's length.
  r.requireRoom(ne, nv * kVertexBytes + 8, "example count");
  for (std::uint64_t k = 0; k < ne; ++k) m.examples.push_back(readVertices(r, nv));
  m.restSource = r.text();
  for (std::uint64_t k = 0; k < ne; ++k) m.exampleSources.push_back(r.text());
  if (version >= 2) {
    m.excludedTets = r.array<int>("excluded tet count");
    if (m.excludedTets.size() > nt) {
      throw InputError(path + ": damaged model file (" + std::to_string(m.excludedTets.size()) +
                       " excluded tets of " + std::to_string(nt) + "); re-run 'tetblend prepare'");
    }
  }
  if (version >= 3) m.inputVertexRows = r.array<int>("input vertex count");
  if (version >= 4 && r.flag("blend cache flag")) {
    BlendCache cache;
    StitchFactorData& f = cache.factor;
    f.perm = r.array<int>("factor permutation size");
    f.super = r.array<int>("factor supernode count");
    f.rowStart = r.array<int>("factor row start count");
    f.rows = r.array<int>("factor row count");
    f.valueStart = r.array<std::int64_t>("factor value start count");
    f.values = r.array<double>("factor value count");
    KajiParameterData& k = cache.kaji;
    k.tets = static_cast<int>(r.count("kaji tet count"));
    k.examples = static_cast<int>(r.count("kaji example count"));
    k.rotationConsistency = r.flag("kaji rotation consistency");
    k.params = r.array<double>("kaji parameter count");
    k.correctedTets = r.array<int>("kaji corrected tet count");
    k.correctionStart = r.array<int>("kaji correction start count");
    k.correctionExample = r.array<int>("kaji correction count");
    k.corrections = r.array<double>("kaji correction value count");
    m.blendCache = std::move(cache);
  }
  if (!r.atEnd()) {
    throw InputError(path +
                     ": damaged model file (bytes after the payload); re-run 'tetblend prepare'");
  }
  return m;
}

std::uint64_t readLittle(const std::vector<unsigned char>& b, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(b[at + i]) << (8 * i);
  return v;
}

}  // namespace

Eigen::Index ModelData::inputVertexCount() const {
  return inputVertexRows.empty() ? surfaceVertexCount
                                 : static_cast<Eigen::Index>(inputVertexRows.size());
}

Vertices ModelData::inputVertices(const Vertices& positions) const {
  if (inputVertexRows.empty()) return positions.topRows(surfaceVertexCount);
  Vertices result(static_cast<Eigen::Index>(inputVertexRows.size()), 3);
  for (std::size_t i = 0; i < inputVertexRows.size(); ++i) {
    result.row(static_cast<Eigen::Index>(i)) = positions.row(inputVertexRows[i]);
  }
  return result;
}

std::uint64_t fnv1a64(const unsigned char* data, std::size_t size, std::uint64_t hash) {
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= kPrime;
  }
  return hash;
}

std::uint64_t fnv1a64Words(const unsigned char* data, std::size_t size) {
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  const std::size_t words = size / 8;
  for (std::size_t i = 0; i < words; ++i) {
    std::uint64_t word = 0;
    for (int b = 0; b < 8; ++b) word |= static_cast<std::uint64_t>(data[8 * i + b]) << (8 * b);
    hash ^= word;
    hash *= kPrime;
  }
  return fnv1a64(data + 8 * words, size - 8 * words, hash);
}

std::uint64_t modelChecksum(const unsigned char* payload, std::size_t size, std::uint32_t version) {
  return version >= 4 ? fnv1a64Words(payload, size) : fnv1a64(payload, size);
}

void checkModel(const ModelData& m, const std::string& what) {
  const Eigen::Index nv = m.rest.vertices.rows();
  if (m.surfaceVertexCount < 0 || m.surfaceVertexCount > nv) {
    throw InputError(what + ": surface vertex count " + std::to_string(m.surfaceVertexCount) +
                     " is outside 0.." + std::to_string(nv));
  }
  for (Eigen::Index i = 0; i < m.rest.tets.rows(); ++i)
    for (int c = 0; c < 4; ++c)
      if (m.rest.tets(i, c) < 0 || m.rest.tets(i, c) >= nv)
        throw InputError(what + ": tet " + std::to_string(i) + " refers to vertex " +
                         std::to_string(m.rest.tets(i, c)) + " of " + std::to_string(nv));
  for (std::size_t i = 0; i < m.inputVertexRows.size(); ++i) {
    const int row = m.inputVertexRows[i];
    if (row < 0 || row >= nv) {
      throw InputError(what + ": input vertex " + std::to_string(i) + " is on row " +
                       std::to_string(row) + " of " + std::to_string(nv) +
                       "; re-run 'tetblend prepare'");
    }
  }
  const Eigen::Index inputVertices = m.inputVertexCount();
  for (Eigen::Index i = 0; i < m.surfaceTriangles.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (m.surfaceTriangles(i, c) < 0 || m.surfaceTriangles(i, c) >= inputVertices)
        throw InputError(what + ": surface triangle " + std::to_string(i) + " refers to vertex " +
                         std::to_string(m.surfaceTriangles(i, c)) + ", not a surface vertex");
  if (m.exampleSources.size() != m.examples.size()) {
    throw InputError(what + ": " + std::to_string(m.examples.size()) + " examples but " +
                     std::to_string(m.exampleSources.size()) + " source names");
  }
  for (std::size_t i = 0; i < m.excludedTets.size(); ++i) {
    const int t = m.excludedTets[i];
    if (t < 0 || t >= m.rest.tets.rows() || (i > 0 && t <= m.excludedTets[i - 1])) {
      throw InputError(what + ": excluded tet " + std::to_string(t) +
                       " is out of range or out of order; re-run 'tetblend prepare'");
    }
  }
  for (std::size_t k = 0; k < m.examples.size(); ++k)
    if (m.examples[k].rows() != nv)
      throw InputError(what + ": example " + std::to_string(k + 1) + " has " +
                       std::to_string(m.examples[k].rows()) + " vertices, the rest mesh " +
                       std::to_string(nv));
}

void writeModelFile(const std::string& path, const ModelData& model) {
  checkModel(model, path);
  const std::vector<unsigned char> payload = encodePayload(model);
  ByteWriter file;
  file.raw(reinterpret_cast<const unsigned char*>(kMagic), sizeof kMagic);
  file.u32(kModelFormatVersion);
  file.u64(payload.size());
  file.raw(payload.data(), payload.size());
  file.u64(modelChecksum(payload.data(), payload.size(), kModelFormatVersion));
  writeFileAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(file.bytes().data()),
              static_cast<std::streamsize>(file.bytes().size()));
    if (!out.flush()) throw InputError(path + ": cannot write the model file");
  });
}

ModelData readModelFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path + ": cannot open the model file");
  const std::streamoff fileSize = in.tellg();
  in.seekg(0);
  std::vector<unsigned char> bytes(fileSize > 0 ? static_cast<std::size_t>(fileSize) : 0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()))) {
    throw InputError(path + ": cannot read the model file");
  }
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 8) != 0) {
    throw InputError(path + ": not a tetblend model file (make one with 'tetblend prepare')");
  }
  if (bytes.size() < kHeaderSize + kTrailerSize) {
    throw InputError(path + ": damaged model file (truncated header); re-run 'tetblend prepare'");
  }
  const auto version = static_cast<std::uint32_t>(readLittle(bytes, 8, 4));
  if (version < 1 || version > kModelFormatVersion) {
    throw InputError(path + ": model file format version " + std::to_string(version) +
                     ", this tetblend reads versions 1 to " + std::to_string(kModelFormatVersion) +
                     "; re-run 'tetblend prepare' with this version");
  }
  const std::uint64_t payloadSize = readLittle(bytes, 12, 8);
  if (payloadSize != bytes.size() - kHeaderSize - kTrailerSize) {
    throw InputError(path + ": damaged model file (size " + std::to_string(bytes.size()) +
                     " bytes does not match its header); re-run 'tetblend prepare'");
  }
  const unsigned char* payload = bytes.data() + kHeaderSize;
  const std::uint64_t stored = readLittle(bytes, kHeaderSize + payloadSize, 8);
  if (modelChecksum(payload, payloadSize, version) != stored) {
    throw InputError(path + ": damaged model file (checksum mismatch); re-run 'tetblend prepare'");
  }
  ModelData model = decodePayload(payload, payloadSize, path, version);
  checkModel(model, path);
  return model;
}

}  // namespace tetblend
