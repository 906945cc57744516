#!/usr/bin/env python3
"""Hierarchical, incremental standard-cell flow of one RTL top in OSU 0.18 um (qflow-tech-osu018).

Each module x parameter set of the top's hierarchy is synthesised and mapped once, on its own (the
modules it instantiates are black boxes), and its gate-level netlist is cached under CACHE_DIR by a
key: the SHA-256 of this script, the Liberty file, the ABC script, target and port constraints, the
module's elaborated RTLIL (Yosys `hierarchy`: its source with parameters, packages and `include
files resolved; source locations and Yosys's global name counters removed, so a comment or a change
in another file does not change it) and the port lists of the modules it instantiates. A module is
mapped together with (flattened into) its parent when the flattened flow would fold constants into
it: every child of a parent that instantiates a module without inputs (a coefficient table), and a
child with a constant on an input port. The top's netlist is the union of the cached module
netlists; OpenSTA times it across the hierarchy with the assumptions of scripts/stdcell_flow.sh
(one ideal clock on clk_i, zero I/O delays, no wire load, rst_ni false path).

Per module the Yosys steps are those of scripts/stdcell_flow.sh (`synth -flatten -run :fine`, which
flattens only the inlined children, memory_map, maccmap, techmap, dfflibmap, abc -liberty -D,
opt_clean), with ABC told that ports are driven by a BUFX2 and loaded by 0.05 pF. Cells, area and
flip-flops are counted from the mapped netlists (Liberty cell areas): cells, area and timing come
from one run.

Prints one JSON object: area_um2, cells, flip_flops, latches, memories, period_ns, fmax_mhz,
path_from, path_to (as scripts/stdcell_flow.sh), and modules (distinct module netlists),
instances, mapped (modules mapped in this run; the rest came from the cache), abc (the script).

Usage: scripts/stdcell_hier.py [--cache-dir D] [--jobs N] [--abc nf|map] [--flat] TOP NETLIST.v [FILE.sv...]
       (files package first; default: the top's files in rtl/manifest.json; cache dir default
       build/stdcell_modules)
       TU_OSU018_LIB: the Liberty file; TU_ABC_TARGET_PS: ABC delay target in ps (default 6667)
Exit 3 with {"error": ...} when yosys, sta or the Liberty file is missing (the message names the
Debian package).
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIB = os.environ.get("TU_OSU018_LIB", "/usr/share/qflow/tech/osu018/osu018_stdcells.lib")
TARGET = os.environ.get("TU_ABC_TARGET_PS", "6667")
# `map`: the script of scripts/stdcell_flow.sh. `nf` (default, the shorter periods at equal area in
# docs/area-timing.md): Yosys 0.23's own `abc -liberty -D` script without dc2 (it rewrote
# Brent-Kung carry trees into ripple chains), with buffering and sizing.
ABC = {
    "map": "strash\ndch -f\nmap -D {T}\ntopo\nbuffer -p\nupsize -D {T}\ndnsize -D {T}\n",
    "nf": "strash\n&get -n\n&fraig -x\n&put\nscorr\ndretime\nstrash\n&get -n\n&dch -f\n&nf -D {T}\n&put\n"
          "buffer\nupsize -D {T}\ndnsize -D {T}\n",
}
# A port is driven and loaded by another module's gates: without a drive and a load ABC neither
# buffers an input that fans out to every flip-flop (a pipeline enable) nor sizes an output driver.
CONSTR = "set_driving_cell BUFX2\nset_load 0.05\n"
MODULE_YS = """read_rtlil {il}
synth -flatten -top {top} -run :fine
tee -q -o {mem} dump t:$mem_v2
opt -fast -full; memory_map; opt -full; maccmap; techmap; opt -fast
dfflibmap -liberty {lib}
abc -liberty {lib} -D {target} -constr constr.txt -script {abc}
opt_clean
write_verilog -noattr -noexpr {net}
"""


def manifest_files(top):
    """The top's sources as `texunit rtl-files TOP` lists them (rtl/manifest.json: packages first)."""
    m = json.load(open(os.path.join(ROOT, "rtl", "manifest.json")))
    blocks = m["blocks"]
    block = next((n for n, b in blocks.items() if top in b.get("tops", [])), None)
    if block is None:
        fail("RTL top '%s' is in no block's \"tops\" in rtl/manifest.json" % top, 2)
    pkgs, files = ["tu_formats_pkg"], []

    def visit(n):
        for u in blocks[n].get("uses", []):
            visit(u)
        pkgs.extend(p for p in blocks[n].get("packages", []) if p not in pkgs)
        files.extend(f for f in blocks[n].get("files", []) if f not in files)
    visit(block)
    return ["rtl/" + m["packages"][p] for p in pkgs] + ["rtl/" + f for f in files]


def fail(msg, code=3):
    print(json.dumps({"error": msg}))
    sys.exit(code)


def sha(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode() if isinstance(p, str) else p)
        h.update(b"\0")
    return h.hexdigest()


# ---- elaborated design: split into modules, names made safe and deterministic ----
MODULE_RE = re.compile(r"^((?:attribute [^\n]*\n)*)module (\S+)\n(.*?)^end\n", re.S | re.M)
SRC_ID = re.compile(r"\$([^\s$\\]*\.svh?):(\d+)\$(\d+)")  # $file:line$counter inside auto names
BARE_ID = re.compile(r"(?<=[A-Za-z_])\$(\d+)")              # $fordecl_block$12: a global counter
PORT_RE = re.compile(r"^\s*wire\b.*\b(?:input|output|inout) \d+ (?:signed )?\S+$", re.M)


def safe_name(yname):
    """`\\name` stays `name`; a derived `$paramod...\\name...` becomes name__<hash of the derived name>."""
    if yname.startswith("\\"):
        return yname[1:]
    m = re.match(r"^\$paramod(?:\$[0-9a-f]+)?\\([^\\]+)", yname)
    if not m:
        raise SystemExit("stdcell_hier: unexpected module name " + yname)
    return m.group(1) + "__" + hashlib.sha1(yname.encode()).hexdigest()[:10]


def normalise(body):
    """Module text without source locations and with per-module numbering of Yosys's auto names."""
    body = re.sub(r"^\s*attribute \\src .*\n", "", body, flags=re.M)
    src, bare = {}, {}
    body = SRC_ID.sub(lambda m: "$s%d" % src.setdefault(m.groups(), len(src)), body)
    return BARE_ID.sub(lambda m: "$%d" % bare.setdefault(m.group(1), len(bare)), body)


CONST_SIG = re.compile(r"^(?:\d+'[01xz]+|-?\d+)$")
CELL_RE = re.compile(r"^  cell \\(\S+) \S+\n(.*?)^  end\n", re.S | re.M)


def split(il):
    mods = {}
    for attrs, yname, body in MODULE_RE.findall(il):
        attrs = "".join(l + "\n" for l in attrs.splitlines() if not l.startswith("attribute \\src"))
        mods[yname] = (attrs, body)
    rename = {y: safe_name(y) for y in mods}
    out = {}
    for yname, (attrs, body) in mods.items():
        def cell(m):
            t = m.group(2)
            return m.group(1) + "\\" + rename[t] + " " if t in rename else m.group(0)
        body = re.sub(r"^(\s*cell )(\S+) ", cell, body, flags=re.M)
        out[rename[yname]] = {"yosys_name": yname, "attrs": attrs, "body": normalise(body)}
    for m in out.values():
        ports = PORT_RE.findall(m["body"])
        m["ports"] = "\n".join(p.strip() for p in ports)
        m["inputs"] = [p.split()[-1] for p in ports if " input " in p]
    for m in out.values():
        # Children, and those with a constant on an input port (the flattened flow would fold it).
        m["children"], const = {}, set()
        for t, conns in CELL_RE.findall(m["body"]):
            if t not in out:
                continue
            m["children"][t] = m["children"].get(t, 0) + 1
            for port, sig in re.findall(r"^\s*connect (\S+) (.*)$", conns, re.M):
                if port in out[t]["inputs"] and CONST_SIG.match(sig.strip()):
                    const.add(t)
        # A child without inputs is a constant generator (coefficient tables): its parent is mapped
        # with its whole subtree flat, so the constants reach the multipliers they feed.
        if any(not out[t]["inputs"] for t in m["children"]):
            const = set(m["children"])
        m["inline"] = sorted(const)
    return out


def subtree(name, mods):
    """name and every module under it."""
    seen, todo = set(), [name]
    while todo:
        n = todo.pop()
        if n not in seen:
            seen.add(n)
            todo.extend(mods[n]["children"])
    return seen


def unit(name, mods):
    """The modules mapped as one netlist NAME (it and its inlined subtrees) and the black boxes it
    instantiates (mapped on their own)."""
    flat = {name}
    for c in mods[name]["inline"]:
        flat |= subtree(c, mods)
    boxes = {c for n in flat for c in mods[n]["children"] if c not in flat}
    return flat, boxes


def module_il(name, mods):
    """The module, the modules it inlines, and black-box stubs (ports only) of the others it instantiates."""
    flat, boxes = unit(name, mods)
    text = ""
    for n in sorted(flat):
        text += mods[n]["attrs"] + "module \\" + n + "\n" + mods[n]["body"] + "end\n"
    for c in sorted(boxes):
        text += "attribute \\blackbox 1\nmodule \\" + c + "\n" + "".join("  " + p + "\n" for p in mods[c]["ports"].splitlines()) + "end\n"
    return text


# ---- netlists: instances and Liberty areas ----
INST_RE = re.compile(r"^\s*(\\?\S+)\s+(\\\S+ |[A-Za-z_][\w$]*)\s*\((.*?)\);", re.S | re.M)


def instances(netlist):
    """(cell type, instance name, connection text) of every instance in a one-module netlist."""
    body = netlist.split(";", 1)[1] if "module" in netlist else netlist
    out = []
    for t, inst, conn in INST_RE.findall(body):
        if t in ("input", "output", "inout", "wire", "reg", "assign", "module", "endmodule"):
            continue
        out.append((t.lstrip("\\"), inst.strip().lstrip("\\"), conn))
    return out


def liberty_areas(lib):
    areas, cell = {}, None
    for line in open(lib, errors="replace"):
        m = re.match(r"\s*cell\s*\(\s*\"?(\w+)\"?\s*\)", line)
        if m:
            cell = m.group(1)
        m = re.match(r"\s*area\s*:\s*([\d.]+)", line)
        if m and cell and cell not in areas:
            areas[cell] = float(m.group(1))
    return areas


def map_module(name, mods, key, cache, abc_text, lib, log):
    """Synthesises and maps one module; stores NAME's netlist and figures under CACHE/KEY.*"""
    d = tempfile.mkdtemp(dir=cache)
    try:
        with open(d + "/m.il", "w") as f:
            f.write(module_il(name, mods))
        with open(d + "/abc.script", "w") as f:
            f.write(abc_text)
        with open(d + "/constr.txt", "w") as f:
            f.write(CONSTR)
        with open(d + "/m.ys", "w") as f:
            f.write(MODULE_YS.format(il="m.il", top=name, mem="mem.il", lib=lib, target=TARGET,
                                     abc="abc.script", net="net.v"))
        r = subprocess.run(["yosys", "-q", "-l", "ylog", "-s", "m.ys"], cwd=d, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            tail = open(d + "/ylog").read()[-2000:] if os.path.exists(d + "/ylog") else r.stderr
            raise RuntimeError("yosys failed on module %s:\n%s" % (name, tail))
        mems = []
        for m in re.finditer(r"cell \$mem_v2 (\S+)(.*?)\n\s*end", open(d + "/mem.il").read(), re.S):
            p = dict(re.findall(r"parameter \\(\w+) (\S+)", m.group(2)))
            num = lambda k: int(p[k].split("'")[-1], 2) if "'" in p[k] else int(p[k])
            mems.append({"name": m.group(1), "bits": num("WIDTH") * num("SIZE"),
                         "kind": "rom" if num("WR_PORTS") == 0 else "ram"})
        os.replace(d + "/net.v", os.path.join(cache, key + ".v"))
        with open(d + "/m.json", "w") as f:
            json.dump({"module": name, "memories": mems}, f, sort_keys=True)
        os.replace(d + "/m.json", os.path.join(cache, key + ".json"))
    finally:
        shutil.rmtree(d, ignore_errors=True)


STA_TCL = """read_liberty {lib}
read_verilog {net}
link_design {top}
create_clock -name clk -period 1000 [get_ports clk_i]
set_input_delay 0 -clock clk [delete_from_list [all_inputs] [get_ports clk_i]]
set_output_delay 0 -clock clk [all_outputs]
set_false_path -from [get_ports rst_ni]
report_checks -path_delay max -format full -digits 4
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cache-dir", default=os.path.join(ROOT, "build", "stdcell_modules"))
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--abc", choices=sorted(ABC), default="nf")
    ap.add_argument("--flat", action="store_true", help="map the top as one flattened netlist (same steps; the reference "
                    "for the hierarchical figures)")
    ap.add_argument("top")
    ap.add_argument("netlist")
    ap.add_argument("files", nargs="*", help="default: the manifest's files of TOP")
    a = ap.parse_args()
    if not shutil.which("yosys"):
        fail("yosys not installed (Debian package yosys)")
    if not shutil.which("sta"):
        fail("OpenSTA (sta) not installed (Debian package opensta)")
    if not os.path.isfile(LIB):
        fail(LIB + " missing (Debian package qflow-tech-osu018)")
    cache = os.path.abspath(a.cache_dir)
    os.makedirs(cache, exist_ok=True)
    # Paths relative to the repository root: the same design text from any checkout.
    files = [os.path.relpath(os.path.abspath(f), ROOT) for f in a.files] or manifest_files(a.top)
    prep = tempfile.mkdtemp(dir=cache)
    try:
        r = subprocess.run(["yosys", "-q", "-p", "read_verilog -sv -Irtl/common -Irtl/generated %s; hierarchy -top %s; "
                            "write_rtlil %s" % (" ".join(files), a.top, prep + "/prep.il")],
                           cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            fail("yosys could not elaborate %s: %s" % (a.top, r.stderr.strip()[-1500:]), 2)
        mods = split(open(prep + "/prep.il").read())
    finally:
        shutil.rmtree(prep, ignore_errors=True)
    if a.top not in mods:
        fail("top %s not found after elaboration" % a.top, 2)
    if a.flat:
        mods[a.top]["inline"] = sorted(mods[a.top]["children"])
    abc_text = ABC[a.abc].format(T=TARGET)
    lib_hash = sha(open(LIB, "rb").read())
    flow_hash = sha(open(os.path.abspath(__file__), "rb").read(), lib_hash, abc_text, CONSTR, TARGET)
    # The netlists of the top, each once: a module and its inlined subtrees are one netlist.
    used, todo = set(), [a.top]
    while todo:
        n = todo.pop()
        if n not in used:
            used.add(n)
            todo.extend(unit(n, mods)[1])

    def key(n):
        flat, boxes = unit(n, mods)
        return sha(flow_hash, n, *[mods[f]["body"] for f in sorted(flat)], *[mods[c]["ports"] for c in sorted(boxes)])[:24]
    keys = {n: key(n) for n in used}
    missing = sorted(n for n in used if not (os.path.exists(os.path.join(cache, keys[n] + ".v")) and
                                             os.path.exists(os.path.join(cache, keys[n] + ".json"))))
    with concurrent.futures.ThreadPoolExecutor(max(1, a.jobs)) as ex:
        for f in [ex.submit(map_module, n, mods, keys[n], cache, abc_text, LIB, None) for n in missing]:
            f.result()
    # The top's netlist: every module's netlist once, in name order.
    nets = {n: open(os.path.join(cache, keys[n] + ".v")).read() for n in used}
    info = {n: json.load(open(os.path.join(cache, keys[n] + ".json"))) for n in used}
    os.makedirs(os.path.dirname(os.path.abspath(a.netlist)), exist_ok=True)
    with open(a.netlist, "w") as f:
        for n in sorted(used):
            f.write(re.sub(r"^/\*.*?\*/\n", "", nets[n], flags=re.S))  # Yosys's banner once per file
    areas = liberty_areas(LIB)
    insts = {n: instances(nets[n]) for n in used}
    memo = {}

    def totals(n):
        """(area, cells, flip-flops, latches, memories, netlist instances) of n with everything under it."""
        if n in memo:
            return memo[n]
        area, cells, ffs, lat, mems, inst_n = 0.0, 0, 0, 0, list(info[n]["memories"]), 1
        for t, inst, _ in insts[n]:
            if t in used:
                ca, cc, cf, cl, cm, ci = totals(t)
                area, cells, ffs, lat, inst_n = area + ca, cells + cc, ffs + cf, lat + cl, inst_n + ci
                mems += [dict(m, name=inst + "." + m["name"]) for m in cm]
            else:
                area += areas[t]
                cells += 1
                ffs += t.startswith("DFF")
                lat += t == "LATCH"
        memo[n] = (area, cells, ffs, lat, mems, inst_n)
        return memo[n]
    area, cells, ffs, lat, mems, inst_n = totals(a.top)
    d = tempfile.mkdtemp(dir=cache)
    try:
        with open(d + "/sta.tcl", "w") as f:
            f.write(STA_TCL.format(lib=LIB, net=os.path.abspath(a.netlist), top=a.top))
        r = subprocess.run(["sta", "-no_init", "-exit", d + "/sta.tcl"], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        sta = r.stdout
        if r.returncode != 0 or "data arrival time" not in sta:
            sys.stderr.write(sta)
            sys.exit(2)
    finally:
        shutil.rmtree(d, ignore_errors=True)

    def register(point):
        """A flip-flop instance u_a/u_b/_12_ is named by its instance path and the net on its Q pin."""
        parts = point.split("/")
        mod, path = a.top, []
        for p in parts[:-1]:
            t = next((t for t, i, _ in insts[mod] if i == p.replace("\\", "")), None)
            if t is None or t not in used:
                return point
            mod, path = t, path + [p]
        for t, i, conn in insts[mod]:
            if i == parts[-1].replace("\\", "") and t.startswith("DFF"):
                q = re.search(r"\.Q\(\\?([^)]*?)\s*\)", conn)
                if q:
                    return ".".join(path + [q.group(1).replace(" ", "")])
        return point.replace("/", ".")
    start = register(re.search(r"^Startpoint: (\S+)", sta, re.M).group(1))
    end = register(re.search(r"^Endpoint: (\S+)", sta, re.M).group(1))
    arrival = float(re.search(r"^\s*([\d.]+)\s+data arrival time", sta, re.M).group(1))
    required = float(re.search(r"^\s*([\d.]+)\s+data required time", sta, re.M).group(1))
    period = arrival + (1000.0 - required)
    print(json.dumps({"top": a.top, "area_um2": round(area, 1), "cells": cells, "flip_flops": ffs, "latches": lat,
                      "memories": mems, "period_ns": round(period, 3), "fmax_mhz": round(1000.0 / period, 1),
                      "path_from": start, "path_to": end, "modules": len(used),
                      "instances": inst_n,
                      "mapped": len(missing), "abc": a.abc, "flat": a.flat}, sort_keys=True))


if __name__ == "__main__":
    main()
