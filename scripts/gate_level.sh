#!/usr/bin/env bash
# Gate-level simulation: the osu018 netlists of the small blocks (scripts/stdcell.sh writes them to
# build/stdcell/; a top whose cache entry is current is re-run only for its netlist) under Icarus
# with the cell models, through the same SystemVerilog vector testbench as the RTL: golden + stiff
# + N random vectors (default 2000), 30% stalls on both sides, 0 mismatches or exit 1.
# Not in CI (the netlists take minutes). Usage: scripts/gate_level.sh [--random N] [BLOCK...]
#
# scripts/gate_level.sh --unit SCENE.json [--filter F] [--window X0 Y0 X1 Y1] [--stall P] [--seed N]
#   The plan's unit: `texunit plan SCENE` writes its configuration package; scripts/stdcell_flow.sh
#   maps tu_texture_unit with that package (build/stdcell/tu_texture_unit_NAME.v; .json: area,
#   fmax; .seconds: flow time; re-made when the package or an RTL file changed; hours under load);
#   tu_unit_stimulus writes the scene's spans, texel RAM and C-model pixels (--filter: the plan's
#   engine, default bilinear; --window: a crop of the pixel stream, each span clipped to that
#   rectangle); scripts/icarus_unit.sh runs the RTL with the package, then the netlist, on them
#   with the same stalls (default 30 %, seed 1). Passes when both match the C model on every pixel,
#   their output logs (every output port of every pixel) are equal and so are their cycle counts.
#   TU_UNIT_STIMULUS: the stimulus binary (default build/default/testbench/tu_unit_stimulus).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --unit ]; then
  scene=${2:?usage: gate_level.sh --unit SCENE.json [--filter F] [--window X0 Y0 X1 Y1] [--stall P] [--seed N]}
  shift 2
  filter=bilinear window=() stall=30 seed=1
  while [ $# -gt 0 ]; do
    case $1 in
      --filter) filter=$2; shift 2 ;;
      --window) window=(--window "$2" "$3" "$4" "$5"); shift 5 ;;
      --stall) stall=$2; shift 2 ;;
      --seed) seed=$2; shift 2 ;;
      *) echo "gate_level.sh: unknown option $1" >&2; exit 2 ;;
    esac
  done
  tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
  stim_bin=${TU_UNIT_STIMULUS:-build/default/testbench/tu_unit_stimulus}
  name=$(basename "$scene" .json)
  work=build/gate_unit/$name
  net=build/stdcell/tu_texture_unit_$name.v
  mkdir -p "$work" build/stdcell
  "$tu" plan "$scene" --out "$work/tu_unit_cfg_pkg.sv" >"$work/plan.txt"
  mapfile -t files < <("$tu" rtl-files tu_texture_unit --root . | sed "s#^\(\./\)\?rtl/0_pkg/tu_unit_cfg_pkg\.sv\$#$work/tu_unit_cfg_pkg.sv#")
  stale=0
  [ -f "$net" ] && [ -f "${net%.v}.pkg.sv" ] && cmp -s "$work/tu_unit_cfg_pkg.sv" "${net%.v}.pkg.sv" || stale=1
  for f in "${files[@]}" scripts/stdcell_flow.sh; do [ "$f" -nt "$net" ] && [ "$f" != "$work/tu_unit_cfg_pkg.sv" ] && stale=1; done
  if [ $stale = 1 ]; then
    echo "gate_level.sh: mapping tu_texture_unit with the plan of $scene (scripts/stdcell_flow.sh; long)"
    t0=$(date +%s)
    scripts/stdcell_flow.sh tu_texture_unit "$net" "${files[@]}" >"${net%.v}.json"
    echo "$(( $(date +%s) - t0 ))" >"${net%.v}.seconds"
    cp "$work/tu_unit_cfg_pkg.sv" "${net%.v}.pkg.sv"
  fi
  cat "${net%.v}.json"
  "$stim_bin" "$scene" "$work/stim" --filter "$filter" "${window[@]}"
  scripts/icarus_unit.sh "$work/tu_unit_cfg_pkg.sv" "$work/stim" --stall "$stall" --seed "$seed" --log "$work/rtl.log" | tee "$work/rtl.out"
  scripts/icarus_unit.sh "$work/tu_unit_cfg_pkg.sv" "$work/stim" --stall "$stall" --seed "$seed" --log "$work/gate.log" \
    --netlist "$net" | tee "$work/gate.out"
  cmp "$work/rtl.log" "$work/gate.log" || { echo "gate_level.sh: FAIL: the netlist's outputs differ from the RTL's" >&2; exit 1; }
  c_rtl=$(sed -n 's/.* \([0-9]*\) cycles.*/\1/p' "$work/rtl.out")
  c_gate=$(sed -n 's/.* \([0-9]*\) cycles.*/\1/p' "$work/gate.out")
  [ "$c_rtl" = "$c_gate" ] || { echo "gate_level.sh: FAIL: cycles RTL $c_rtl, netlist $c_gate" >&2; exit 1; }
  echo "gate_level.sh: $scene plan unit: $(grep -c . "$work/gate.log") pixels, RTL = netlist = C model, 0 mismatches, $c_gate cycles (${stall}% stalls, seed $seed)"
  exit 0
fi
random=2000
if [ "${1:-}" = --random ]; then random=$2; shift 2; fi
blocks=("$@")
[ ${#blocks[@]} -gt 0 ] || blocks=(reciprocal gauss_weight clip_p1 clip_horner clip_estrin clip_seq persp)
tops=()
for b in "${blocks[@]}"; do tops+=("$(awk -v b="$b" '$1 == b {print $2}' testbench/icarus/blocks.txt)"); done
scripts/stdcell.sh "${tops[@]}"
exec scripts/icarus_all.sh --netlists build/stdcell --random "$random" "${blocks[@]}"
