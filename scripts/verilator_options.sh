#!/usr/bin/env bash
# Does a Verilator option pay? Builds tu_reciprocal three ways (FST tracing compiled in but off,
# as every co-simulation model is built; no tracing; no tracing with -O3 -march=native C++) with
# testbench/bench/vl_reciprocal_drv.cpp and runs each RUNS times, interleaved (docs/performance.md).
# Usage: scripts/verilator_options.sh [RUNS]   (needs build/default/tools/texunit/texunit)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
tu=build/default/tools/texunit/texunit
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mapfile -t src < <("$tu" rtl-files tu_reciprocal --root .)
for mode in trace notrace o3native; do
  extra=(); cflags="-O2"
  [ "$mode" = trace ] && extra=(--trace-fst)
  [ "$mode" = o3native ] && cflags="-O3 -march=native"
  nice verilator --cc -Wno-fatal -Wno-lint -Wno-style -O3 --x-assign fast --x-initial fast \
    -Irtl/generated "${extra[@]}" --top-module tu_reciprocal --Mdir "$work/$mode" \
    --exe "$PWD/testbench/bench/vl_reciprocal_drv.cpp" "${src[@]}" \
    -CFLAGS "$cflags -DMODE=\\\"$mode\\\"" --build -j 2 >"$work/$mode.log" 2>&1 \
    || { cat "$work/$mode.log"; exit 1; }
done
for _ in $(seq "$runs"); do
  for mode in trace notrace o3native; do "$work/$mode/Vtu_reciprocal"; done
done
