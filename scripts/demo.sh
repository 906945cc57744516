#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job (`texunit demo`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)" --target texunit
exec build/default/tools/texunit/texunit demo "$@"
