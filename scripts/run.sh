#!/usr/bin/env bash
# Installs what Padrob needs, builds it, and starts it on the bundled liner
# manipulator (for now the command-line program: `padrob check` and `padrob info`;
# the GUI, padrob-studio, takes its place when it exists). Extra arguments go to
# `padrob info` (e.g. --json).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset default >/dev/null
cmake --build --preset default -j "${PADROB_JOBS:-2}" --target padrob
model=models/liner_manipulator.pad
build/default/bin/padrob check "$model"
exec build/default/bin/padrob info "$model" "$@"
