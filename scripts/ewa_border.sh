#!/bin/sh
# EWA sub-texel border weights against the ground truth (docs/blocks/ewa.md "Border weights"):
# per scene (the default scene and docs/scenes/*.json, EWA on every material, texture path) and
# clip variant, the C-model render against the 16 x 16-sample truth (box and Gaussian kernels)
# and the float EWA reference (off / exact Phi border weights): PSNR over covered pixels and
# texels walked per pixel. Usage: TU_TEXUNIT=build/default/tools/texunit/texunit scripts/ewa_border.sh [OUT]
# (about 3 minutes idle; prints one table row per scene and variant).
set -eu
T=${TU_TEXUNIT:-build/default/tools/texunit/texunit}
OUT=${1:-/tmp/ewa_border}
VARIANTS="off seed_p1 seed_p2 seed_p3 mm_p1 mm_p2 mm_p3 mm_p3_estrin mm_p4 tab16"
mkdir -p "$OUT"

# PSNR over a's covered pixels (RGB, as render::psnr_covered) and a's texels per pixel.
psnr() {
  python3 - "$1" "$2" <<'PY'
import csv, math, sys
def load(p):
    with open(p) as f:
        return {(r['x'], r['y']): r for r in csv.DictReader(f)}
a, b = load(sys.argv[1]), load(sys.argv[2])
se = n = tex = 0
for k, r in a.items():
    s = b[k]
    for c in 'rgb':
        se += (int(r[c]) - int(s[c])) ** 2
        n += 1
    tex += int(r['texels'])
print("%s %.2f" % ("inf" if se == 0 else "%.2f" % (10 * math.log10(255 * 255 * n / se)), tex / len(a)))
PY
}

printf '%-10s %-13s %10s %10s %12s %9s\n' scene clip "vs box" "vs gauss" "vs float" "texels/px"
for scene in default docs/scenes/*.json; do
  name=$(basename "$scene" .json)
  d="$OUT/$name"
  mkdir -p "$d"
  for k in box gauss; do
    nice "$T" render "$scene" --engine truth --truth-kernel "$k" --no-relief --filter ewa --out "$d/truth_$k" \
      --dump "$d/truth_$k.csv" >/dev/null 2>&1
  done
  for c in off mm_p3; do  # the float reference: off, exact Phi (any variant name turns it on)
    nice "$T" render "$scene" --engine ref --no-relief --filter ewa --clip "$c" --out "$d/ref_$c" \
      --dump "$d/ref_$c.csv" >/dev/null 2>&1
  done
  for c in float_off float_exact $VARIANTS; do
    if [ "$c" = float_off ] || [ "$c" = float_exact ]; then
      if [ "$c" = float_off ]; then f="$d/ref_off.csv"; else f="$d/ref_mm_p3.csv"; fi
      fl=$f
      label=$c
    else
      f="$d/cmodel_$c.csv"
      nice "$T" render "$scene" --engine cmodel --no-relief --filter ewa --clip "$c" --out "$d/cm_$c" \
        --dump "$f" >/dev/null 2>&1
      if [ "$c" = off ]; then fl="$d/ref_off.csv"; else fl="$d/ref_mm_p3.csv"; fi
      label=$c
    fi
    set -- $(psnr "$f" "$d/truth_box.csv") $(psnr "$f" "$d/truth_gauss.csv") $(psnr "$f" "$fl")
    printf '%-10s %-13s %10s %10s %12s %9s\n' "$name" "$label" "$1" "$3" "$5" "$2"
  done
done
