#!/usr/bin/env bash
# Gate-level simulation: the osu018 netlists of the small blocks (scripts/stdcell.sh writes them to
# build/stdcell/; a top whose cache entry is current is re-run only for its netlist) under Icarus
# with the cell models, through the same SystemVerilog vector testbench as the RTL: golden + stiff
# + N random vectors (default 2000), 30% stalls on both sides, 0 mismatches or exit 1.
# Not in CI (the netlists take minutes). Usage: scripts/gate_level.sh [--random N] [BLOCK...]
set -euo pipefail
cd "$(dirname "$0")/.."
random=2000
if [ "${1:-}" = --random ]; then random=$2; shift 2; fi
blocks=("$@")
[ ${#blocks[@]} -gt 0 ] || blocks=(reciprocal gauss_weight clip_p1 clip_horner clip_estrin clip_seq persp)
tops=()
for b in "${blocks[@]}"; do tops+=("$(awk -v b="$b" '$1 == b {print $2}' testbench/icarus/blocks.txt)"); done
scripts/stdcell.sh "${tops[@]}"
exec scripts/icarus_all.sh --netlists build/stdcell --random "$random" "${blocks[@]}"
