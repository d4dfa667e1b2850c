#pragma once
// The default compression of blended shapes' .vtu/.vtp files (blend, batch,
// variations, animate; the meshing library's writers default to zlib).

#include "tetblend/meshing/vtk_compression.h"

namespace tetblend::cli {

/// lz4 at VTK's level 5: a batch of .vtu + .vtp jobs ran 3.3 times as fast as
/// with zlib for files 23 % larger (README, Benchmarks: batch throughput).
inline constexpr VtkCompression kBlendOutputCompression{VtkCompressor::lz4, 5};

}  // namespace tetblend::cli
