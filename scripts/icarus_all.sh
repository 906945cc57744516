#!/usr/bin/env bash
# Every block of testbench/icarus/blocks.txt under Icarus Verilog 11 on its golden set
# (vectors/golden/) and its stiff set (written by `texunit vectors --set stiff`), 30% stalls on
# both sides: the CI test Icarus.GoldenAndStiff. Exit 1 on any mismatch.
# Usage: scripts/icarus_all.sh [--netlists DIR] [--random N] [BLOCK...]
#        --netlists DIR: the gate-level netlists DIR/TOP.v instead of the RTL (scripts/stdcell.sh)
#        --random N: also N seeded random vectors per block (seed 7)
#        TU_TEXUNIT=path/to/texunit (default build/default/tools/texunit/texunit)
set -euo pipefail
cd "$(dirname "$0")/.."
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
export TU_TEXUNIT=$tu
netdir="" random=0
while [ $# -gt 0 ]; do
  case $1 in
    --netlists) netdir=$2; shift 2 ;;
    --random) random=$2; shift 2 ;;
    *) break ;;
  esac
done
blocks=("$@")
# Left out of the default list (the CI test), run by name: texel_depth's stiff set takes ~4.6 min
# under Icarus on a loaded machine (22,115 vectors): `scripts/icarus_all.sh texel_depth`; the
# texel decoders' stiff sets are exhaustive (texel_decode 787,454 and bc1_decode 786,432 vectors,
# ~9 min under Icarus): `scripts/icarus_all.sh texel_decode bc1_decode` (Verilator runs them in CI).
ci_skip=" texel_depth texel_decode bc1_decode "
[ ${#blocks[@]} -gt 0 ] || mapfile -t blocks < <(awk -v skip="$ci_skip" '!/^#/ && NF && index(skip, " " $1 " ") == 0 {print $1}' testbench/icarus/blocks.txt)
command -v iverilog >/dev/null || { echo "icarus_all.sh: skipped: iverilog not installed (apt-get install iverilog)"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=()
for b in "${blocks[@]}"; do
  opt=()
  if [ -n "$netdir" ]; then
    top=$(awk -v b="$b" '$1 == b {print $2}' testbench/icarus/blocks.txt)
    opt=(--netlist "$netdir/$top.v")
  fi
  "$tu" vectors --block "$b" --set stiff --seed 1 --out "$tmp/$b.stiff.vec" >/dev/null
  sets=("vectors/golden/$b.vec" "$tmp/$b.stiff.vec")
  if [ "$random" -gt 0 ]; then
    "$tu" vectors --block "$b" --set random --count "$random" --seed 7 --out "$tmp/$b.random.vec" >/dev/null
    sets+=("$tmp/$b.random.vec")
  fi
  for v in "${sets[@]}"; do
    scripts/icarus_cosim.sh "$b" "$v" "${opt[@]}" | grep -E '^(tu_vec_tb|icarus):' || failed+=("$b:$(basename "$v")")
  done
done
[ ${#failed[@]} -eq 0 ] || { echo "icarus_all.sh: FAILED: ${failed[*]}" >&2; exit 1; }
echo "icarus_all.sh: ${#blocks[@]} blocks${netdir:+ (gate level, $netdir)}, golden + stiff$([ "$random" = 0 ] || echo " + $random random"), 0 mismatches"
