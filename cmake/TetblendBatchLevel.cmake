# tetblend_batch_march(<out-var> <flags>): the -march option for
# core/src/batch_kernels.cpp in a build whose flags (CMAKE_CXX_FLAGS plus
# <flags>) already target AVX2. It names the x86-64 level those flags cover
# (x86-64-v4, else x86-64-v3), so the kernels are the code the default build's
# clone of that level runs, with its generic tuning: with -march=native on a
# Zen 3/4 host (znver3 tuning) sym_exp and sym_log measured 3-4 % slower than
# the default build, and at parity once compiled for x86-64-v4 (README,
# Benchmarks). Empty when the flags do not cover a level, or for compilers
# other than GCC (whose function multi-versioning the default build uses).
include(CheckCXXSourceCompiles)

# check_cxx_source_compiles(<result>) of a file that compiles only when every
# macro of <macros> is defined.
function(tetblend_defines_all result macros)
  set(source "")
  foreach(macro IN LISTS macros)
    string(APPEND source "#ifndef ${macro}\n#error ${macro} undefined\n#endif\n")
  endforeach()
  check_cxx_source_compiles("${source}int main() { return 0; }" ${result})
endfunction()

function(tetblend_batch_march out_var flags)
  set(${out_var} "" PARENT_SCOPE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR NOT CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    return()
  endif()
  string(MAKE_C_IDENTIFIER "${flags}" key)
  set(CMAKE_REQUIRED_FLAGS "${flags}")
  set(CMAKE_REQUIRED_QUIET ON)
  tetblend_defines_all(TETBLEND_FLAGS_COVER_V3_${key}
    "__AVX2__;__FMA__;__BMI__;__BMI2__;__F16C__;__LZCNT__;__MOVBE__")
  tetblend_defines_all(TETBLEND_FLAGS_COVER_V4_${key}
    "__AVX512F__;__AVX512BW__;__AVX512CD__;__AVX512DQ__;__AVX512VL__")
  if(TETBLEND_FLAGS_COVER_V3_${key} AND TETBLEND_FLAGS_COVER_V4_${key})
    set(${out_var} "-march=x86-64-v4" PARENT_SCOPE)
  elseif(TETBLEND_FLAGS_COVER_V3_${key})
    set(${out_var} "-march=x86-64-v3" PARENT_SCOPE)
  endif()
endfunction()
