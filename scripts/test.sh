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
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=${PADROB_JOBS:-2}

cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"

# the GUI tests need an X server (the 3D view's OpenGL window does not work with Qt's `offscreen`
# platform): without a display, start a virtual one for the run
xvfb_pid=""
if [ -z "${DISPLAY:-}" ]; then
  for n in $(seq 90 120); do
    [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ] && continue
    Xvfb ":$n" -screen 0 1920x1080x24 -nolisten tcp >/dev/null 2>&1 &
    xvfb_pid=$!
    export DISPLAY=":$n"
    break
  done
  trap '[ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true' EXIT
  for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X${DISPLAY#:}" ] && break; sleep 0.1; done
fi
ctest --preset default -j "$jobs"

cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --preset asan -j "$jobs"

cmake --preset tsan >/dev/null
cmake --build --preset tsan --target studio_sim_test -j "$jobs"
ctest --preset tsan  # TSAN_OPTIONS (halt_on_error, suppressions) come with the preset
echo "test.sh: all tests passed"
