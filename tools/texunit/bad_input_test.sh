#!/usr/bin/env bash
# Bad input through the CLI (docs/robustness.md): each case exits with the documented code, says
# what is wrong (file and line or field), and leaves no partial output. One ctest case each.
# Usage: bad_input_test.sh TEXUNIT SOURCE_DIR CASE
set -euo pipefail
tu=$1; src=$2; case=$3
. "$(dirname "$0")/test_lib.sh"  # tmp, fail, expect
no_tmp_left() { ! find "$1" -name '*.tmp' | grep -q . || fail "leftover temporary files: $(find "$1" -name '*.tmp')"; }
header='# texunit-vectors 1
# block: reciprocal
# set: golden
# seed: 1
# fields: q:in:s24.16 mant:out:u25.24 shift:out:u5.0 flag:out:u1.0 ref:ref:f64'
case $case in
  usage_exit_2)
    # One exit code, 2, for every usage error (CLI11's own codes are 105, 106, ...).
    expect 2 "dilate" "$tu" complexity in.png out.png --dilate abc
    expect 2 "dilate" "$tu" complexity in.png out.png --dilate 4
    expect 2 "out" "$tu" vectors --block reciprocal
    expect 2 "vectors" "$tu" cosim --block reciprocal --vectors "$tmp/none.vec"
    expect 2 "cord-unroll" "$tu" sysmodel default --cord-unroll 0
    expect 2 "cord-unroll" "$tu" sysmodel default --cord-unroll abc
    expect 2 "filter: cubic not in" "$tu" render default --out "$tmp/o" --filter cubic
    expect 2 "gamma" "$tu" complexity in.png out.png --gamma nan
    "$tu" --help >/dev/null || fail "--help must succeed"
    ;;
  distance_map)
    # Good run: raw + header + slices, memory printed; bad images, sizes and options: exit 2,
    # the file or option named, nothing written.
    python3 -c "
import zlib, struct
def png(w, h, rows):
    raw = b''.join(b'\\x00' + bytes(r) for r in rows)
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    return b'\\x89PNG\\r\\n\\x1a\\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 0, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
open('$tmp/h16.png', 'wb').write(png(16, 16, [[(x * 37 + y * 11) % 256 for x in range(16)] for y in range(16)]))
open('$tmp/h12.png', 'wb').write(png(12, 12, [[0] * 12] * 12))
"
    "$tu" distance-map "$tmp/h16.png" "$tmp/ok" --depth 4 --scale 0.25 --slices "$tmp/sl" >"$tmp/out" 2>"$tmp/err" ||
      fail "distance-map failed: $(cat "$tmp/err")"
    grep -q "memory 1024 bytes" "$tmp/out" || fail "memory not printed: $(cat "$tmp/out")"
    [ "$(stat -c %s "$tmp/ok.raw")" = 1024 ] || fail "raw size"
    grep -q '"layers": 4' "$tmp/ok.json" || fail "header"
    [ -f "$tmp/sl/layer_003.png" ] || fail "slices"
    expect 2 "h12.png: .*power of two" "$tu" distance-map "$tmp/h12.png" "$tmp/bad" --depth 4 --scale 0.5
    expect 2 "scale" "$tu" distance-map "$tmp/h16.png" "$tmp/bad" --depth 4 --scale 0.01
    expect 2 "depth" "$tu" distance-map "$tmp/h16.png" "$tmp/bad" --depth 0
    expect 2 "depth" "$tu" distance-map "$tmp/h16.png" "$tmp/bad" --depth 256
    printf 'not a png' >"$tmp/junk.png"
    expect 2 "junk.png" "$tu" distance-map "$tmp/junk.png" "$tmp/bad" --depth 4
    expect 2 "missing.png" "$tu" distance-map "$tmp/missing.png" "$tmp/bad" --depth 4
    [ ! -e "$tmp/bad.raw" ] && [ ! -e "$tmp/bad.json" ] || fail "partial output"
    no_tmp_left "$tmp"
    ;;
  stall_nan)
    "$tu" vectors --block reciprocal --set golden --out "$tmp/r.vec" 2>/dev/null
    expect 2 "stall-prob" "$tu" cosim --block reciprocal --vectors "$tmp/r.vec" --stall-prob nan
    expect 2 "stall-prob" "$tu" cosim --block reciprocal --vectors "$tmp/r.vec" --stall-prob inf
    ;;
  negative_seed)
    expect 2 "seed" "$tu" vectors --block reciprocal --set random --count 5 --seed -3 --out "$tmp/r.vec"
    [ ! -e "$tmp/r.vec" ] || fail "wrote a file"
    expect 2 "seed" "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --seed -1
    printf '%s\n' "$header" | sed 's/# seed: 1/# seed: -3/' >"$tmp/neg.vec"
    echo "0000a3 0155555 05 0 3fd5555555555555" >>"$tmp/neg.vec"
    expect 2 "neg.vec:4: seed '-3' is not an unsigned integer" "$tu" cosim --block reciprocal --vectors "$tmp/neg.vec"
    ;;
  count_bound)
    expect 2 "count" "$tu" vectors --block reciprocal --set random --count 4294967296 --out "$tmp/r.vec"
    expect 2 "count" "$tu" vectors --block reciprocal --set random --count 4194305 --out "$tmp/r.vec"
    expect 2 "count" "$tu" demo --count 0
    [ ! -e "$tmp/r.vec" ] || fail "wrote a file"
    ;;
  header_only_vectors)
    printf '%s\n' "$header" >"$tmp/h.vec"
    expect 2 "h.vec: no vectors" "$tu" cosim --block reciprocal --vectors "$tmp/h.vec"
    ;;
  fst_missing_dir)
    expect 2 "$tmp/missing/w.fst: cannot write the file (directory '$tmp/missing' does not exist)" \
      "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --fst "$tmp/missing/w.fst"
    # A writable place gets the waveform, under its own name, and no temporary.
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --fst "$tmp/w.fst" >/dev/null
    [ -s "$tmp/w.fst" ] || fail "no waveform"
    no_tmp_left "$tmp"
    ;;
  partial_output)
    # --dump into a missing directory: nothing written (no ref.png), the --out directory not left.
    expect 2 "$tmp/missing/d.csv: cannot write the file (directory '$tmp/missing' does not exist)" \
      "$tu" render default --engine ref --out "$tmp/o" --dump "$tmp/missing/d.csv"
    [ ! -e "$tmp/o" ] || fail "left $(ls -R "$tmp/o")"
    # An unwritable layers.png (a directory of that name): no ref.png.
    mkdir -p "$tmp/o2/layers.png"
    expect 2 "layers.png: cannot write the file (it is a directory)" "$tu" render default --engine ref --out "$tmp/o2"
    [ ! -e "$tmp/o2/ref.png" ] || fail "left ref.png"
    # --out / --dump that is a directory: a worded error, no X.tmp.
    mkdir -p "$tmp/o3/ref.png"
    expect 2 "ref.png: cannot write the file (it is a directory)" "$tu" render default --engine ref --out "$tmp/o3"
    expect 2 "cannot write the file (it is a directory)" "$tu" render default --engine ref --out "$tmp/o4" --dump "$tmp"
    [ ! -e "$tmp/o4" ] || fail "left the --out directory"
    expect 2 "cannot write the file (it is a directory)" "$tu" vectors --block reciprocal --set golden --out "$tmp"
    # plan: a failing --out-full leaves no --out file.
    expect 2 "does not exist" "$tu" plan default --out "$tmp/a.sv" --out-full "$tmp/missing/b.sv"
    [ ! -e "$tmp/a.sv" ] || fail "plan left --out"
    expect 2 "does not exist" "$tu" complexity docs/blocks/relief/layers_default.png "$tmp/missing/c.png"
    no_tmp_left "$tmp"
    ;;
  scene_errors)
    # A number outside double's range: file and line.
    sed 's/"fovy_deg": 60/"fovy_deg": 1e400/' docs/scenes/ui_quad.json >"$tmp/big.json"
    grep -q 1e400 "$tmp/big.json" || fail "edit"
    expect 2 "big.json:[0-9]*: number 1e400 is outside double's range" "$tu" render "$tmp/big.json" --out "$tmp/o"
    # Camera up along the view: rejected at load by both engines, naming the field.
    python3 - "$tmp" <<'PY'
import json, sys
d = json.load(open("docs/scenes/ui_quad.json"))
c = d["camera"]
c["up"] = [l - p for l, p in zip(c["look_at"], c["position"])]
json.dump(d, open(sys.argv[1] + "/up.json", "w"))
d["camera"]["up"] = [0, 0, 0]
json.dump(d, open(sys.argv[1] + "/up0.json", "w"))
PY
    for e in ref cmodel; do
      expect 2 "up.json: /camera/up: is parallel to the view direction" "$tu" render "$tmp/up.json" --engine $e --out "$tmp/o"
      expect 2 "up0.json: /camera/up: is the zero vector" "$tu" render "$tmp/up0.json" --engine $e --out "$tmp/o"
    done
    # Duplicate keys; a NUL byte (\u0000 in a key) shown escaped, the message not cut.
    sed 's/"fovy_deg": 60/"fovy_deg": 60, "fovy_deg": 61/' docs/scenes/ui_quad.json >"$tmp/dup.json"
    expect 2 "dup.json: /camera/fovy_deg: duplicate key" "$tu" render "$tmp/dup.json" --out "$tmp/o"
    sed 's/"fovy_deg": 60/"fovy_deg": 60, "a\\u0000b": 1/' docs/scenes/ui_quad.json >"$tmp/nul.json"
    expect 2 'nul.json: /camera/a\\x00b: unknown field' "$tu" render "$tmp/nul.json" --out "$tmp/o"
    # Huge uv: a range error naming the field.
    python3 - "$tmp" <<'PY'
import json, sys
d = json.load(open("docs/scenes/ui_quad.json"))
d["objects"][0]["uv"][1] = [1e18, 0]
json.dump(d, open(sys.argv[1] + "/uv.json", "w"))
PY
    expect 2 "uv.json: /objects/0/uv/1/0: value 1e+18 is out of range" "$tu" render "$tmp/uv.json" --out "$tmp/o"
    # An unknown clip-volume variant names the field; the RTL unit's walk has one clip volume (mm_p1).
    sed 's/"filter": "ewa"/"filter": "ewa", "clip": "p9"/' docs/scenes/ui_quad.json >"$tmp/clip.json"
    grep -q '"clip": "p9"' "$tmp/clip.json" || fail "edit"
    expect 2 "clip.json: /materials/panel/clip" "$tu" render "$tmp/clip.json" --out "$tmp/o"
    expect 2 "/materials/panel/clip: mm_p3, but the unit's EWA walk has the clip volume mm_p1" "$tu" render docs/scenes/ui_quad.json --engine rtl --clip mm_p3 --out "$tmp/o"
    [ ! -e "$tmp/o" ] || fail "left output"
    # af_visibility is a boolean.
    sed 's/"af_visibility": true/"af_visibility": "yes"/' docs/scenes/af_visibility.json >"$tmp/afv.json"
    grep -q '"af_visibility": "yes"' "$tmp/afv.json" || fail "edit"
    expect 2 "afv.json: /materials/.*/relief/af_visibility: expected true or false" "$tu" render "$tmp/afv.json" --out "$tmp/o"
    [ ! -e "$tmp/o" ] || fail "left output"
    ;;
  degenerate_triangle)
    # A zero-area triangle is dropped with a warning naming the object; the render goes on.
    python3 - "$tmp" <<'PY'
import json, sys
d = json.load(open("docs/scenes/ui_quad.json"))
o = dict(d["objects"][0]); o["name"] = "sliver"; o["type"] = "triangle"
v = o["vertices"]; o["vertices"] = [v[0], v[1], v[1]]; o["uv"] = o["uv"][:3]
d["objects"].append(o)
json.dump(d, open(sys.argv[1] + "/deg.json", "w"))
PY
    for e in ref cmodel; do
      expect 0 "warning: .*deg.json: object 'sliver' (/objects/1): triangle 'sliver' has zero area" \
        "$tu" render "$tmp/deg.json" --engine $e --out "$tmp/o"
      [ -s "$tmp/o/$e.png" ] || fail "no image"
    done
    ;;
  plan_any_directory)
    # The report table is built in: plan works from any directory.
    (cd "$tmp" && "$tu" plan default --json >"$tmp/p.json") || fail "plan failed outside the repository"
    python3 -c "import json; d=json.load(open('$tmp/p.json')); assert d['report_table'] == 'docs/report/report.json'" || fail "report_table"
    expect 2 "x.json: cannot read the report table" "$tu" plan default --report "$tmp/x.json"
    ;;
  progress_not_in_logs)
    "$tu" render docs/scenes/ui_quad.json --engine cmodel --out "$tmp/o" 2>"$tmp/err" >/dev/null
    ! grep -q $'\r' "$tmp/err" || fail "progress bar in a log: $(cat -A "$tmp/err" | head -3)"
    ;;
  numeric_options)
    # Every numeric option: finite, in range, in decimal, named in the message (one check for all
    # options, tools/texunit/cli_checks.hpp check_values); nothing written.
    expect 2 "dt: 'nan' is not a finite number" "$tu" render docs/scenes/procedural.json --frames 2 --dt nan --out "$tmp/o"
    expect 2 "os-stall-prob: 'nan' is not a finite number" "$tu" render default --pipeline object-space --engine rtl --os-stall-prob nan --out "$tmp/o"
    expect 2 "os-spacing: 'nan' is not a finite number" "$tu" render default --pipeline object-space --os-spacing nan --out "$tmp/o"
    expect 2 "os-spacing: 'nan' is not a finite number" "$tu" objspace-compare default --os-spacing nan
    expect 2 "max-cycles: 'nan' is not a FINITE in \[0 - 1e+18\]" "$tu" plan default --max-cycles nan
    expect 2 "max-cycles: 'inf' is not a FINITE in \[0 - 1e+18\]" "$tu" plan default --max-cycles inf
    expect 2 "afvis-heights: '-nan' is not a FINITE" "$tu" relief-quality --afvis default --afvis-heights 1,-nan
    expect 2 "seed: '18446744073709551616' is out of range" "$tu" vectors --block reciprocal --set random --count 5 --seed 18446744073709551616 --out "$tmp/r.vec"
    expect 2 "seed: '99999999999999999999999' is out of range" "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --seed 99999999999999999999999
    expect 2 "count: '010' is not a non-negative integer in decimal" "$tu" vectors --block reciprocal --set random --count 010 --out "$tmp/r.vec"
    expect 2 "threads: '0x4' is not an integer in decimal" "$tu" vectors --block reciprocal --set golden --threads 0x4 --out "$tmp/r.vec"
    expect 2 "cache-size: " "$tu" sysmodel default --cache-size -1
    expect 2 "frames: " "$tu" render default --frames 1e3 --out "$tmp/o"
    [ ! -e "$tmp/o" ] && [ ! -e "$tmp/r.vec" ] || fail "wrote output"
    # The largest seed is still a seed.
    "$tu" vectors --block reciprocal --set random --count 5 --seed 18446744073709551615 --out "$tmp/r.vec" 2>/dev/null ||
      fail "refused seed 2^64 - 1"
    grep -q "^# seed: 18446744073709551615$" "$tmp/r.vec" || fail "seed header"
    ;;
  merge_identity)
    # Each shard carries what identifies its run; merge refuses a mismatch, a gap, a repeat or a
    # malformed field, naming the file and the field (exit 2, nothing written).
    "$tu" vectors --block reciprocal --set random --count 600 --seed 5 --out "$tmp/a.vec" 2>/dev/null
    "$tu" vectors --block reciprocal --set random --count 600 --seed 6 --out "$tmp/b.vec" 2>/dev/null
    for k in 0 1; do
      "$tu" cosim --block reciprocal --vectors "$tmp/a.vec" --shard $k/2 --json >"$tmp/a$k.json"
      "$tu" cosim --block reciprocal --vectors "$tmp/b.vec" --shard $k/2 --json >"$tmp/b$k.json"
      "$tu" vectors --block reciprocal --set random --count 600 --seed 5 --shard $k/2 --out "$tmp/v5_$k.vec" 2>/dev/null
      "$tu" vectors --block reciprocal --set random --count 600 --seed 6 --shard $k/2 --out "$tmp/v6_$k.vec" 2>/dev/null
      "$tu" cosim --block reciprocal --vectors "$tmp/v5_$k.vec" --json >"$tmp/f5_$k.json"
      "$tu" cosim --block reciprocal --vectors "$tmp/v6_$k.vec" --json >"$tmp/f6_$k.json"
    done
    grep -q '"shard": "1/2", "set": "random", "seed": 5, "first_vector": 300, "rtl": "", "file_vectors": 600, "file_hash": "' "$tmp/a1.json" ||
      fail "no identity in a cosim shard: $(cat "$tmp/a1.json")"
    "$tu" merge "$tmp"/a{0,1}.json --json "$tmp/ok.json" || fail "merge of one run's shards"
    expect 2 "b1.json: shard 1/2 is of another run: seed 6, shard 0 (.*a0.json) has 5" "$tu" merge "$tmp"/a0.json "$tmp"/b1.json --json "$tmp/m.json"
    expect 2 "f6_1.json: shard 1/2 is of another run: seed 6" "$tu" merge "$tmp"/f5_0.json "$tmp"/f6_1.json --json "$tmp/m.json"
    expect 2 "a1.json: shard 1/2 is of another run: file_hash '[0-9a-f]*', shard 0 (.*f5_0.json) has ''" "$tu" merge "$tmp"/f5_0.json "$tmp"/a1.json --json "$tmp/m.json"
    # Hand-edited shard 1: every field is read with its type, a count is a non-negative integer.
    refused() {  # refused NAME FROM TO PATTERN: shard 1 with FROM replaced by TO, merged with shard 0
      python3 -c "import sys; t = open('$tmp/a1.json').read(); assert sys.argv[2] in t; open('$tmp/' + sys.argv[1], 'w').write(t.replace(sys.argv[2], sys.argv[3]))" "$1" "$2" "$3"
      expect 2 "$1: $4" "$tu" merge "$tmp"/a0.json "$tmp/$1" --json "$tmp/m.json"
    }
    refused neg.json '"vectors": 300' '"vectors": -5' '"vectors": expected a non-negative integer, not -5'
    refused mis.json '"mismatches": 0' '"mismatches": -1' '"mismatches": expected a non-negative integer, not -1'
    refused frac.json '"vectors": 300' '"vectors": 1.7' '"vectors": expected a non-negative integer, not 1.7'
    refused str.json '"vectors": 300' '"vectors": "300"' '"vectors": expected a non-negative integer, not "300"'
    refused err.json '"max_abs_err": ' '"max_abs_err": "x", "was": ' '"max_abs_err": expected a number, not "x"'
    refused dup.json '"vectors": 300' '"vectors": 300, "vectors": 600' 'key "vectors" appears twice in one object'
    refused sh.json '"shard": "1/2"' '"shard": "7/3"' "\"shard\": shard '7/3': need 0 <= K < N"
    refused gap.json '"first_vector": 300' '"first_vector": 301' "shard 1/2 starts at vector 301, the shards before it end at 300 (a gap or an overlap)"
    refused noid.json ', "set": "random"' '' 'no "set"'
    # Report shards: element 0 is the identity; a missing shard, another --count, a malformed row.
    for k in 0 1 2; do
      "$tu" report --blocks reciprocal,persp,ellipse --count 50 --no-yosys --shard $k/3 --json "$tmp/r$k.json" >/dev/null 2>&1
    done
    "$tu" report --blocks reciprocal,persp,ellipse --count 60 --no-yosys --shard 1/3 --json "$tmp/c1.json" >/dev/null 2>&1
    head -2 "$tmp/r1.json" | grep -q '{"blocks":\["reciprocal","persp","ellipse"\],"count":50,"report_shard":"1/3"' ||
      fail "no identity in a report shard: $(head -2 "$tmp/r1.json")"
    "$tu" merge "$tmp"/r{0,1,2}.json --json "$tmp/ok.json" >/dev/null 2>&1 || fail "merge of one report's shards"
    expect 2 "report shards 1 of 3 are missing" "$tu" merge "$tmp"/r{0,2}.json --json "$tmp/m.json"
    expect 2 'c1.json: shard 1/3 is of another run: .*"count":60' "$tu" merge "$tmp"/r0.json "$tmp"/c1.json "$tmp"/r2.json --json "$tmp/m.json"
    expect 2 "r0.json: shard 0/3 given twice" "$tu" merge "$tmp"/r{0,0,1,2}.json --json "$tmp/m.json"
    python3 -c "
t = open('$tmp/r1.json').read()
open('$tmp/rx.json', 'w').write(t.replace('\"max_abs_err\": ', '\"max_abs_err\": \"x\", \"was\": ', 1))"
    expect 2 'rx.json: row 1: "max_abs_err": expected a number, not "x"' "$tu" merge "$tmp"/r0.json "$tmp"/rx.json "$tmp"/r2.json --json "$tmp/m.json"
    [ ! -e "$tmp/m.json" ] || fail "merge wrote a partial result"
    ;;
  messages_name_field)
    # Each message names the file and the field (or the path and what it is).
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --shard 0/2 --json >"$tmp/s0.json"
    sed 's/"hung": false/"hung": "no"/' "$tmp/s0.json" >"$tmp/t.json"
    expect 2 't.json: "hung": expected true or false, not "no"' "$tu" merge "$tmp/t.json"
    ! grep -q "json.exception" "$tmp/err" || fail "nlohmann's message: $(cat "$tmp/err")"
    # A stdcell cache entry of the current hash without area_um2.
    key=$("$tu" rtl-files tu_reciprocal --key stdcell)
    printf '{"tu_reciprocal": {"hash": "%s", "period_ns": 5}}\n' "$key" >"$tmp/sc.json"
    expect 2 "sc.json: /tu_reciprocal/area_um2: missing" "$tu" report --blocks reciprocal --count 50 --no-yosys --stdcell-cache "$tmp/sc.json" --json "$tmp/r.json"
    [ ! -e "$tmp/r.json" ] || fail "report wrote a partial result"
    # A directory, a FIFO or a device as a texture; a directory as the scene.
    mkdir -p "$tmp/dir.png"; mkfifo "$tmp/fifo.png"
    for png in "$tmp/dir.png" "$tmp/fifo.png" /dev/zero; do
      sed "s|\"builtin\": \"checkerboard\"|\"png\": \"$png\"|" docs/scenes/ui_quad.json >"$tmp/tex.json"
      grep -q "\"png\": \"$png\"" "$tmp/tex.json" || fail "edit"
      case $png in *dir.png) what="is a directory, not a PNG file" ;; *) what="is not a regular file" ;; esac
      expect 2 "tex.json: /textures/.*/png: '$png' $what" timeout 20 "$tu" render "$tmp/tex.json" --out "$tmp/o"
    done
    expect 2 "$tmp: is a directory, not a scene file" "$tu" render "$tmp" --out "$tmp/o"
    [ ! -e "$tmp/o" ] || fail "left output"
    ;;
  silent_acceptance)
    # What was accepted silently and is now refused (exit 2), naming the option or field.
    expect 2 "RTL 'perlin3d_serial' runs block 'perlin3d' vectors, not block 'bc1_decode' (--rtl)" \
      "$tu" cosim --block bc1_decode --vectors vectors/golden/bc1_decode.vec --rtl perlin3d_serial
    expect 2 "dump $tmp/o/ref.png: the render writes its image" "$tu" render default --engine ref --out "$tmp/o" --dump "$tmp/o/ref.png"
    expect 2 "dump $tmp/o/../o/layers.png: the render writes its image" "$tu" render default --engine ref --out "$tmp/o" --dump "$tmp/o/../o/layers.png"
    [ ! -e "$tmp/o" ] || fail "left the --out directory"
    sed 's/"filter": "ewa"/"filter": "trilinear"/' docs/scenes/af_visibility.json >"$tmp/afv.json"
    grep -q '"filter": "trilinear"' "$tmp/afv.json" || fail "edit"
    for e in ref cmodel rtl; do
      expect 2 "afv.json: /materials/.*/relief/af_visibility: needs filter ewa" "$tu" render "$tmp/afv.json" --engine $e --out "$tmp/o"
    done
    expect 2 "direction-step requires --refined" "$tu" distance-map docs/blocks/relief/layers_default.png "$tmp/d" --depth 4 --direction-step 10
    expect 2 "stdcell-cache: File does not exist: $tmp/none.json" "$tu" report --blocks reciprocal --count 50 --no-yosys --stdcell-cache "$tmp/none.json"
    expect 2 "out: empty value" "$tu" render default --out ""
    expect 2 "OUT $tmp/dd/: a base name" "$tu" distance-map docs/blocks/relief/layers_default.png "$tmp/dd/" --depth 4
    [ ! -e "$tmp/dd/.raw" ] && [ ! -e "$tmp/dd/.json" ] || fail "wrote DIR/.raw"
    # Vector files: a set the block does not have; a NaN reference where the block's is finite.
    sed 's/^# set: golden/# set: bogus/' vectors/golden/reciprocal.vec >"$tmp/set.vec"
    expect 2 "set.vec: set 'bogus' is not a set of block 'reciprocal' (golden, stiff, random)" "$tu" cosim --block reciprocal --vectors "$tmp/set.vec"
    awk '!/^#/ && !done { $NF = "7ff8000000000000"; done = 1 } { print }' vectors/golden/reciprocal.vec >"$tmp/nan.vec"
    expect 2 "nan.vec: vector 0: ref field 'ref' is nan, the block's float reference gives" "$tu" cosim --block reciprocal --vectors "$tmp/nan.vec"
    # The golden set's own non-finite references (a reciprocal of 0 is +inf) still pass.
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec >/dev/null || fail "golden set refused"
    # --frames / --dt: the last frame's time stays in the scene format's |t| <= 1e6.
    expect 2 "frames 3 --dt 600000: material '.*' reaches time 1.2e+06 in the last frame" "$tu" render docs/scenes/procedural.json --frames 3 --dt 600000 --out "$tmp/o"
    [ ! -e "$tmp/o" ] || fail "left output"
    ;;
  *) fail "unknown case" ;;
esac
echo "ok ($case)"
