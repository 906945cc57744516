#!/usr/bin/env bash
# Regenerates docs/report.md, docs/report/report.json and the per-block Pareto plots
# (docs/report/*.png) with one command: every block and variant, error / cycles / area / speed.
# Yosys results are cached in docs/report/yosys_cache.json by the RTL files' hash, so a re-run
# only synthesises the tops whose RTL changed. Standard-cell area / timing come from
# docs/report/stdcell_cache.json (read only; scripts/stdcell.sh fills it).
# Usage: scripts/report.sh [COUNT [REPORT-OPTIONS...]]  (random vectors per registry block; default 200000;
#        REPORT-OPTIONS go to texunit report, e.g. --yosys-cached-only to take cells only from cache
#        entries that match the RTL and never synthesise: minutes instead of hours on a cold cache)
#        TU_TEXUNIT=path/to/texunit to use another build
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-200000}
shift $(( $# > 0 ? 1 : 0 ))
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
[ -n "${TU_TEXUNIT:-}" ] || [ -x "$tu" ] || { cmake --preset default >/dev/null && cmake --build --preset default --target texunit; }
start=$(date +%s)
"$tu" report --count "$count" --root . --yosys-cache docs/report/yosys_cache.json \
  --stdcell-cache docs/report/stdcell_cache.json \
  --json docs/report/report.json --plots docs/report --markdown docs/report.md "$@"
rm -f docs/report/*.dat docs/report/*.gp  # plot inputs; the PNGs and the JSON are the result
echo "scripts/report.sh: $(( $(date +%s) - start )) s" >&2
