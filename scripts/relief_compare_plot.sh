#!/usr/bin/env bash
# Relief methods compared (docs/blocks/relief-appendix.md §13.6): PSNR against the exact intersection vs
# modelled cycles per pixel, one panel per height map, at 60 and 80 degrees.
# Usage: scripts/relief_compare_plot.sh [TEXUNIT] [OUT_DIR]   (default: build/default/tools/texunit/texunit, docs/blocks/relief)
set -euo pipefail
tu=${1:-build/default/tools/texunit/texunit}
out=${2:-docs/blocks/relief}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$tu" relief-quality --compare --debug-dir "$tmp" >"$tmp/q.md"
# columns of the table: map angle method steps fetches cycles psnr psnr_exact nonconv ref
awk -F'|' 'NR > 2 { for (i = 2; i <= 11; ++i) gsub(/ /, "", $i); m = $4; fam = m;
  if (m ~ /^N=/) fam = "pom_fixed"; else if (m ~ /^linbin/) fam = "linbin";
  if ($8 == "inf") next;
  print $2, $3, fam, m, $7, $9 > ("'"$tmp"'/" $2 "_" $3 "_" fam ".dat") }' "$tmp/q.md"
maps="smooth bricks noisy fbm gravel bark stone"
for ang in 60 80; do
  {
    echo "set terminal pngcairo size 1800,420 noenhanced"
    echo "set output '$out/compare_psnr_vs_cycles_${ang}.png'"
    echo "set grid; set key bottom right font ',7'; set xlabel 'cycles / px (model)'; set ylabel 'PSNR vs exact dB'"
    echo "set multiplot layout 1,7 title 'relief methods at ${ang} deg (texunit relief-quality --compare)'"
    for m in $maps; do
      echo "set title '$m'"
      plot="plot"
      sep=""
      for fam in pom_fixed linbin adaptive iter-norm dm dm-refined dm+finish dm-refined+finish; do
        f="$tmp/${m}_${ang}_${fam}.dat"
        [ -f "$f" ] || continue
        style="points pt 7"
        case $fam in pom_fixed|linbin) style="linespoints pt 7" ;; dm-refined*) style="points pt 6 ps 2" ;; esac
        plot="$plot$sep '$f' using 5:6 with $style title '$fam'"
        sep=","
      done
      echo "$plot"
    done
    echo "unset multiplot"
  } >"$tmp/p_$ang.gp"
  gnuplot "$tmp/p_$ang.gp"
done
cp "$tmp"/height_*.png "$out/"
echo "wrote $out/compare_psnr_vs_cycles_{60,80}.png and the height maps"
