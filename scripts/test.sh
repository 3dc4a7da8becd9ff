#!/usr/bin/env bash
# Installs what Padrob needs, builds it, and runs every test:
#   1. the default build (RelWithDebInfo) and all its tests;
#   2. the solver and its tests again under AddressSanitizer + UBSan (parser fuzzing,
#      bad input), so memory errors and undefined behaviour fail the run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=${PADROB_JOBS:-2}

cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
ctest --preset default -j "$jobs"

cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --preset asan -j "$jobs"
echo "test.sh: all tests passed"
