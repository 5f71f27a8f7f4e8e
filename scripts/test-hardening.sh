#!/usr/bin/env bash
# Hardening checks, after the normal test run (scripts/test.sh): the whole project built with
# AddressSanitizer and UBSan in build-hardening/ and the whole ctest suite run on it, then each
# libFuzzer target (tests/fuzz) for a bounded time. Fails on any test failure, sanitizer report
# or fuzzer crash; a fuzzer's crashing input is kept in build-hardening/fuzz-artifacts/.
#   FUZZ_SECONDS=60   time per fuzz target
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-hardening
fuzz_seconds=${FUZZ_SECONDS:-60}

# -O1: the instrumented tests stay fast enough on two cores; -g1: line numbers in reports.
# No -DNDEBUG, so assertions stay on. The same tree builds the fuzzers (libFuzzer needs clang),
# not the benchmarks, which no test runs.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  -DGEODESIC_SANITIZE=ON -DGEODESIC_FUZZ=ON -DGEODESIC_BENCH=OFF >/dev/null
cmake --build "$build" -j "$(nproc)"

# Leak checking is on, with no suppressions: Mesa, the Vulkan loader and LLVM leak nothing that
# LeakSanitizer reports. Child processes (the jobs and web tests' `geodesic serve`) inherit
# these.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Excluded: deploy (linters and the install script on a copy of the tree; no instrumented code
# runs, and the normal run has them).
ctest --test-dir "$build" --output-on-failure -j 2 -LE deploy

# Each fuzzer starts from its seeds (read in place) and writes what it finds to a scratch
# corpus, the first directory given. -timeout: a hang is a failure too, but generator text
# costs a bounded yet long time (up to 200000 group elements per Dirichlet base point and
# growth step; up to 36 s under ASan on a loaded machine), so only two minutes count as one.
fuzz() {
  local target=$1
  shift
  local corpus=$build/fuzz-corpus/$target
  mkdir -p "$corpus" "$build/fuzz-artifacts"
  echo "test-hardening: $target for ${fuzz_seconds} s"
  "$build/tests/fuzz/$target" -max_total_time="$fuzz_seconds" -timeout=120 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$target-" "$corpus" "$@"
}
fuzz fuzz_scene -dict=tests/fuzz/scene.dict scenes scenes/catalogue
fuzz fuzz_messages -dict=tests/fuzz/scene.dict tests/fuzz/corpus/messages
echo "test-hardening: passed"
