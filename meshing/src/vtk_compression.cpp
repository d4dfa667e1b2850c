#include "tetblend/meshing/vtk_compression.h"

#include "tetblend/core/error.h"

namespace tetblend {

std::string vtkCompressorName(VtkCompressor compressor) {
  switch (compressor) {
    case VtkCompressor::zlib:
      return "zlib";
    case VtkCompressor::lz4:
      return "lz4";
    case VtkCompressor::none:
      return "none";
  }
  return "zlib";
}

VtkCompression parseVtkCompression(const std::string& compressor, int level,
                                   const std::string& what) {
  if (level < kMinCompressionLevel || level > kMaxCompressionLevel) {
    throw InputError(what + ": level " + std::to_string(level) + " is outside " +
                     std::to_string(kMinCompressionLevel) + ".." +
                     std::to_string(kMaxCompressionLevel));
  }
  for (VtkCompressor c : {VtkCompressor::zlib, VtkCompressor::lz4, VtkCompressor::none})
    if (vtkCompressorName(c) == compressor) return {c, level};
  throw InputError(what + ": unknown compressor '" + compressor + "'; use lz4, zlib or none");
}

}  // namespace tetblend
