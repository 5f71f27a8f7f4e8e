#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: installs what is missing, builds, and
# runs every test with ctest (unit tests, then render tests on lavapipe), then the hardening
# checks (scripts/test-hardening.sh: sanitizers and fuzzers).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j 2
# Then the sanitizer build with the whole suite again, and the fuzzers (bounded runs).
bash scripts/test-hardening.sh
