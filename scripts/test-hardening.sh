#!/usr/bin/env bash
# Hardening checks, after the normal test run (scripts/test.sh): the whole project built with
# AddressSanitizer and UBSan in build-hardening/ and the ctest suite run on it (all but the
# deploy checks and four render tests that are lavapipe's time, listed below), then the
# libFuzzer targets (tests/fuzz) for a bounded time. Fails on any test failure, sanitizer report
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
# runs), and the three closed-form light tests and the fine-mesh tube test: 160 s of lavapipe
# sampling (uninstrumented) behind a host path, a small scene's Renderer, that the render tests
# kept here take too (EdgeTubes.ACameraOnAFace*, the other DirectLight and Mis tests). The
# normal run has them all.
# The load test walks its 50 sessions for 40 s, not two minutes: two walk-and-stand cycles and
# twenty jobs take every path of the daemon's under instrumentation; the normal run holds the two
# minutes and the time bounds, which it skips here (tests/load/sanitizer.h).
sampling_only='^(DirectLight\.(Sphere|Quad|Horosphere)LightsMatchTheirClosedForms|EdgeTubes\.RenderAsTheirFineMeshDoes)$'
GEODESIC_LOAD_SECONDS=40 ctest --test-dir "$build" --output-on-failure -j 2 -LE deploy \
  -E "$sampling_only"

# Each fuzzer starts from its seeds (read in place) and writes what it finds to a scratch
# corpus, the first directory given. -timeout: a hang is a failure too, but generator text
# costs a bounded yet long time (up to 200000 group elements per Dirichlet base point and
# growth step; up to 36 s under ASan on a loaded machine), so only two minutes count as one.
# A fuzzer runs on one core: the two run side by side, each into its own log, printed after.
fuzz() {
  local target=$1
  shift
  local corpus=$build/fuzz-corpus/$target
  mkdir -p "$corpus" "$build/fuzz-artifacts"
  "$build/tests/fuzz/$target" -max_total_time="$fuzz_seconds" -timeout=120 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$target-" "$corpus" "$@" \
    >"$build/$target.log" 2>&1
}
echo "test-hardening: fuzz_scene and fuzz_messages for ${fuzz_seconds} s each, side by side"
fuzz fuzz_scene -dict=tests/fuzz/scene.dict scenes scenes/catalogue & scene=$!
fuzz fuzz_messages -dict=tests/fuzz/scene.dict tests/fuzz/corpus/messages & messages=$!
failed=()
wait "$scene" || failed+=(fuzz_scene)
wait "$messages" || failed+=(fuzz_messages)
for target in fuzz_scene fuzz_messages; do
  echo "test-hardening: $target:"
  cat "$build/$target.log"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "test-hardening: FAILED: ${failed[*]} (inputs in $build/fuzz-artifacts/)" >&2
  exit 1
fi
echo "test-hardening: passed"
