# ASan + UBSan flags, applied per target by tetblend_project_options().
# UBSan's pointer checks are left to ASan, which reports a null or misaligned
# access that faults (SEGV) and every access outside its object; checked by
# UBSan as well they made the CGAL-heavy files build 1.4 times as long
# (hole_refill.cpp: 86 -> 63 s, g++ 12 at -O1, one core).
set(TETBLEND_SANITIZER_FLAGS
    -fsanitize=address,undefined -fno-sanitize=alignment,null,object-size
    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
if(TETBLEND_SANITIZE)
  # Propagate to link steps of every target (static libraries get linked into
  # executables that must carry the runtime).
  add_link_options(-fsanitize=address,undefined)
endif()

# libFuzzer builds (TETBLEND_BUILD_FUZZERS, fuzz/): the project's code gets
# coverage instrumentation plus ASan and UBSan; the fuzz targets themselves
# link libFuzzer's main with -fsanitize=fuzzer. Only clang has libFuzzer
# (Debian 12: packages clang and libclang-rt-14-dev).
set(TETBLEND_FUZZ_INSTRUMENT_FLAGS
    -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
set(TETBLEND_FUZZ_LINK_FLAGS -fsanitize=fuzzer,address,undefined)
if(TETBLEND_BUILD_FUZZERS AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR
    "TETBLEND_BUILD_FUZZERS needs clang with libFuzzer (found ${CMAKE_CXX_COMPILER_ID}): "
    "install clang and libclang-rt-14-dev, and configure a fresh build directory with "
    "CC=clang CXX=clang++")
endif()
if(TETBLEND_BUILD_FUZZERS AND TETBLEND_SANITIZE)
  message(FATAL_ERROR "TETBLEND_BUILD_FUZZERS already adds ASan and UBSan: "
    "leave TETBLEND_SANITIZE off in the fuzz build")
endif()
if(TETBLEND_BUILD_FUZZERS)
  add_link_options(-fsanitize=address,undefined)
endif()
