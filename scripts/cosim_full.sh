#!/usr/bin/env bash
# Full co-simulation of one block: stiff, golden and 1,000,000 random vectors, 30% stalls.
# Usage: scripts/cosim_full.sh BLOCK [COUNT]      (TU_TEXUNIT=path/to/texunit to use another build;
#        TU_RTL=VARIANT runs another RTL scheme on the block's vectors, e.g. TU_RTL=perlin3d_serial)
set -euo pipefail
cd "$(dirname "$0")/.."
block=${1:?usage: scripts/cosim_full.sh BLOCK [COUNT]}
count=${2:-1000000}
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
[ -n "${TU_TEXUNIT:-}" ] || [ -x "$tu" ] || { cmake --preset default >/dev/null && cmake --build --preset default --target texunit; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for set in golden stiff random; do
  "$tu" vectors --block "$block" --set "$set" --count "$count" --seed 2026 --out "$dir/$set.vec"
  "$tu" cosim --block "$block" ${TU_RTL:+--rtl "$TU_RTL"} --vectors "$dir/$set.vec" --stall-prob 0.3 --json
done
