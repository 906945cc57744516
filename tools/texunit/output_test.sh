#!/usr/bin/env bash
# Outputs all or none (docs/robustness.md): a full disk, a missing or unwritable directory, a bad
# argument and SIGINT / SIGTERM leave no partial output, no temporary, no directory the command
# created and no child process; every writer goes through the one checked output path. One ctest
# case each.
# Usage: output_test.sh TEXUNIT SOURCE_DIR CASE FAIL_WRITE_SHIM
set -euo pipefail
tu=$1; src=$2; case=$3; shim=${4:-}
. "$(dirname "$0")/test_lib.sh"  # tmp, fail, expect
# full N PATTERN CMD...: CMD on a disk that is full after N bytes (the LD_PRELOAD shim): exit 2,
# a message naming the file.
full() {
  local n=$1 pat=$2; shift 2
  expect 2 "$pat" env LD_PRELOAD="$shim" TU_FAIL_WRITE_AFTER="$n" "$@"
}
# Nothing in DIR but what `keep` lists: no temporary, no partial file.
no_tmp_left() { ! find "$1" -name '*.tmp*' -o -name '*.hier' | grep -q . || fail "leftover temporaries: $(find "$1" -name '*.tmp*' -o -name '*.hier')"; }
absent() { for p in "$@"; do [ ! -e "$p" ] || fail "left $p ($(ls -la "$p" 2>&1 | head -5))"; done; }
nospc="No space left on device"
case $case in
  full_disk)
    [ -f "$shim" ] || fail "no shim '$shim'"
    # render: the first PNG written (ref.png) is cut at 4 KiB; nothing is left, not the --out directory.
    full 4096 "ref.png: cannot write the file ($nospc)" "$tu" render default --engine ref --out "$tmp/r"
    absent "$tmp/r"
    # The second file of a command (layers.png after ref.png): ref.png is not left either.
    size=$("$tu" render default --engine ref --out "$tmp/ok" 2>/dev/null >/dev/null; stat -c %s "$tmp/ok/ref.png")
    full "$((size + 10))" "layers.png: cannot write the file ($nospc)" "$tu" render default --engine ref --out "$tmp/r2"
    absent "$tmp/r2"
    # Animation frames: frame 1 of 3 fails; no frame is left.
    full "$((size + 10))" "cannot write the file ($nospc)" "$tu" render default --engine ref --frames 3 --out "$tmp/fr"
    absent "$tmp/fr"
    # A full disk reported at close(2) (delayed allocation, NFS): the same.
    expect 2 "ref.png: cannot write the file ($nospc)" env LD_PRELOAD="$shim" TU_FAIL_CLOSE=1 "$tu" render default --engine ref --out "$tmp/rc"
    absent "$tmp/rc"
    pngs=$(cat "$tmp/ok"/*.png | wc -c)  # ref.png and layers.png written, the dump (last) fails
    full "$((pngs + 100))" "d.csv: cannot write the file ($nospc)" "$tu" render default --engine ref --out "$tmp/ok" --dump "$tmp/d.csv"
    absent "$tmp/d.csv"
    full 2000 "c.png: cannot write the file ($nospc)" "$tu" complexity docs/blocks/relief/layers_default.png "$tmp/c.png"
    absent "$tmp/c.png"
    python3 -c "
import zlib, struct
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
raw = b''.join(b'\\x00' + bytes((x * 37 + y * 11) % 256 for x in range(16)) for y in range(16))
open('$tmp/h16.png', 'wb').write(b'\\x89PNG\\r\\n\\x1a\\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 16, 16, 8, 0, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))
"
    full 0 "dm.raw: cannot write the file ($nospc)" "$tu" distance-map "$tmp/h16.png" "$tmp/dm" --depth 4 --scale 0.25
    absent "$tmp/dm.raw" "$tmp/dm.json"
    full 1500 "cannot write the file ($nospc)" "$tu" distance-map "$tmp/h16.png" "$tmp/dm" --depth 4 --scale 0.25 --slices "$tmp/sl"
    absent "$tmp/dm.raw" "$tmp/dm.json" "$tmp/sl"
    full 5000 "v.vec: cannot write the file ($nospc)" "$tu" vectors --block reciprocal --set random --count 1000 --out "$tmp/v.vec"
    absent "$tmp/v.vec"
    full 500 "r.json: cannot write the file ($nospc)" "$tu" report --blocks reciprocal --count 50 --no-yosys --json "$tmp/r.json"
    absent "$tmp/r.json"
    "$tu" report --blocks reciprocal --count 50 --no-yosys --json "$tmp/r.json" >/dev/null 2>&1
    js=$(stat -c %s "$tmp/r.json"); rm "$tmp/r.json"  # the JSON written, the Markdown (second) fails
    full "$((js + 10))" "m.md: cannot write the file ($nospc)" "$tu" report --blocks reciprocal --count 50 --no-yosys --json "$tmp/r.json" --markdown "$tmp/m.md"
    absent "$tmp/r.json" "$tmp/m.md"
    # Plots: the first data file fails; no plot file, no plot directory.
    full 100 "cannot write the file ($nospc)" "$tu" report --blocks reciprocal --count 50 --no-yosys --plots "$tmp/pl" --json "$tmp/r.json"
    absent "$tmp/pl" "$tmp/r.json"
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --json --shard 0/2 >"$tmp/s0.json"
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --json --shard 1/2 >"$tmp/s1.json"
    full 0 "mg.json: cannot write the file ($nospc)" "$tu" merge "$tmp/s0.json" "$tmp/s1.json" --json "$tmp/mg.json"
    absent "$tmp/mg.json"
    # Standard output redirected to a file on a full disk: exit 2, not 0 (stdio writes it, past the
    # shim: a file-size limit of 0 fails every write to a file).
    set +e
    (ulimit -f 0; trap '' XFSZ; exec "$tu" merge "$tmp/s0.json" "$tmp/s1.json" 2>&1 >"$tmp/so.json") | cat >"$tmp/err"
    rc=${PIPESTATUS[0]}
    set -e
    [ "$rc" = 2 ] || fail "merge > file on a full disk: exit $rc"
    grep -q "standard output: cannot write (File too large)" "$tmp/err" || fail "stdout message: $(cat "$tmp/err")"
    rm -f "$tmp/so.json"
    full 0 "a.sv: cannot write the file ($nospc)" "$tu" plan default --out "$tmp/a.sv"
    absent "$tmp/a.sv"
    # gen-rtl into an empty root: every generated file or none (no rtl/ directory left).
    mkdir "$tmp/root"
    full 20000 "cannot write the file ($nospc)" "$tu" gen-rtl --root "$tmp/root"
    [ -z "$(ls -A "$tmp/root")" ] || fail "gen-rtl left $(find "$tmp/root" | head)"
    "$tu" gen-rtl --root "$tmp/root" 2>/dev/null
    "$tu" gen-rtl --root "$tmp/root" --check || fail "gen-rtl after the failure is not whole"
    # The waveform is written by Verilator's own stdio (not the shim's write): a file-size limit
    # (a full disk for that file) cuts it; the check after close refuses it.
    set +e
    "$tu" vectors --block reciprocal --set random --count 5000 --out "$tmp/r.vec" 2>/dev/null  # a 0.6 MB waveform
    (ulimit -f 100; trap '' XFSZ; exec "$tu" cosim --block reciprocal --vectors "$tmp/r.vec" --fst "$tmp/w.fst") >/dev/null 2>"$tmp/err"
    rc=$?
    set -e
    [ "$rc" = 2 ] || fail "cosim --fst on a full disk: exit $rc ($(head -c 300 "$tmp/err"))"
    grep -q "w.fst: cannot write the file" "$tmp/err" || fail "cosim --fst message: $(cat "$tmp/err")"
    absent "$tmp/w.fst"
    # The same command with room writes a waveform the check accepts.
    "$tu" cosim --block reciprocal --vectors "$tmp/r.vec" --fst "$tmp/w.fst" >/dev/null
    [ -s "$tmp/w.fst" ] || fail "no waveform"
    rm -rf "$tmp/ok" "$tmp/w.fst" "$tmp/r.vec" "$tmp/root" "$tmp/s0.json" "$tmp/s1.json" "$tmp/h16.png"
    no_tmp_left "$tmp"
    ;;
  missing_dir)
    # A target in a missing directory, a directory as the target, an unwritable directory:
    # refused before the work (exit 2, the file named), nothing written.
    expect 2 "/nonexistent/r.json: cannot write the file (directory '/nonexistent' does not exist)" \
      "$tu" report --blocks reciprocal --count 50 --no-yosys --json /nonexistent/r.json
    expect 2 "/nonexistent/r.md: cannot write the file" "$tu" report --blocks reciprocal --count 50 --no-yosys --markdown /nonexistent/r.md
    expect 2 "cannot write the file (it is a directory)" "$tu" report --blocks reciprocal --count 50 --no-yosys --json "$tmp"
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --json --shard 0/2 >"$tmp/s0.json"
    "$tu" cosim --block reciprocal --vectors vectors/golden/reciprocal.vec --json --shard 1/2 >"$tmp/s1.json"
    expect 2 "$tmp/missing/m.json: cannot write the file (directory '$tmp/missing' does not exist)" \
      "$tu" merge "$tmp/s0.json" "$tmp/s1.json" --json "$tmp/missing/m.json"
    if [ "$(id -u)" != 0 ]; then  # root writes anywhere: the case needs an ordinary user (CI)
      mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
      expect 2 "is not writable" "$tu" report --blocks reciprocal --count 50 --no-yosys --json "$tmp/ro/r.json"
      expect 2 "is not writable" "$tu" render default --engine ref --out "$tmp/ro/x"
      absent "$tmp/ro/r.json" "$tmp/ro/x"
    fi
    absent "$tmp/missing"
    no_tmp_left "$tmp"
    ;;
  validate_first)
    # Every argument and target checked before the first side effect.
    expect 2 "nonexistent.json" "$tu" filter-compare /nonexistent.json --plot "$tmp/NEW"
    absent "$tmp/NEW"
    expect 2 "shard 5/10 of 3 vectors is empty" "$tu" vectors --block reciprocal --set random --count 3 --shard 5/10 --out "$tmp/v.vec"
    absent "$tmp/v.vec"
    # stdcell: the unknown second top refuses the command before the first is synthesised (the
    # flow would run minutes and fill the cache): no cache file, no netlist directory.
    expect 2 "tu_nosuch" "$tu" stdcell tu_bc1_decode tu_nosuch --force --cache "$tmp/c.json" --netlists "$tmp/net"
    absent "$tmp/c.json" "$tmp/net"
    no_tmp_left "$tmp"
    ;;
  signals)
    # A real SIGTERM / SIGINT to a running command: exit 128 + signal, no temporary, no directory
    # the command created, no child left. Job control on: a background job of a script has
    # SIGINT ignored otherwise (and texunit keeps an ignored signal ignored, as nohup expects).
    set -m
    # wait_for GLOB SECONDS: until a file matching GLOB exists (the command is writing).
    wait_for() {
      for _ in $(seq 1 $(($2 * 10))); do
        compgen -G "$1" >/dev/null && return 0
        kill -0 "$pid" 2>/dev/null || fail "the command ended before the signal"
        sleep 0.1
      done
      fail "no $1 after $2 s"
    }
    stop() {  # stop SIGNAL WANT_RC
      kill -"$1" "$pid"
      set +e
      wait "$pid"
      local rc=$?
      set -e
      [ "$rc" = "$2" ] || fail "SIG$1: exit $rc, expected $2"
    }
    "$tu" render default --engine ref --frames 2000 --out "$tmp/anim" >/dev/null 2>"$tmp/err" &
    pid=$!
    wait_for "$tmp/anim/.ref_0001.png.texunit-*.tmp" 120
    stop TERM 143
    absent "$tmp/anim"
    "$tu" render default --engine ref --frames 2000 --out "$tmp/anim" >/dev/null 2>"$tmp/err" &
    pid=$!
    wait_for "$tmp/anim/.ref_0001.png.texunit-*.tmp" 120
    stop INT 130
    absent "$tmp/anim"
    "$tu" vectors --block ewa --set random --count 2000000 --out "$tmp/e.vec" >/dev/null 2>"$tmp/err" &
    pid=$!
    wait_for "$tmp/.e.vec.texunit-*.tmp" 300
    stop INT 130
    absent "$tmp/e.vec"
    no_tmp_left "$tmp"
    # A child (the standard-cell flow, here a stand-in that sleeps) is killed and reaped.
    mkdir -p "$tmp/root/scripts"
    ln -s "$src/rtl" "$tmp/root/rtl"
    printf '#!/bin/sh\necho $$ >"%s"\nexec sleep 300\n' "$tmp/child.pid" >"$tmp/root/scripts/stdcell_flow.sh"
    chmod +x "$tmp/root/scripts/stdcell_flow.sh"
    "$tu" stdcell tu_reciprocal --root "$tmp/root" --force --cache "$tmp/c.json" --netlists "$tmp/net" >/dev/null 2>"$tmp/err" &
    pid=$!
    wait_for "$tmp/child.pid" 60
    sleep 0.2
    stop TERM 143
    child=$(cat "$tmp/child.pid")
    sleep 0.5
    # Dead: gone, or a zombie of the process that inherited it (it writes nothing any more).
    st=$(ps -o stat= -p "$child" 2>/dev/null || true)
    [ -z "$st" ] || [ "${st#Z}" != "$st" ] || { kill "$child"; fail "the flow's child $child outlived texunit ($st)"; }
    absent "$tmp/c.json"
    ;;
  writers_grep)
    # Every file of the CLI and of the library writers is written through texunit/output.hpp:
    # no other way to create a file (std::ofstream, stb's file writers, fopen for writing) and
    # no other way to start a child (std::system, popen: a signal could not kill it).
    hits=$(grep -rnE 'std::ofstream|ofstream[ (]|stbi_write_(png|bmp|tga|jpg|hdr)[ (]|fopen\([^)]*"[wa]|std::system\(|popen\(|[^_]system\(' \
             tools/texunit cmodel/src cmodel/blocks cmodel/include vectors --include='*.cpp' --include='*.hpp' --include='*.h' \
           | grep -v '^cmodel/src/output.cpp:' || true)
    [ -z "$hits" ] || fail "writers outside the checked output path:
$hits"
    ;;
  *) fail "unknown case" ;;
esac
echo "ok ($case)"
