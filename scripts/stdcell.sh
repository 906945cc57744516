#!/usr/bin/env bash
# OSU 0.18 um area and timing of RTL tops (scripts/stdcell_flow.sh through `texunit stdcell`), cached
# in docs/report/stdcell_cache.json by the hash of each top's RTL files and the flow script; the
# report reads that cache and never synthesises. Netlists go to build/stdcell/TOP.v (gate level).
# Usage: scripts/stdcell.sh [--force] [--hier] [TOP...]   (default: every top in the Yosys cache, smallest first)
#        --hier: the hierarchical flow (scripts/stdcell_hier.py; cache docs/report/stdcell_hier.json,
#        module netlists in build/stdcell_modules/, two modules mapped at once)
#        scripts/stdcell.sh --table   prints the cache as the Markdown table of docs/area-timing.md
#        Large tops (tu_ewa, tu_ellipse, tu_texture_unit) take long: run them in the background, e.g.
#        nohup scripts/stdcell.sh tu_ewa > build/stdcell_ewa.log 2>&1 &
#        TU_TEXUNIT=path/to/texunit to use another build
set -euo pipefail
cd "$(dirname "$0")/.."
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
if [ "${1:-}" = --table ]; then
  exec python3 - docs/report/stdcell_cache.json "$tu" <<'PY'
import json, os, subprocess, sys
d = json.load(open(sys.argv[1]))
import math
def current(t):
    """The entry's hash against the top's key now (texunit rtl-files --key stdcell); None: cannot tell."""
    if not os.access(sys.argv[2], os.X_OK) or d[t].get("hash", "").startswith("n/a"):
        return None
    r = subprocess.run([sys.argv[2], "rtl-files", t, "--key", "stdcell"], capture_output=True, text=True)
    return r.returncode == 0 and r.stdout.strip() == d[t].get("hash")
# Register overhead of a stage: DFFPOSX1 clock-to-Q (0.749 ns) + set-up (0.187 ns), as OpenSTA
# reports them on tu_reciprocal's critical path; logic left per stage at 150 MHz: 6.667 - 0.936 ns.
ovh, budget = 0.936, 1000 / 150 - 0.936
print("| top | area um2 | cells | flip-flops | ROM / RAM bits (in area) | critical path (ns) | from -> to | fmax MHz | >= 150 MHz | stages the critical stage needs at 150 MHz | flow s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for t in sorted(d, key=lambda t: d[t]["area_um2"]):
    e = d[t]
    mem = ", ".join("%s %d" % (m["kind"], m["bits"]) for m in e["memories"]) or "-"
    ok = "yes" if e["fmax_mhz"] >= 150 else "no (%.0f%% slower)" % (100 * (e["period_ns"] / (1000 / 150) - 1))
    stages = max(1, math.ceil((e["period_ns"] - ovh) / budget))
    cur = current(t)
    if cur is False:  # the RTL or the flow changed since this run: an old figure, marked
        ok = "stale: RTL or flow changed since this run"
    print("| %s | %.0f | %d | %d | %s | %.2f | %s -> %s | %.1f | %s | %d | %s |" % (t, e["area_um2"], e["cells"], e["flip_flops"], mem,
          e["period_ns"], e["path_from"], e["path_to"], e["fmax_mhz"], ok, stages, e.get("flow_seconds", "-")))
PY
fi
force=()
if [ "${1:-}" = --force ]; then force=(--force); shift; fi
if [ "${1:-}" = --hier ]; then force+=(--hier --jobs 2); shift; fi
tops=("$@")
if [ ${#tops[@]} -eq 0 ]; then
  mapfile -t tops < <(python3 -c "import json; d = json.load(open('docs/report/yosys_cache.json'))
for t in sorted(d, key=lambda t: d[t]['cells']): print(t)")
fi
exec nice "$tu" stdcell "${tops[@]}" --root . --update-cache "${force[@]}"
