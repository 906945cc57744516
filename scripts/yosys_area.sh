#!/usr/bin/env bash
# Generic Yosys synthesis of one RTL top: prints one JSON object with the $mul count (before
# techmap, flattened), the total cell count and the flip-flop count after `synth`.
# Usage: scripts/yosys_area.sh TOP FILE.sv...   (files in dependency order, package first)
# TU_YOSYS_PARAMS="Name Value ..." overrides parameters of TOP (Yosys chparam), e.g. "HasPom 0".
set -euo pipefail
top=${1:?usage: yosys_area.sh TOP FILES...}; shift
command -v yosys >/dev/null || { echo '{"error": "yosys not installed"}'; exit 3; }
rtl=$(cd "$(dirname "$0")/../rtl" && pwd)
inc="-I$rtl/common -I$rtl/generated"  # `include files (rtl/manifest.json include_dirs)
log=$(mktemp)
trap 'rm -f "$log"' EXIT
chparam=""
params=(${TU_YOSYS_PARAMS:-})
for ((i = 0; i + 1 < ${#params[@]}; i += 2)); do chparam+="chparam -set ${params[i]} ${params[i+1]} $top; "; done
yosys -q -l "$log" -p "read_verilog -sv $inc $*; $chparam hierarchy -top $top; proc; flatten; opt; wreduce; opt_clean; tee -o /dev/stdout stat; synth -flatten -top $top; tee -o /dev/stdout stat" >/dev/null
python3 - "$log" "$top" <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
stats = text.split("Number of wire bits")  # one block per `stat`
def cells(block):
    out = {}
    for m in re.finditer(r"^\s+(\$\S+)\s+(\d+)\s*$", block, re.M):
        out[m.group(1)] = out.get(m.group(1), 0) + int(m.group(2))
    return out
pre, post = cells(stats[1]), cells(stats[2])
total = sum(post.values())
ffs = sum(n for c, n in post.items() if "DFF" in c or "DLATCH" in c)
latches = sum(n for c, n in post.items() if "DLATCH" in c)
print(json.dumps({"top": sys.argv[2], "multipliers": pre.get("$mul", 0), "cells": total,
                  "flip_flops": ffs, "latches": latches}))
PY
