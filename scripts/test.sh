#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: installs what is missing, builds, and
# runs every test with ctest (unit tests, then render tests on lavapipe), then the hardening
# checks (scripts/test-hardening.sh: sanitizers and fuzzers), then the deployment on a real
# container engine (podman): the image built and probed, and the run command on a bare Debian.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j 2
# Then the sanitizer build with the whole suite again, and the fuzzers (bounded runs).
bash scripts/test-hardening.sh

# A deployment step, bounded and timed; exit 77 means the engine cannot start on this machine:
# the step is skipped, loudly, rather than failed. The whole run keeps to a budget
# (TEST_BUDGET_SECONDS, 80 min: CI stops at 90): a step gets at most what is left of it, and
# one that has no time left, or runs out of it, is skipped with that reason, loudly.
budget=${TEST_BUDGET_SECONDS:-4800}
deploy_step() {
  local limit=$1 start status=0 left=$(( budget - SECONDS ))
  shift
  if [ "$left" -lt 300 ]; then
    echo "test: SKIPPED $1: the run's time budget ($budget s) is spent after $SECONDS s"
    return 0
  fi
  [ "$limit" -le "$left" ] || limit=$left
  start=$(date +%s)
  timeout --kill-after=30 "$limit" bash "$@" || status=$?
  if [ "$status" -eq 124 ] && [ "$limit" -eq "$left" ]; then
    echo "test: SKIPPED $1: stopped when the run's time budget ($budget s) ran out after $(( $(date +%s) - start )) s"
  elif [ "$status" -eq 77 ]; then
    echo "test: SKIPPED $1 (see its message above) after $(( $(date +%s) - start )) s"
  elif [ "$status" -ne 0 ]; then
    echo "test: $1 FAILED (status $status) after $(( $(date +%s) - start )) s" >&2
    return 1
  else
    echo "test: $1 passed in $(( $(date +%s) - start )) s"
  fi
}
deploy_step 1800 tests/deploy/image_test.sh
deploy_step 1500 tests/deploy/fresh_run_test.sh 1400
