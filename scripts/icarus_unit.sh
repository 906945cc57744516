#!/usr/bin/env bash
# The texture-unit top under Icarus Verilog 11 on a scene's spans (testbench/icarus/tu_unit_tb.sv;
# stimulus: tu_unit_stimulus, testbench/icarus/tu_unit_stimulus.cpp): the RTL with a unit
# configuration package (`texunit plan SCENE --out PKG.sv`) in place of rtl/0_pkg/tu_unit_cfg_pkg.sv,
# or a gate-level netlist of that unit (osu018 cells; scripts/gate_level.sh --unit makes it).
# Usage: scripts/icarus_unit.sh PKG.sv STIMULUS_DIR [--netlist NET.v] [--stall P] [--seed N] [--log FILE]
#        --log: every output pixel (all output ports, hex) to FILE, for comparing two runs
#        Prints the testbench's PASS line and the wall time; exit 1 on a mismatch or error.
#        TU_TEXUNIT=path/to/texunit (for `texunit rtl-files`; default build/default/...)
#        TU_ICARUS_PLUSARGS=+progress: a testbench line every 1000 cycles
set -euo pipefail
cd "$(dirname "$0")/.."
pkg=${1:?usage: icarus_unit.sh PKG.sv STIMULUS_DIR [--netlist NET.v] [--stall P] [--seed N] [--log FILE]}
stim=${2:?stimulus directory}; shift 2
netlist="" stall=30 seed=1 log=""
while [ $# -gt 0 ]; do
  case $1 in
    --netlist) netlist=$2; shift 2 ;;
    --stall) stall=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --log) log=$2; shift 2 ;;
    *) echo "icarus_unit.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
command -v iverilog >/dev/null || { echo "icarus_unit.sh: iverilog not installed (apt-get install iverilog)" >&2; exit 3; }
for f in "$pkg" "$stim/spans.txt" "$stim/expect.txt" "$stim/texels.hex"; do
  [ -f "$f" ] || { echo "icarus_unit.sh: $f: no such file" >&2; exit 2; }
done
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
if [ -n "$netlist" ]; then
  # The testbench takes its port widths from the two packages; the netlist is the flattened top.
  design=(rtl/0_pkg/tu_formats_pkg.sv "$pkg" /usr/share/qflow/tech/osu018/osu018_stdcells.v "$netlist")
else
  mapfile -t design < <("$tu" rtl-files tu_texture_unit --root . | sed "s#^\(\./\)\?rtl/0_pkg/tu_unit_cfg_pkg\.sv\$#$pkg#")
  [ ${#design[@]} -gt 0 ] || { echo "icarus_unit.sh: no RTL files from '$tu rtl-files' (set TU_TEXUNIT)" >&2; exit 2; }
fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
iverilog -g2012 -Irtl/common -Irtl/generated -o "$dir/sim.vvp" -s tu_unit_tb "${design[@]}" testbench/icarus/tu_unit_tb.sv \
  2>"$dir/err" || { cat "$dir/err" >&2; echo "icarus_unit.sh: iverilog failed" >&2; exit 2; }
words=$(grep -c . "$stim/texels.hex")
t0=$(date +%s.%N)
vvp -n "$dir/sim.vvp" "+dir=$stim" "+texwords=$words" "+stall=$stall" "+seed=$seed" ${log:+"+log=$log"} ${TU_ICARUS_PLUSARGS:-} \
  >"$dir/out" 2>&1 || true
t1=$(date +%s.%N)
grep -v '^VCD' "$dir/out"
grep -q '^tu_unit_tb: PASS' "$dir/out" || exit 1
python3 -c "print('icarus: tu_texture_unit ${netlist:+gate-level ($netlist) }%.1f s' % ($t1 - $t0))"
