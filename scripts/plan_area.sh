#!/usr/bin/env bash
# Yosys cells of the texture-unit RTL top, full against specialised to a scene:
# `texunit plan SCENE --out PLAN.sv --out-full FULL.sv` writes both tu_unit_cfg_pkg packages; every
# localparam of the package that the top declares as a parameter is set with `chparam`, and the
# top is synthesised twice (generic `synth`, as scripts/yosys_area.sh). Exit 1 when the plan
# leaves hardware out (some parameter differs) but the cell count does not drop.
# Usage: scripts/plan_area.sh [--coarse] SCENE.json|default [TOP]   (TOP: default tu_texture_unit)
#        --coarse: cells after proc/flatten/opt, before techmap (seconds instead of the tens of
#        minutes `synth` takes on the whole top)
#        TU_TEXUNIT=path/to/texunit to use another build
set -euo pipefail
cd "$(dirname "$0")/.."
coarse=0
if [ "${1:-}" = --coarse ]; then coarse=1; shift; fi
scene=${1:?usage: scripts/plan_area.sh [--coarse] SCENE.json|default [TOP]}
top=${2:-tu_texture_unit}
flow="synth -flatten -top $top"
[ $coarse = 0 ] || flow="opt_clean"
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
command -v yosys >/dev/null || { echo "cells not measured: yosys not installed" >&2; exit 3; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$tu" plan "$scene" --out "$dir/plan.sv" --out-full "$dir/full.sv" >/dev/null 2>"$dir/err" || { cat "$dir/err" >&2; exit 2; }
files=$("$tu" rtl-files "$top" --root . | tr '\n' ' ')
inc=$("$tu" rtl-files --list include-dirs --root . | sed 's/^/-I/' | tr '\n' ' ')
top_file=$(grep -lE "^\s*module\s+$top\b" $files)
declared=$(grep -oE "^\s*parameter\s+(int\s+unsigned\s+|int\s+|bit\s+)?[A-Z][A-Za-z0-9]*" "$top_file" | awk '{print $NF}')

# "Name value" for every localparam of a package (1'b1 -> 1, 3'd7 -> 7).
params() { sed -nE "s/^ *localparam [^=]* ([A-Z][A-Za-z0-9]*) = ([0-9]+'[bd])?([0-9]+);.*/\1 \3/p" "$1"; }

cells() {
  local chp="" set=""
  while read -r name value; do
    if grep -qx "$name" <<<"$declared"; then chp+="chparam -set $name $value $top; "; set+="$name=$value "; fi
  done < <(params "$1")
  yosys -q -l "$dir/log" -p "read_verilog -sv $inc $files; $chp hierarchy -top $top; proc; flatten; opt; $flow; tee -o $dir/stat stat" >/dev/null 2>"$dir/err" ||
    { cat "$dir/err" >&2; exit 2; }
  echo "$(grep -E 'Number of cells' "$dir/stat" | tail -1 | awk '{print $NF}') ${set:-(no parameter of $top set)}"
}

full_out=$(cells "$dir/full.sv")  # an assignment, so that a failed synthesis stops the script
plan_out=$(cells "$dir/plan.sv")
read -r full full_set <<<"$full_out"
read -r plan plan_set <<<"$plan_out"
echo "$top full:        $full cells  ($full_set)"
echo "$top specialised: $plan cells  ($plan_set) for $scene"
if [ "$full_set" != "$plan_set" ] && [ "$plan" -ge "$full" ]; then
  echo "FAIL: the plan leaves hardware out but the cells do not drop" >&2
  exit 1
fi
