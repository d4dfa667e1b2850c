#pragma once
// The one harness behind every reader fuzz target (fuzz_target.cpp): the
// readers take a path, so the input is written to a file with the reader's
// extension in a private temporary directory and read back through the
// public entry point. Allowed outcomes: a normal return whose result is
// consistent (finite positions, indices in range), or a tetblend::Error
// whose message is one line naming the file. Anything else prints what
// happened to stderr and aborts, which libFuzzer (or the replay main)
// reports as a finding.

#include <cstddef>
#include <cstdint>
#include <string>

namespace tetblend::fuzz {

/// Separates the .node part from the .ele part of a TetGen input (".node"):
/// the bytes before its first occurrence go to the .node file, the bytes
/// after it to the .ele file (empty when absent).
inline constexpr char kTetGenSeparator[] = "\n@ele\n";

/// Reads `size` bytes of `data` as a file with `extension`:
///   .obj .off .ply .stl .vtp   readSurface
///   .vtu .node .mesh           readTetMesh (.node: split at kTetGenSeparator)
///   .tbm                       cli::readModelFile, after the payload size and
///                              checksum fields of an input that starts with
///                              the model magic are set to match its bytes
///                              (else every mutation fails the checksum test)
///   .json                      cli::readBatchSpec
/// Returns 0; aborts on any outcome listed above as not allowed.
int readFuzzInput(const std::uint8_t* data, std::size_t size, const std::string& extension);

}  // namespace tetblend::fuzz
