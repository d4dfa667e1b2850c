// libFuzzer's entry point for one reader; TETBLEND_FUZZ_EXTENSION (".ply",
// ...) is set per target in fuzz/CMakeLists.txt. In a test build the same
// entry point is driven by replay_main.cpp instead of libFuzzer.

#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tetblend::fuzz::readFuzzInput(data, size, TETBLEND_FUZZ_EXTENSION);
}
