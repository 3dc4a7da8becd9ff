#!/usr/bin/env bash
# Installs what Padrob needs, builds it, and runs every test:
#   1. the default build (RelWithDebInfo) and all its tests, the GUI's as real windows
#      on an X server (a virtual one, Xvfb, when there is no DISPLAY);
#   2. the solver and its tests again under AddressSanitizer + UBSan (parser fuzzing,
#      bad input), so memory errors and undefined behaviour fail the run;
#   3. the solver thread's test (studio.sim_test: SimulationRunner and the GUI thread)
#      under ThreadSanitizer, so a data race in studio:: or solver:: code fails the run.
#      The `tsan` presets build only that test and what it links (solver, studio_model,
#      studio_sim), run it on Qt's offscreen platform, and suppress only Qt's own
#      reports (Qt is not instrumented; tests/studio/tsan.supp).
# After the default tests, scripts/test-package.sh builds the .deb and runs the installed
# programs from a temporary root.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=${PADROB_JOBS:-2}

cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"

# the GUI tests need an X server (the 3D view's OpenGL window does not work with Qt's `offscreen`
# platform): without a display, start a virtual one for the run
. scripts/start-xvfb.sh
ctest --preset default -j "$jobs"
# the Debian package, installed into a temporary root and run from there (docs/packaging.md)
scripts/test-package.sh build/default

cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --preset asan -j "$jobs"

cmake --preset tsan >/dev/null
cmake --build --preset tsan --target studio_sim_test -j "$jobs"
ctest --preset tsan  # TSAN_OPTIONS (halt_on_error, suppressions) come with the preset
echo "test.sh: all tests passed"
