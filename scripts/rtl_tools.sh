#!/usr/bin/env bash
# Every RTL file parses in the three tools the project supports (docs/architecture.md, "RTL
# tools"): Verilator (`--lint-only -Wall` over the whole tree, one run), Icarus Verilog 11
# (`iverilog -g2012` elaboration of every module as top) and Yosys 0.23 (`read_verilog -sv` +
# `hierarchy -top` of every module but the big tops). A tool that is not installed is skipped
# with a message; any error (or, for Icarus, any warning other than its "sorry" notes on
# always_comb sensitivity and unique case) fails.
# Usage: scripts/rtl_tools.sh [verilator|iverilog|yosys]...   (default: all three)
set -uo pipefail
cd "$(dirname "$0")/.."
tools=("$@")
[ ${#tools[@]} -gt 0 ] || tools=(verilator iverilog yosys)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Packages first, then every other file in sorted order.
mapfile -t files < <(ls rtl/0_pkg/*_pkg.sv; find rtl -name '*.sv' ! -path 'rtl/0_pkg/*' | sort)
mapfile -t tops < <(sed -nE 's/^\s*module\s+(\w+).*/\1/p' "${files[@]}")
inc=(-Irtl/generated)
# Yosys tops left out: minutes of elaboration each (the texture-unit tops and the EWA engine);
# their sub-blocks are all checked.
big='^(tu_texture_unit|tu_texture_unit_sim|tu_ewa|tu_ewa_sim)$'
fail=0

for tool in "${tools[@]}"; do
  if ! command -v "$tool" >/dev/null; then
    echo "SKIP $tool: not installed"
    continue
  fi
  case $tool in
    verilator)
      if verilator --lint-only -Wall "${inc[@]}" rtl/0_pkg/tu_lint_waivers.sv "${files[@]}" >"$tmp/log" 2>&1; then
        echo "PASS verilator --lint-only -Wall: ${#files[@]} files"
      else
        cat "$tmp/log"; echo "FAIL verilator --lint-only -Wall"; fail=1
      fi ;;
    iverilog)
      n=0 bad=0
      for top in "${tops[@]}"; do
        if ! iverilog -g2012 "${inc[@]}" -s "$top" -o "$tmp/a.vvp" "${files[@]}" >"$tmp/log" 2>&1 ||
           grep -v -e 'sorry: constant selects in always_\* processes' -e 'sorry: Case unique/unique0' "$tmp/log" | grep -q .; then
          cat "$tmp/log"; echo "FAIL iverilog -g2012 -s $top"; bad=1
        fi
        n=$((n + 1))
      done
      if [ $bad = 0 ]; then echo "PASS iverilog -g2012: $n tops"; else fail=1; fi ;;
    yosys)
      script="read_verilog -sv ${inc[*]} ${files[*]}; design -save all;"
      n=0
      for top in "${tops[@]}"; do
        [[ $top =~ $big ]] && continue
        script+=" design -load all; hierarchy -check -top $top;"
        n=$((n + 1))
      done
      if yosys -q -p "$script" >"$tmp/log" 2>&1; then
        echo "PASS yosys read_verilog -sv + hierarchy -top: $n tops"
      else
        cat "$tmp/log"; echo "FAIL yosys"; fail=1
      fi ;;
    *) echo "unknown tool $tool (verilator, iverilog or yosys)"; exit 2 ;;
  esac
done
exit $fail
