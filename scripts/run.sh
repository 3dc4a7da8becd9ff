#!/usr/bin/env bash
# Installs what Padrob needs, builds it, and starts padrob-studio on the bundled
# liner manipulator (models/liner_manipulator_fluid.pad, in fluid power). Press F5 to run the simulation;
# with the 3D view focused, hold Q/A, W/S, E/D… to open the valves (Simulation ▸
# Keyboard Controls lists them).
#
# Without a display (a headless machine, a CI container) there is no window to show:
# the command-line program describes the machine and drives it through a short
# demonstration instead (resources/demo/liner_demo_input.csv: boom up, telescope
# out, slew, wrist down, claws closed), printing its events and one row a second.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset default >/dev/null
model=models/liner_manipulator_fluid.pad
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  cmake --build --preset default -j "${PADROB_JOBS:-2}" --target padrob-studio
  exec build/default/bin/padrob-studio "$model"
fi
cmake --build --preset default -j "${PADROB_JOBS:-2}" --target padrob
padrob=build/default/bin/padrob
echo "run.sh: no display, so no window: the command-line program instead." >&2
"$padrob" info "$model"
echo
echo "Demonstration: $padrob simulate $model --time 14 --input resources/demo/liner_demo_input.csv --every 1000"
exec "$padrob" simulate "$model" --time 14 --input resources/demo/liner_demo_input.csv --every 1000
