#!/usr/bin/env bash
# Standard-cell synthesis and static timing of one RTL top in OSU 0.18 um (qflow-tech-osu018):
# Yosys 0.23 `synth -flatten` (coarse part), maccmap (multiplies and multiply-adds as carry-save
# trees of full adders instead of a chain of ripple adders), techmap ($lcu = Brent-Kung),
# dfflibmap + `abc -liberty -D` (delay-oriented mapping with the script strash; dch -f; map -D; buffer;
# upsize; dnsize: ABC's default liberty script with &nf takes minutes per small block, and without
# buffering a pipeline enable driving hundreds of flops sets the critical path; dch -f, structural
# choices, instead of dc2, which rewrote Yosys's Brent-Kung carry trees into ripple chains: a
# registered 49-bit adder 6.31 ns with dc2), `stat -liberty`; then OpenSTA:
# one clock on clk_i, ideal (no clock tree), zero input / output delays, no wire load
# (the library defines none; nets cost only the pin capacitances they drive).
# Prints one JSON object: area_um2, cells, flip_flops, latches, memories (bits per $mem, before
# mapping: ROMs become logic and are inside area_um2), period_ns (the critical path), fmax_mhz,
# path_from / path_to (its start and end points).
# Usage: scripts/stdcell_flow.sh TOP NETLIST.v FILE.sv...   (files package first)
#        TU_ABC_TARGET_PS: ABC delay target in ps (default 6667, i.e. 150 MHz)
set -euo pipefail
top=${1:?usage: stdcell_flow.sh TOP NETLIST.v FILES...}; net=${2:?netlist path}; shift 2
lib=${TU_OSU018_LIB:-/usr/share/qflow/tech/osu018/osu018_stdcells.lib}
target=${TU_ABC_TARGET_PS:-6667}
command -v yosys >/dev/null || { echo '{"error": "yosys not installed"}'; exit 3; }
command -v sta >/dev/null || { echo '{"error": "OpenSTA (sta) not installed"}'; exit 3; }
[ -f "$lib" ] || { echo "{\"error\": \"$lib missing (package qflow-tech-osu018)\"}"; exit 3; }
rtl=$(cd "$(dirname "$0")/../rtl" && pwd)
inc="-I$rtl/common -I$rtl/generated"  # `include files (rtl/manifest.json include_dirs)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$(dirname "$net")"
printf 'strash\ndch -f\nmap -D %s\ntopo\nbuffer -p\nupsize -D %s\ndnsize -D %s\n' "$target" "$target" "$target" > "$dir/abc.script"
yosys -q -l "$dir/ylog" -p "read_verilog -sv $inc $*; hierarchy -top $top; synth -flatten -top $top -run :fine;
  tee -q -o $dir/mem.il dump t:\$mem_v2; opt -fast -full; memory_map; opt -full; maccmap; techmap; opt -fast;
  dfflibmap -liberty $lib; abc -liberty $lib -D $target -script $dir/abc.script; opt_clean;
  tee -q -o $dir/stat.txt stat -liberty $lib; write_verilog -noattr -noexpr $net" >/dev/null
cat > "$dir/sta.tcl" <<TCL
read_liberty $lib
read_verilog $net
link_design $top
create_clock -name clk -period 1000 [get_ports clk_i]
set_input_delay 0 -clock clk [delete_from_list [all_inputs] [get_ports clk_i]]
set_output_delay 0 -clock clk [all_outputs]
set_false_path -from [get_ports rst_ni]
report_checks -path_delay max -format full -digits 4
TCL
sta -no_init -exit "$dir/sta.tcl" > "$dir/sta.txt" 2>&1 || { cat "$dir/sta.txt" >&2; exit 2; }
python3 - "$dir" "$top" "$net" <<'PY'
import json, re, sys
d, top, net = sys.argv[1], sys.argv[2], sys.argv[3]
netlist = open(net).read()
def register(point):
    """A flip-flop instance is named by the register (net) on its Q pin; ports stay as they are."""
    inst = point.split("/")[0]
    m = re.search(r"DFF\w* " + re.escape(inst) + r" \((.*?)\);", netlist, re.S)
    q = m and re.search(r"\.Q\(\\?([^)]*?)\s*\)", m.group(1))
    return q.group(1).replace(" ", "") if q else point
stat = open(d + "/stat.txt").read()
cells = {m.group(1): int(m.group(2)) for m in re.finditer(r"^\s+(\S+)\s+(\d+)\s*$", stat, re.M)
         if not m.group(1).startswith("Number")}
area = float(re.search(r"Chip area for (?:top )?module .*?:\s*([\d.]+)", stat).group(1))
ffs = sum(n for c, n in cells.items() if c.startswith("DFF"))
latches = cells.get("LATCH", 0)
mems = []
for m in re.finditer(r"cell \$mem_v2 (\S+)(.*?)\n\s*end", open(d + "/mem.il").read(), re.S):
    p = dict(re.findall(r"parameter \\(\w+) (\S+)", m.group(2)))
    num = lambda k: int(p[k].split("'")[-1], 2) if "'" in p[k] else int(p[k])
    mems.append({"name": m.group(1), "bits": num("WIDTH") * num("SIZE"),
                 "kind": "rom" if num("WR_PORTS") == 0 else "ram"})
sta = open(d + "/sta.txt").read()
start = register(re.search(r"^Startpoint: (\S+)", sta, re.M).group(1))
end = register(re.search(r"^Endpoint: (\S+)", sta, re.M).group(1))
arrival = float(re.search(r"^\s*([\d.]+)\s+data arrival time", sta, re.M).group(1))
# Required time = period + clock latency 0 - setup: the period the path needs is arrival + setup.
required = float(re.search(r"^\s*([\d.]+)\s+data required time", sta, re.M).group(1))
period = arrival + (1000.0 - required)
print(json.dumps({"top": top, "area_um2": round(area, 1), "cells": sum(cells.values()), "flip_flops": ffs,
                  "latches": latches, "memories": mems, "period_ns": round(period, 3),
                  "fmax_mhz": round(1000.0 / period, 1), "path_from": start, "path_to": end}))
PY
