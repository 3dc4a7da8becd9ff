#!/usr/bin/env bash
# Installs what Padrob needs, builds it, and starts it on the bundled liner
# manipulator. Until the GUI (padrob-studio) exists this is the command-line program:
# it describes the machine (`padrob info`) and then drives it through a short
# demonstration (`padrob simulate` with resources/demo/liner_demo_input.csv: boom up,
# telescope out, slew, wrist down, claws closed), printing the events and one row of
# the trajectory a second.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset default >/dev/null
cmake --build --preset default -j "${PADROB_JOBS:-2}" --target padrob
padrob=build/default/bin/padrob
model=models/liner_manipulator.pad
"$padrob" info "$model"
echo
echo "Demonstration: $padrob simulate $model --time 14 --input resources/demo/liner_demo_input.csv --every 1000"
exec "$padrob" simulate "$model" --time 14 --input resources/demo/liner_demo_input.csv --every 1000
