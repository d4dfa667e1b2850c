#pragma once
// How the .vtu and .vtp writers compress their binary appended data. VTK's
// readers (and ParaView) read all three.

#include <string>

namespace tetblend {

/// The compressor of written VTK XML files.
enum class VtkCompressor { zlib, lz4, none };

/// Compressor and level of written VTK XML files.
struct VtkCompression {
  VtkCompressor compressor = VtkCompressor::zlib;
  /// VTK's scale 1 (fastest) .. 9 (smallest): zlib's level; for lz4, VTK
  /// maps it to LZ4's acceleration (lower level, faster). Ignored by none.
  int level = 5;
};

/// "zlib", "lz4" or "none".
std::string vtkCompressorName(VtkCompressor compressor);

/// Lowest and highest VtkCompression::level.
constexpr int kMinCompressionLevel = 1;
constexpr int kMaxCompressionLevel = 9;

/// The compressor named `compressor` ("zlib", "lz4", "none") at `level`;
/// InputError naming `what` for another name or a level outside 1..9.
VtkCompression parseVtkCompression(const std::string& compressor, int level,
                                   const std::string& what);

}  // namespace tetblend
