#!/usr/bin/env bash
# Every RTL file parses in the three tools the project supports (docs/architecture.md, "RTL
# manifest and tools"), over the lists of rtl/manifest.json (`texunit rtl-files`):
#   Verilator  `--lint-only -Wall --assert` over the whole tree, one run (the lint test);
#   Icarus 11  `iverilog -g2012` elaboration of every top, on its block's sources;
#   Yosys 0.23 `read_verilog -sv` + `hierarchy -check -top` of every top.
# A tool that is not installed is skipped with a message; any error (for Icarus also any warning
# other than its "sorry" notes on always_comb sensitivity and unique case) fails.
# Usage: scripts/rtl_tools.sh [verilator|iverilog|yosys]...   (default: all three)
#        TU_TEXUNIT=path/to/texunit to use another build (default build/default)
set -uo pipefail
cd "$(dirname "$0")/.."
tu=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
tools=("$@")
[ ${#tools[@]} -gt 0 ] || tools=(verilator iverilog yosys)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
list() { "$tu" rtl-files --root . "$@" || { echo "FAIL texunit rtl-files $*"; exit 1; }; }

mapfile -t all < <(list --list all)
mapfile -t tops < <(list --list tops)
mapfile -t lint_only < <(list --list lint-only)
inc=()
for d in $(list --list include-dirs); do inc+=("-I$d"); done
fail=0

for tool in "${tools[@]}"; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIP $tool: not installed"
    continue
  fi
  case $tool in
    verilator)
      if verilator --lint-only -Wall --assert "${inc[@]}" "${lint_only[@]}" "${all[@]}" >"$tmp/log" 2>&1; then
        echo "PASS verilator --lint-only -Wall --assert: ${#all[@]} files"
      else
        cat "$tmp/log"; echo "FAIL verilator --lint-only -Wall --assert"; fail=1
      fi ;;
    iverilog)
      bad=0
      for top in "${tops[@]}"; do
        mapfile -t src < <(list "$top")
        if ! iverilog -g2012 "${inc[@]}" -s "$top" -o "$tmp/a.vvp" "${src[@]}" >"$tmp/log" 2>&1 ||
           grep -v -e 'sorry: constant selects in always_\* processes' -e 'sorry: Case unique/unique0' "$tmp/log" | grep -q .; then
          cat "$tmp/log"; echo "FAIL iverilog -g2012 -s $top"; bad=1
        fi
      done
      if [ $bad = 0 ]; then echo "PASS iverilog -g2012: ${#tops[@]} tops"; else fail=1; fi ;;
    yosys)
      script="" n=0
      for top in "${tops[@]}"; do
        mapfile -t src < <(list "$top")
        script+="design -reset; read_verilog -sv ${inc[*]} ${src[*]}; hierarchy -check -top $top; "
        n=$((n + 1))
      done
      if yosys -q -p "$script" >"$tmp/log" 2>&1; then
        echo "PASS yosys read_verilog -sv + hierarchy -check -top: $n tops"
      else
        cat "$tmp/log"; echo "FAIL yosys"; fail=1
      fi ;;
    *) echo "unknown tool $tool (verilator, iverilog or yosys)"; exit 2 ;;
  esac
done
exit $fail
