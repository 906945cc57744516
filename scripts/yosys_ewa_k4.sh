#!/usr/bin/env bash
# Generic Yosys cells of the K = 4 EWA engine (tu_ewa Lanes = 4, Setups = 3) as docs/blocks/ewa.md
# states them: the commands of scripts/yosys_area.sh on the wrapper scripts/synth/tu_ewa_k4_top.sv
# (Yosys 0.23 cannot chparam tu_ewa). About 27 min under load; prints one JSON object.
# Usage: scripts/yosys_ewa_k4.sh   (TU_TEXUNIT=path/to/texunit for the file list)
set -euo pipefail
cd "$(dirname "$0")/.."
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
mapfile -t files < <("$tu" rtl-files tu_ewa)
exec scripts/yosys_area.sh tu_ewa_k4_top "${files[@]}" scripts/synth/tu_ewa_k4_top.sv
