#!/usr/bin/env bash
# What does a cold build of a co-simulation model cost, with and without FST tracing compiled in?
# For each model: Verilator with the configured build's exact arguments (verilator_args.txt), once
# with --trace-fst and once without, then every generated C++ file compiled as CMake compiles it
# (Release -O3; the "slow" files -O0, testbench/cosim/CMakeLists.txt), no ccache; CPU seconds
# (user + system) per step summed, 2 compiles at a time (docs/performance.md §5).
# Usage: scripts/verilator_build_cost.sh [-j N] MODEL...   e.g. Vtu_ellipse Vtu_texture_unit_bil
#        (needs a configured build/default: cmake --preset default)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=2
if [ "${1:-}" = -j ]; then jobs=$2; shift 2; fi
[ $# -gt 0 ] || { echo "usage: $0 [-j N] MODEL... (e.g. Vtu_ellipse)" >&2; exit 2; }
dir=build/default/testbench/cosim/CMakeFiles/tu_cosim.dir
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
vinc=/usr/share/verilator/include
cpu() { awk '{u += $1; s += $2} END {printf "%.1f", u + s}' "$@"; }
printf "%-32s %-8s %8s %8s %8s %8s %6s\n" model tracing verilate compile "(fast" "slow)" files
for m in "$@"; do
  args_file=$dir/$m.dir/verilator_args.txt
  [ -f "$args_file" ] || { echo "$args_file: missing (configure build/default first)" >&2; exit 2; }
  mapfile -t args < <(tr ';' '\n' <"$args_file")
  for mode in trace notrace; do
    out=$work/$m.$mode
    mkdir -p "$out"
    a=()
    skip=0
    for x in "${args[@]:1}"; do  # [0] is verilator_bin
      if [ $skip = 1 ]; then skip=0; continue; fi
      case "$x" in
        --Mdir|--make) skip=1; continue ;;
        --trace-fst) [ $mode = notrace ] && continue ;;
      esac
      a+=("$x")
    done
    /usr/bin/time -f "%U %S" -o "$out.vtime" nice verilator --Mdir "$out" --make cmake "${a[@]}" >"$out.vlog" 2>&1 ||
      { cat "$out.vlog"; exit 1; }
    tr=$([ $mode = trace ] && echo 1 || echo 0)
    list() { sed -n "s/^set(${m}_$1 \(.*\))$/\1/p" "$out/$m.cmake" | tr -d '"' | tr ' ' '\n' | grep -v '^$' || true; }
    { list CLASSES_FAST | sed 's/^/fast /'; list SUPPORT_FAST | sed 's/^/fast /'
      list CLASSES_SLOW | sed 's/^/slow /'; list SUPPORT_SLOW | sed 's/^/slow /'; } >"$out.files"
    export out tr vinc
    # shellcheck disable=SC2016
    xargs -P "$jobs" -L 1 bash -c 'f=$1; kind=$0; o=$out/$(basename "$f").o
      opt=""; [ "$kind" = slow ] && opt=-O0
      /usr/bin/time -f "%U %S" -o "$o.$kind.time" nice g++ -O3 -DNDEBUG -std=gnu++20 $opt -DVM_COVERAGE=0 -DVM_SC=0 \
        -DVM_TRACE=$tr -DVM_TRACE_FST=$tr -DVM_TRACE_VCD=0 -I"$out" -I"$vinc" -I"$vinc/vltstd" -c "$f" -o "$o"' \
      <"$out.files"
    fast=$(cat "$out"/*.fast.time 2>/dev/null | cpu); slow=$(cat "$out"/*.slow.time 2>/dev/null | cpu)
    printf "%-32s %-8s %8s %8.1f %8s %8s %6d\n" "$m" "$mode" "$(cpu "$out.vtime")" "$(echo "$fast + $slow" | bc)" \
      "$fast" "$slow" "$(wc -l <"$out.files")"
  done
done
