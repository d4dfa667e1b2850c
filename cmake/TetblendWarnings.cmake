# tetblend_project_options(<target>): warnings as errors on the project's own
# code only (third-party headers come in as SYSTEM), plus the sanitizers when
# TETBLEND_SANITIZE is on and libFuzzer's instrumentation with them when
# TETBLEND_BUILD_FUZZERS is on. GCC's -W(maybe-)uninitialized stay warnings: with
# -march=native on AVX-512 machines it fires inside Eigen's inlined
# intrinsics (avx512dqintrin.h, a false positive) and would stop the build.
function(tetblend_project_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized -Wno-error=uninitialized)
  endif()
  if(TETBLEND_SANITIZE)
    target_compile_options(${target} PRIVATE ${TETBLEND_SANITIZER_FLAGS})
    target_link_options(${target} PRIVATE ${TETBLEND_SANITIZER_FLAGS})
  endif()
  if(TETBLEND_BUILD_FUZZERS)
    target_compile_options(${target} PRIVATE ${TETBLEND_FUZZ_INSTRUMENT_FLAGS})
  endif()
endfunction()
