# Sourced by scripts/test.sh and scripts/test-package.sh: when there is no X display,
# starts a virtual one (Xvfb, 1920x1080) on the first free display number from 90,
# exports DISPLAY, and stops it when the sourcing script exits.
if [ -z "${DISPLAY:-}" ]; then
  xvfb_pid=""
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
