#!/usr/bin/env bash
# tetblend's one entry point for developers and CI.
#   ./dev.sh setup   install the Debian packages the project needs (idempotent)
#   ./dev.sh build   set up, then configure and build (Release) into build/release
#   ./dev.sh demo    set up, build, and run the main job on the bundled samples
#   ./dev.sh test    set up, build, and run the whole test suite with ctest
#   ./dev.sh asan    set up, build with ASan+UBSan into build/asan, run the suite
#                    (without the Python module: Debian's python3 cannot load
#                    an ASan-instrumented extension); what CI runs
#   ./dev.sh asan-ci the same for the tests labelled "input" only (readers,
#                    writers, model file, pipeline, command line): a quicker
#                    check of the code that handles untrusted input
#   ./dev.sh bench   set up, build, and run the benchmarks (figures for README)
#   ./dev.sh fuzz [seconds]  set up, build the reader fuzzers (clang, libFuzzer,
#                    ASan+UBSan) into build/fuzz, replay their seeds and
#                    regressions, fuzz each reader for seconds (default 30)
# TETBLEND_JOBS limits build and test parallelism (default: all cores).
set -euo pipefail
cd "$(dirname "$0")"
jobs=${TETBLEND_JOBS:-$(nproc)}

build() { # build <dir> <cmake args...>
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja "$@"
  cmake --build "$dir" --parallel "$jobs"
}

asan_configure() {
  # -g1: line tables only, enough for the sanitizers' stack traces (file and
  # line of every frame); full debug info made the build about 20 % longer.
  # -O1, the level the ASan documentation suggests: kaji_ochiai_test.cpp,
  # when it still instantiated Eigen's MatrixFunctions itself, built in 162 s
  # instead of 215 s at -O2.
  cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTETBLEND_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DTETBLEND_BUILD_BENCHMARKS=OFF -DTETBLEND_BUILD_PYTHON=OFF
}

asan_ctest() { # asan_ctest <ctest args...>
  # A huge allocation fails as in a normal build (the readers' tests make
  # VTK try one); fuzz/lsan.supp names VTK 9.1's own leaks on damaged files.
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
    LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp" \
    ctest --test-dir build/asan --output-on-failure --parallel "$jobs" "$@"
}

case "${1:-}" in
  setup) bash setup.sh ;;
  build) bash setup.sh && build build/release -DCMAKE_BUILD_TYPE=Release ;;
  demo)
    bash setup.sh && build build/release -DCMAKE_BUILD_TYPE=Release
    bash samples/run_samples.sh build/release out/samples ;;
  test)
    bash setup.sh && build build/release -DCMAKE_BUILD_TYPE=Release
    ctest --test-dir build/release --output-on-failure --parallel "$jobs" ;;
  asan)
    bash setup.sh
    asan_configure
    cmake --build build/asan --parallel "$jobs"
    asan_ctest ;;
  asan-ci)
    bash setup.sh
    asan_configure
    cmake --build build/asan --parallel "$jobs" --target input_tests
    asan_ctest -L input ;;
  bench)
    bash setup.sh && build build/release -DCMAKE_BUILD_TYPE=Release
    for b in build/release/apps/bench/bench_*; do "$b"; done ;;
  fuzz)
    bash setup.sh
    CC=clang CXX=clang++ cmake -S . -B build/fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DTETBLEND_BUILD_FUZZERS=ON -DTETBLEND_BUILD_TESTS=OFF -DTETBLEND_BUILD_BENCHMARKS=OFF \
      -DTETBLEND_BUILD_PYTHON=OFF
    cmake --build build/fuzz --parallel "$jobs" --target fuzz_all
    TETBLEND_FUZZ_SECONDS="${2:-30}" \
      ctest --test-dir build/fuzz --output-on-failure --parallel "$jobs" -L fuzz ;;
  *) sed -n '2,16p' "$0"; exit 2 ;;
esac
