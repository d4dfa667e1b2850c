#pragma once
// Internal: checks, before VTK's XML readers see a file, that the sizes its
// header declares fit in the file. VTK allocates from them first: a
// NumberOfPoints of 2e9 in a 2 KB file, or a compressed block header claiming
// 2^32 blocks or a 4 GB block, asked for gigabytes before anything was read.

#include <string>

namespace tetblend::detail {

/// Throws InputError naming `path` when `bytes` (the whole file) declares a
/// piece count (NumberOfPoints, NumberOfCells, NumberOfPolys, ...) larger
/// than its bytes can hold, or a compressed data array whose block header
/// (raw appended or base64, UInt32 or UInt64 words, either byte order) has
/// more blocks than bytes follow, or a block whose uncompressed size exceeds
/// what its compressed size can inflate to.
void checkVtkXmlBounds(const std::string& path, const std::string& bytes);

}  // namespace tetblend::detail
