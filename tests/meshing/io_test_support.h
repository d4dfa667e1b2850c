#pragma once
// Helpers for the mesh I/O tests: a self-cleaning temporary directory, raw
// file access, seeded random meshes and a byte builder for binary formats
// (written here, independently of the writers under test).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>

#include "tetblend/core/mesh_types.h"
#include "test_seed.h"

namespace tetblend::io_test {

namespace fs = std::filesystem;

/// Seed of the random tests: TETBLEND_SEED if set, else a fixed default;
/// printed so a failure can be replayed.
inline std::uint32_t testSeed(const std::string& testName) {
  return test_seed::seedFor(testName.c_str(), 20240611u);
}

/// A fresh directory under the system temp directory, removed on destruction.
class TempDir {
 public:
  TempDir() {
    std::random_device device;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string("tetblend_io_") + (info ? info->name() : "test") + "_" +
                             std::to_string(device()) + std::to_string(device());
    path_ = fs::temp_directory_path() / name;
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }
  /// Number of entries in the directory (to detect stray temporary files).
  int entryCount() const {
    return static_cast<int>(std::distance(fs::directory_iterator(path_), fs::directory_iterator()));
  }

 private:
  fs::path path_;
};

inline void writeText(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Appends scalars in a chosen byte order.
class ByteBuilder {
 public:
  explicit ByteBuilder(bool littleEndian) : little_(littleEndian) {}
  template <typename T>
  ByteBuilder& put(T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    const bool hostLittle = first == 1;
    if (hostLittle != little_) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
    bytes_.append(reinterpret_cast<const char*>(bytes), sizeof(T));
    return *this;
  }
  ByteBuilder& text(const std::string& s) {
    bytes_ += s;
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  bool little_;
  std::string bytes_;
};

/// Coordinates that stress exact round trips: signed zero, subnormal, huge
/// and tiny magnitudes, values with 17 significant digits.
inline Vertices hardVertices() {
  Vertices v(6, 3);
  v << -0.0, 0.0, 1.0 / 3.0,                             //
      5e-324, -2.2250738585072014e-308, 1e308,           //
      0.1, 0.2, 0.30000000000000004,                     //
      -123456789.12345679, 6.02214076e23, 1e-300,        //
      1.7976931348623157e308, -1.0, 9007199254740993.0,  //
      2.0 / 3.0, -7.0 / 11.0, 3.141592653589793;
  return v;
}

/// #V random positions of mixed magnitudes (10^-6..10^6) and #F random
/// triangles with distinct corners.
inline SurfaceMesh randomSurface(std::mt19937& rng, int vertexCount, int faceCount) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  std::uniform_int_distribution<int> vertex(0, vertexCount - 1);
  SurfaceMesh m;
  m.vertices.resize(vertexCount, 3);
  for (int i = 0; i < vertexCount; ++i) {
    for (int c = 0; c < 3; ++c) m.vertices(i, c) = unit(rng) * std::pow(10.0, exponent(rng));
  }
  m.triangles.resize(faceCount, 3);
  for (int f = 0; f < faceCount; ++f) {
    int a = vertex(rng), b = vertex(rng), c = vertex(rng);
    while (b == a) b = vertex(rng);
    while (c == a || c == b) c = vertex(rng);
    m.triangles.row(f) << a, b, c;
  }
  return m;
}

/// True when the positions are bitwise equal (so -0 and +0 differ).
inline bool sameBits(const Vertices& a, const Vertices& b) {
  if (a.rows() != b.rows()) return false;
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

}  // namespace tetblend::io_test
