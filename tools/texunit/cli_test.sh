#!/usr/bin/env bash
# CLI tests of `texunit report`, `texunit plan` and --threads (registered in CMakeLists.txt, one case each).
# Usage: cli_test.sh TEXUNIT SOURCE_DIR CASE
set -euo pipefail
tu=$1; src=$2; case=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$src"
fail() { echo "FAIL ($case): $*" >&2; exit 1; }
val() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }
case $case in
  report_fields)
    # Measured fields are numbers; a field that is not measured says why.
    "$tu" report --blocks reciprocal,persp --count 2000 --no-yosys --json "$tmp/r.json" >/dev/null
    [ "$(val "$tmp/r.json" "len(d)")" = 5 ] || fail "expected 5 rows (reciprocal + 4 persp variants, incl. texel_depth)"
    [ "$(val "$tmp/r.json" "all(r['cells'] == 'not measured: --no-yosys' for r in d)")" = True ] || fail "cells reason"
    [ "$(val "$tmp/r.json" "all(isinstance(r['rtl_sim_items_per_s'], (int, float)) and r['rtl_sim_items_per_s'] > 0 for r in d)")" = True ] || fail "rtl speed"
    [ "$(val "$tmp/r.json" "all(r['cycles_source'].startswith('measured') for r in d)")" = True ] || fail "cycles source"
    # texel_depth (seed 001 §3): tu_texel_depth measured on B1's seeds, two stages longer than B1.
    [ "$(val "$tmp/r.json" "[r['latency_cycles'] for r in d if r['variant'] == 'texel_depth'][0]")" = 10 ] || fail "texel_depth latency"
    [ "$(val "$tmp/r.json" "[r['max_abs_err'] for r in d if r['variant'] == 'incremental'][0] < 1/16")" = True ] || fail "persp error"
    ;;
  report_stdcell)
    # Standard-cell columns from the committed cache: numbers where the cache is current, with
    # latency_ns = latency x period and ns_per_item = II x period; a missing cache says why.
    "$tu" report --blocks reciprocal --count 2000 --no-yosys --stdcell-cache docs/report/stdcell_cache.json \
      --json "$tmp/r.json" >/dev/null
    [ "$(val "$tmp/r.json" "all(isinstance(r[k], (int, float)) and r[k] > 0 for r in d for k in ('area_um2', 'period_ns', 'fmax_mhz'))")" = True ] ||
      fail "stdcell fields: $(val "$tmp/r.json" "d[0]['stdcell_source']")"
    [ "$(val "$tmp/r.json" "all(abs(r['latency_ns'] - r['latency_cycles'] * r['period_ns']) < 1e-6 * r['latency_ns'] and abs(r['ns_per_item'] - r['ii_cycles'] * r['period_ns']) < 1e-6 * r['ns_per_item'] for r in d)")" = True ] || fail "ns columns"
    "$tu" report --blocks reciprocal --count 2000 --no-yosys --stdcell-cache "$tmp/none.json" --json "$tmp/r2.json" >/dev/null
    [ "$(val "$tmp/r2.json" "d[0]['area_um2'].startswith('not measured: tu_reciprocal not in')")" = True ] || fail "missing-cache reason"
    ;;
  report_cache_key)
    # A top's synthesis cache key covers the package constants and enums its files name, not the
    # rest of the package: a constant or enum added for another block keeps the key, a changed
    # width or enum member the top uses changes it.
    mkdir -p "$tmp/r/scripts"; cp -r rtl "$tmp/r/"; cp scripts/yosys_area.sh scripts/stdcell_flow.sh "$tmp/r/scripts/"
    key() { "$tu" rtl-files "$1" --root "$tmp/r" --key "$2"; }
    k_rec=$(key tu_reciprocal yosys); k_top=$(key tu_texture_unit stdcell); pkg="$tmp/r/rtl/0_pkg/tu_formats_pkg.sv"
    sed -i 's/^endpackage/  \/\/ another block'"'"'s width and codes\n  localparam int OtherBlockW = 7;\n  typedef enum logic [1:0] {\n    OtherA = 2'"'"'d0,\n    OtherB = 2'"'"'d1\n  } other_e;\nendpackage/' "$pkg"
    grep -q "other_e;" "$pkg" || fail "test edit of the package"
    [ "$(key tu_reciprocal yosys)" = "$k_rec" ] || fail "an unused constant or enum changed tu_reciprocal's key"
    [ "$(key tu_texture_unit stdcell)" = "$k_top" ] || fail "an unused constant or enum changed tu_texture_unit's key"
    sed -i 's/EngNearest = \([0-9]*\).d3/EngNearest = \1'"'"'d2/' "$pkg"
    [ "$(key tu_texture_unit stdcell)" != "$k_top" ] || fail "a changed engine code kept tu_texture_unit's key"
    [ "$(key tu_reciprocal yosys)" = "$k_rec" ] || fail "the engine enum changed tu_reciprocal's key"
    sed -i 's/localparam int RecipIdxW = [0-9]*;/localparam int RecipIdxW = 9;/' "$pkg"
    [ "$(key tu_reciprocal yosys)" != "$k_rec" ] || fail "a changed width kept tu_reciprocal's key"
    ;;
  stdcell_concurrent)
    # Two `texunit stdcell` runs at once on one cache keep each other's entries (each save re-reads
    # the file under a lock and writes only its own top). A stand-in flow script (0.3 s, fixed
    # figures) replaces the osu018 flow; the tops, files and keys are the real ones.
    mkdir -p "$tmp/r/scripts"; cp -r rtl "$tmp/r/"
    printf '#!/bin/sh\nsleep 0.3\necho "{\\"top\\": \\"$1\\", \\"area_um2\\": 1.0, \\"period_ns\\": 5.0, \\"path_from\\": \\"a\\", \\"path_to\\": \\"b\\"}"\n' \
      > "$tmp/r/scripts/stdcell_flow.sh"
    chmod +x "$tmp/r/scripts/stdcell_flow.sh"
    c="$tmp/cache.json"
    "$tu" stdcell tu_reciprocal tu_persp tu_clip_p1 tu_nearest --root "$tmp/r" --cache "$c" --netlists "$tmp/n" 2>/dev/null &
    a=$!
    "$tu" stdcell tu_bilinear tu_gauss_weight tu_pom_march tu_texel_addr --root "$tmp/r" --cache "$c" --netlists "$tmp/n" 2>/dev/null &
    b=$!
    wait $a || fail "first stdcell run failed"
    wait $b || fail "second stdcell run failed"
    [ "$(val "$c" "len(d)")" = 8 ] || fail "entries lost by two runs at once: $(val "$c" "sorted(d)")"
    [ "$(val "$c" "d['tu_persp']['hash'] == '$("$tu" rtl-files tu_persp --root "$tmp/r" --key stdcell)'")" = True ] || fail "entry key"
    ;;
  report_bad_block)
    if "$tu" report --blocks recip --no-yosys --json "$tmp/r.json" 2>"$tmp/err"; then fail "accepted an unknown block"; fi
    grep -q "unknown block 'recip' (known: reciprocal, persp" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    [ ! -e "$tmp/r.json" ] || fail "partial output written"
    ;;
  render_procedural)
    # Procedural materials: an animation (one PNG per frame, the smoke moves), the PSNR against the
    # reference (fbm, smoke and water render on the RTL: TextureUnitRtl.ProceduralSceneEqualsCModelCyclesPredicted,
    # TextureUnitRtl.WaterEqualsCModelCyclesPredicted).
    "$tu" render docs/scenes/procedural.json --engine cmodel --frames 3 --dt 0.5 --out "$tmp/a" 2>/dev/null >/dev/null
    for i in 0000 0001 0002; do [ -s "$tmp/a/cmodel_$i.png" ] || fail "frame $i missing"; done
    ! cmp -s "$tmp/a/cmodel_0000.png" "$tmp/a/cmodel_0001.png" || fail "frames 0 and 1 are equal"
    "$tu" render docs/scenes/procedural.json --engine cmodel --vs ref --out "$tmp/b" 2>/dev/null >"$tmp/b.txt"
    grep -q "PSNR cmodel vs ref: .* dB over 2\?[0-9]* covered pixels; ground .* dB smoke .* dB" "$tmp/b.txt" || fail "$(cat "$tmp/b.txt")"
    [ -s "$tmp/b/heat_cmodel_vs_ref.png" ] || fail "heat map missing"
    ;;
  plan_default)
    "$tu" plan default --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "d['filter'], d['relief'], d['persp'].split('/')[0]")" = "('ewa', True, 'persp')" ] || fail "$(cat "$tmp/p.json")"
    grep -q "localparam bit HasEwa = 1'b1;" "$tmp/cfg.sv" || fail "HasEwa"
    # No light in the default scene: no shading stage.
    [ "$(val "$tmp/p.json" "d['shading']")" = False ] || fail "shading $(cat "$tmp/p.json")"
    grep -q "localparam bit HasShading = 1'b0;" "$tmp/cfg.sv" || fail "HasShading"
    ;;
  plan_shaded_sphere)
    # A light: the shading stage with the cheapest model within max_brdf_mad (0.01: F_QR, MAD
    # 0.0082, the fewest cells); a tighter budget (0.002) needs F_ST16; a model the material names wins.
    "$tu" plan docs/scenes/shaded_sphere.json --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "d['shading']['model'].split()[0]")" = "brdf/qr" ] || fail "$(cat "$tmp/p.json")"
    grep -q "localparam bit HasShading = 1'b1;" "$tmp/cfg.sv" || fail "HasShading"
    grep -q "localparam int ShadeModel = 6;" "$tmp/cfg.sv" || fail "ShadeModel"
    sed 's/"max_brdf_mad": 0.01/"max_brdf_mad": 0.002/' docs/scenes/shaded_sphere.json >"$tmp/tight.json"
    "$tu" plan "$tmp/tight.json" --json >"$tmp/p2.json"
    [ "$(val "$tmp/p2.json" "d['shading']['model'].split()[0]")" = "brdf/st16" ] || fail "$(cat "$tmp/p2.json")"
    sed 's/"specular": {"n": 40/"specular": {"model": "dsh", "n": 40/' docs/scenes/shaded_sphere.json >"$tmp/pinned.json"
    "$tu" plan "$tmp/pinned.json" --json >"$tmp/p3.json"
    [ "$(val "$tmp/p3.json" "d['shading']['model'].split()[0], d['shading']['why']")" = "('brdf/dsh', 'named by the materials (MAD 0.00251)')" ] || fail "$(cat "$tmp/p3.json")"
    ;;
  plan_pipeline)
    # Pipeline per material (object space vs screen space, by rendering each material alone).
    # ui_quad's head-on panel: object space at spacing 1.9 (0.28 samples/px x 16 trilinear clocks
    # + 1 divide) beats screen bilinear (7 clocks/px) and meets 28 dB; at a 30 dB budget it does
    # not (29.4 dB): the choice flips back to screen space. hud_floor: never (the floor needs more
    # samples than EWA's clocks allow; the HUD at 1.9 leaves holes).
    "$tu" plan docs/scenes/ui_quad.json --json >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "d['pipelines']['panel']['pipeline']")" = object-space ] || fail "ui_quad: $(val "$tmp/p.json" "d['pipelines']")"
    [ "$(val "$tmp/p.json" "[k['spacing'] for k in d['pipelines']['panel']['object_space'] if k['rendered'] and k['clocks_per_px'] < d['pipelines']['panel']['screen_clocks_per_px'] and k['psnr_db'] >= 28 and k['holes'] == 0]")" = "[1.9]" ] || fail "ui_quad tries"
    python3 -c "import json,sys; d=json.load(open('docs/scenes/ui_quad.json')); d['error_budget']['min_psnr_db']=30; json.dump(d, open(sys.argv[1],'w'))" "$tmp/ui30.json"
    "$tu" plan "$tmp/ui30.json" --json >"$tmp/p30.json"
    [ "$(val "$tmp/p30.json" "d['pipelines']['panel']['pipeline']")" = screen ] || fail "ui_quad at 30 dB: $(val "$tmp/p30.json" "d['pipelines']")"
    "$tu" plan docs/scenes/hud_floor.json --json >"$tmp/h.json"
    [ "$(val "$tmp/h.json" "sorted((k, v['pipeline']) for k, v in d['pipelines'].items())")" = "[('floor', 'screen'), ('hud', 'screen')]" ] || fail "hud_floor"
    [ "$(val "$tmp/h.json" "[k['holes'] > 0 for k in d['pipelines']['hud']['object_space'] if k['rendered']]")" = "[True]" ] || fail "hud holes"
    ;;
  plan_ui_quad)
    # Head-on, magnified: bilinear instead of EWA, no relief hardware; fewer cells than the full unit.
    "$tu" plan docs/scenes/ui_quad.json --json --out "$tmp/tu_unit_cfg_pkg.sv" >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "d['filter'], d['relief']")" = "('bilinear', False)" ] || fail "$(cat "$tmp/p.json")"
    [ "$(val "$tmp/p.json" "d['specialised']['cells_sum_of_blocks'] < d['full']['cells_sum_of_blocks']")" = True ] || fail "area"
    grep -q "localparam bit HasEwa = 1'b0;" "$tmp/tu_unit_cfg_pkg.sv" || fail "HasEwa"
    grep -q "localparam bit HasRelief = 1'b0;" "$tmp/tu_unit_cfg_pkg.sv" || fail "HasRelief"
    grep -q "localparam bit HasBilinear = 1'b1;" "$tmp/tu_unit_cfg_pkg.sv" || fail "HasBilinear"
    grep -q "localparam bit HasTriFilter = 1'b0;" "$tmp/tu_unit_cfg_pkg.sv" || fail "HasTriFilter"
    # Its one texture clamps: the texel addressing keeps repeat and clamp only (bits 0 and 2).
    grep -q "localparam logic \[4:0\] WrapModes = 5'd5;" "$tmp/tu_unit_cfg_pkg.sv" || fail "WrapModes"
    [ "$(val "$tmp/p.json" "d['wrap_modes']")" = "['repeat', 'clamp']" ] || fail "wrap_modes $(cat "$tmp/p.json")"
    grep -q "localparam bit HasNoise = 1'b0;" "$tmp/tu_unit_cfg_pkg.sv" || fail "HasNoise"
    # Exact scene cycles (texture path): bilinear on every span is cheaper than the authored EWA.
    [ "$(val "$tmp/p.json" "0 < d['scene_cycles']['specialised'] < d['scene_cycles']['full']")" = True ] || fail "scene cycles"
    # The package lints (-Wall) as the RTL top would read it.
    cat >"$tmp/tu_cfg_user.sv" <<'SV'
module tu_cfg_user (
  output logic [15:0] has_o,
  output logic [2:0]  wsrc_o,
  output logic [31:0] sizes_o,
  output logic [4:0]  wrap_o
);
  assign wrap_o = tu_unit_cfg_pkg::WrapModes;
  assign has_o = {tu_unit_cfg_pkg::HasTrilinear, tu_unit_cfg_pkg::HasEwa, tu_unit_cfg_pkg::HasBilinear, tu_unit_cfg_pkg::HasTriFilter, tu_unit_cfg_pkg::HasNearest, tu_unit_cfg_pkg::HasFeline, tu_unit_cfg_pkg::HasRelief,
                  tu_unit_cfg_pkg::HasPom, tu_unit_cfg_pkg::HasIterParallax, tu_unit_cfg_pkg::HasShading, tu_unit_cfg_pkg::EllRecurrence,
                  tu_unit_cfg_pkg::HasEwaClip, tu_unit_cfg_pkg::HasNoise, tu_unit_cfg_pkg::HasDistanceMap,
                  tu_unit_cfg_pkg::HasWater, tu_unit_cfg_pkg::HasAfvis};
  assign wsrc_o = tu_unit_cfg_pkg::WeightSources;
  assign sizes_o = tu_unit_cfg_pkg::PomMaxLayers + tu_unit_cfg_pkg::WtabLog2N + tu_unit_cfg_pkg::Wtab2dLog2N +
                   tu_unit_cfg_pkg::PerspLanes + tu_unit_cfg_pkg::ShadeModel + tu_unit_cfg_pkg::EwaClipVariant +
                   tu_unit_cfg_pkg::NoiseDims + tu_unit_cfg_pkg::NoiseCores + tu_unit_cfg_pkg::NoiseScheme +
                   32'(tu_unit_cfg_pkg::TexFormats) + 32'(tu_unit_cfg_pkg::HasSrgb) + tu_unit_cfg_pkg::TexelW + 32'(tu_unit_cfg_pkg::HasBc1);
endmodule
SV
    verilator --lint-only -Wall "$tmp/tu_unit_cfg_pkg.sv" "$tmp/tu_cfg_user.sv" || fail "package does not lint"
    ;;
  cfg_pkg_full)
    # The committed configuration the RTL top reads by default is the full unit's, as plan writes it.
    "$tu" plan default --out-full "$tmp/full.sv" >/dev/null
    diff -u rtl/0_pkg/tu_unit_cfg_pkg.sv "$tmp/full.sv" || fail "rtl/0_pkg/tu_unit_cfg_pkg.sv is not the full unit: texunit plan default --out-full rtl/0_pkg/tu_unit_cfg_pkg.sv"
    ;;
  plan_procedural)
    # Procedural materials: the noise unit, 3-D cores (the smoke moves through time), the fewest
    # octave cores meeting min_psnr_db on the procedural pixels (docs/blocks/noise-appendix.md §5).
    "$tu" plan docs/scenes/procedural.json --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "d['noise']['dims'], sorted(d['noise']['materials'])")" = "(3, ['marble', 'smoke'])" ] || fail "$(cat "$tmp/p.json")"
    k=$(val "$tmp/p.json" "d['noise']['octave_cores']")
    [ "$(val "$tmp/p.json" "all((float(v) if v != 'identical' else 1e9) >= d['budget']['min_psnr_db'] for kk, v in d['noise']['psnr_db_by_octaves'].items() if int(kk) == $k)")" = True ] || fail "octaves"
    grep -q "localparam bit HasNoise = 1'b1;" "$tmp/cfg.sv" || fail "HasNoise"
    grep -q "localparam int NoiseCores = $k;" "$tmp/cfg.sv" || fail "NoiseCores"
    # No cycle budget: the pipelined scheme; a budget the octave-serial unit meets picks it (one
    # core), one clock less keeps the pipelined unit.
    [ "$(val "$tmp/p.json" "d['noise']['scheme']['picked']")" = pipelined ] || fail "scheme $(cat "$tmp/p.json")"
    grep -q "localparam int NoiseScheme = 0;" "$tmp/cfg.sv" || fail "NoiseScheme 0"
    # (the budget runs on a 48 x 36 copy of the scene: seconds)
    python3 -c "import json; d=json.load(open('docs/scenes/procedural.json')); d['camera'].update(width=48, height=36); json.dump(d, open('$tmp/small.json', 'w'))"
    "$tu" plan "$tmp/small.json" --json >"$tmp/ps.json"
    read -r pipe serial < <(val "$tmp/ps.json" "'%d %d' % (d['noise']['scheme']['pipelined_cycles'], d['noise']['scheme']['octave_serial_cycles'])")
    [ "$serial" -gt "$pipe" ] || fail "octave-serial $serial <= pipelined $pipe clocks"
    for budget in "$serial" "$((serial - 1))"; do
      "$tu" plan "$tmp/small.json" --max-cycles "$budget" --json --out "$tmp/cfg_b.sv" >"$tmp/pb.json"
      want=pipelined; code=0
      [ "$budget" = "$serial" ] && want=octave_serial && code=1
      [ "$(val "$tmp/pb.json" "d['noise']['scheme']['picked']")" = "$want" ] || fail "budget $budget: $(cat "$tmp/pb.json")"
      grep -q "localparam int NoiseScheme = $code;" "$tmp/cfg_b.sv" || fail "NoiseScheme at $budget"
    done
    rc=0; "$tu" plan "$tmp/small.json" --max-cycles -5 >/dev/null 2>"$tmp/err" || rc=$?
    [ "$rc" != 0 ] || fail "accepted a negative cycle budget"
    ;;
  plan_corridor)
    "$tu" plan docs/scenes/corridor.json --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    # The RTL co-simulation's corridor unit (TextureUnitRtl.CorridorPlannedUnit...) is this package.
    diff -u testbench/cosim/rtl/corridor/tu_unit_cfg_pkg.sv "$tmp/cfg.sv" ||
      fail "testbench/cosim/rtl/corridor/tu_unit_cfg_pkg.sv is stale: texunit plan docs/scenes/corridor.json --out testbench/cosim/rtl/corridor/tu_unit_cfg_pkg.sv"
    [ "$(val "$tmp/p.json" "d['filter'], d['relief']")" = "('ewa', True)" ] || fail "$(cat "$tmp/p.json")"
    [ "$(val "$tmp/p.json" "any('iter_parallax' in b for b in d['specialised']['blocks'])")" = True ] || fail "iterative relief"
    ;;
  plan_af_visibility)
    # AF with parallax visibility (docs/blocks/afvis-appendix.md §5): the unit keeps tu_afvis when a material
    # asks for it and reports its clocks; a scene without the flag leaves it out.
    "$tu" plan docs/scenes/af_visibility.json --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    grep -q "localparam bit HasAfvis = 1'b1;" "$tmp/cfg.sv" || fail "af_visibility.json: HasAfvis not 1: $(cat "$tmp/cfg.sv")"
    [ "$(val "$tmp/p.json" "d['af_visibility']['pixels'] > 0 and d['af_visibility']['walker_clocks_per_px'] > d['af_visibility']['ewa_walker_clocks_per_px']")" = True ] ||
      fail "af_visibility cost: $(cat "$tmp/p.json")"
    "$tu" plan docs/scenes/ui_quad.json --json --out "$tmp/cfg2.sv" >"$tmp/p2.json"
    grep -q "localparam bit HasAfvis = 1'b0;" "$tmp/cfg2.sv" || fail "ui_quad.json: HasAfvis not 0"
    [ "$(val "$tmp/p2.json" "d['af_visibility']")" = False ] || fail "ui_quad af_visibility: $(cat "$tmp/p2.json")"
    ;;
  plan_hud_floor)
    # Per-material filters: the floor needs EWA, the head-on HUD quad bilinear; no trilinear or
    # relief hardware; the plan's per-span filters beat the authored EWA-everywhere in cycles.
    "$tu" plan docs/scenes/hud_floor.json --json --out "$tmp/cfg.sv" >"$tmp/p.json"
    [ "$(val "$tmp/p.json" "sorted(d['filters'].items())")" = "[('floor', 'ewa'), ('hud', 'bilinear')]" ] || fail "$(cat "$tmp/p.json")"
    for kv in "HasEwa = 1'b1" "HasBilinear = 1'b1" "HasTriFilter = 1'b0" "HasRelief = 1'b0"; do
      grep -q "localparam bit $kv;" "$tmp/cfg.sv" || fail "$kv"
    done
    [ "$(val "$tmp/p.json" "d['scene_cycles']['specialised'] < d['scene_cycles']['full_as_authored']")" = True ] || fail "cycles"
    ;;
  plan_too_tight)
    sed 's/"min_psnr_db": 40/"min_psnr_db": 100/' docs/scenes/corridor.json >"$tmp/tight.json"
    set +e
    "$tu" plan "$tmp/tight.json" --out "$tmp/cfg.sv" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    set -e
    [ $rc = 2 ] || fail "exit $rc, expected 2"
    grep -q "tight.json: /error_budget/min_psnr_db = 100: no .* variant reaches it (best: " "$tmp/err" || fail "message: $(cat "$tmp/err")"
    [ ! -e "$tmp/cfg.sv" ] && [ ! -s "$tmp/out" ] || fail "partial output"
    sed 's/"max_texel_err": 0.03125/"max_texel_err": 0.001/' docs/scenes/corridor.json >"$tmp/tight2.json"
    if "$tu" plan "$tmp/tight2.json" 2>"$tmp/err2" >/dev/null; then fail "accepted max_texel_err 0.001"; fi
    grep -q "/error_budget/max_texel_err = 0.001: no persp variant reaches it" "$tmp/err2" || fail "message: $(cat "$tmp/err2")"
    ;;
  plan_area_ui_quad)
    # The RTL top synthesised with the full and with ui_quad's parameters (pre-techmap cells):
    # the plan sets HasEwa = 0 and the cells drop (the script fails otherwise).
    TU_TEXUNIT="$tu" scripts/plan_area.sh --coarse docs/scenes/ui_quad.json >"$tmp/out"
    cat "$tmp/out"
    grep -q "full: .*HasEwa=1" "$tmp/out" && grep -q "specialised: .*HasEwa=0" "$tmp/out" || fail "HasEwa not set"
    ;;
  threads_same_output)
    # --threads 1 and --threads 3 write the same bytes (C-model render with relief, vector file).
    for t in 1 3; do
      "$tu" render default --engine cmodel --threads $t --out "$tmp/r$t" --dump "$tmp/r$t.csv" 2>/dev/null
      "$tu" vectors --block ewa --set random --count 3000 --seed 4 --threads $t --out "$tmp/v$t.vec" 2>/dev/null
    done
    cmp "$tmp/r1/cmodel.png" "$tmp/r3/cmodel.png" || fail "render image differs"
    cmp "$tmp/r1.csv" "$tmp/r3.csv" || fail "render dump differs"
    cmp "$tmp/v1.vec" "$tmp/v3.vec" || fail "vector file differs"
    if "$tu" render default --engine cmodel --threads -1 --out "$tmp/bad" 2>"$tmp/err"; then fail "accepted --threads -1"; fi
    grep -q "threads" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    ;;
  objspace_render)
    # render --pipeline object-space: every engine writes its image and prints holes / overlaps
    # (rtl: the per-sample datapath, no mismatch, cycles as predicted); an engine without the
    # pipeline and an exceeded sample cap exit 2 without output.
    for e in ref cmodel rtl; do
      "$tu" render docs/scenes/ui_quad.json --pipeline object-space --engine $e --out "$tmp/o" >"$tmp/out" 2>/dev/null
      [ -s "$tmp/o/objspace_$e.png" ] || fail "no objspace_$e.png"
      grep -q "object space: 2 triangles, .* samples (1.00 per covered pixel).* 0 holes" "$tmp/out" || fail "stats: $(cat "$tmp/out")"
    done
    grep -q "rtl per-sample datapath (tu_objspace_sample): .* 0 mismatches against the C model; 0 pixels differ" "$tmp/out" \
      || fail "rtl: $(cat "$tmp/out")"
    if "$tu" render docs/scenes/ui_quad.json --pipeline object-space --engine truth --out "$tmp/bad" 2>"$tmp/err"; then fail "accepted truth"; fi
    grep -q "engine must be ref, cmodel or rtl" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    if "$tu" render docs/scenes/ui_quad.json --pipeline object-space --max-samples 100 --out "$tmp/bad2" 2>"$tmp/err"; then fail "cap ignored"; fi
    grep -q "object 'panel' (/objects/0): .*--max-samples" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    [ ! -e "$tmp/bad2/objspace_ref.png" ] || fail "partial output written"
    ;;
  relief_quality_afvis)
    # relief-quality --afvis (docs/blocks/afvis-appendix.md §4): one row per visibility variant, plain traces
    # nothing; the height PNGs' temporary directory is removed; a scene without relief is refused.
    mkdir -p "$tmp/p"
    "$tu" relief-quality --afvis docs/scenes/af_visibility.json --afvis-maps bricks,gravel --afvis-heights 1 --afvis-ss 2 \
      --threads 2 --afvis-plot "$tmp/p" >"$tmp/out" 2>/dev/null
    [ -s "$tmp/p/afvis_gain_vs_clocks.png" ] || fail "no plot"
    [ "$(grep -cE '^\| (bricks|gravel) \| ×1 \| [0-9.]+° \| (plain|every|row|pyramid2|row\+pyramid2) \| [0-9]+ \| [0-9.]+ dB \|' "$tmp/out")" = 10 ] ||
      fail "table: $(cat "$tmp/out")"
    grep -qE '^\| bricks \| ×1 \| [0-9.]+° \| plain \| [0-9]+ \| [0-9.]+ dB \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| 0.00 \| 0.00 \|' "$tmp/out" ||
      fail "plain row: $(cat "$tmp/out")"
    ! ls -d "${TMPDIR:-/tmp}"/texunit_afvis_* 2>/dev/null | grep -q . || fail "temporary directory left"
    if "$tu" relief-quality --afvis docs/scenes/ui_quad.json 2>"$tmp/err" >/dev/null; then fail "accepted a scene without relief"; fi
    grep -q "no material has relief" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    ;;
  report_filters)
    # The report's filters group: 9 filters x 5 scenes, the same numbers as filter-compare on the
    # scene (one measurement, two outputs), kept off the error-vs-cost Pareto plots, its own plot.
    "$tu" report --blocks filters --no-yosys --json "$tmp/r.json" --plots "$tmp/p" --markdown "$tmp/r.md" >/dev/null 2>&1
    [ "$(val "$tmp/r.json" "len(d)")" = 45 ] || fail "expected 45 rows"
    [ -s "$tmp/p/filters_psnr_vs_clocks.png" ] || fail "no plot"
    ! ls "$tmp/p"/filters_error_vs_* 2>/dev/null | grep -q . || fail "filters on a Pareto plot"
    grep -q "^| ui_quad (6216 px) | ewa K=4 | " "$tmp/r.md" || fail "markdown: $(grep -c filters "$tmp/r.md")"
    "$tu" filter-compare docs/scenes/ui_quad.json >"$tmp/fc" 2>/dev/null
    for f in "nearest" "feline N<=8" "ewa K=4"; do
      want=$(grep -E "^$f +[0-9]" "$tmp/fc" | sed "s/^$f//" | awk '{print $1, $3, $7}')
      got=$(val "$tmp/r.json" "' '.join('%.2f' % r[k] for r in d if r['scheme'] == 'ui_quad' and r['variant'] == '$f' for k in ('psnr_truth_db', 'psnr_float_ewa_db', 'clocks_per_px'))")
      [ "$want" = "$got" ] || fail "$f: filter-compare '$want', report '$got'"
    done
    ;;
  filter_compare)
    # filter-compare: one row per filter and Feline cap, numbers in every column, the plot; a Feline
    # material through render: probes per pixel printed; a unit without the Feline engine (the
    # corridor plan's) refuses it naming the field.
    "$tu" filter-compare docs/scenes/ui_quad.json --ss 2 --plot "$tmp/p" >"$tmp/out" 2>/dev/null
    [ "$(grep -cE '^(nearest|bilinear|trilinear|feline N<=(2|4|8|16)|ewa) +[0-9.]+ dB +[0-9.]+ dB( +[0-9.]+\*?){5}$' "$tmp/out")" = 8 ] ||
      fail "table: $(cat "$tmp/out")"
    [ -s "$tmp/p/psnr_vs_clocks.png" ] || fail "no plot"
    "$tu" render default --engine cmodel --filter feline --feline-max-probes 4 --no-relief --out "$tmp/f" >"$tmp/out" 2>/dev/null
    grep -q "Feline: [0-9]* pixels, [0-9.]* probes per pixel" "$tmp/out" || fail "render: $(cat "$tmp/out")"
    sed 's/"filter": "ewa"/"filter": "feline"/' docs/scenes/ui_quad.json >"$tmp/fel.json"
    if "$tu" render "$tmp/fel.json" --engine rtl --rtl-unit corridor --out "$tmp/bad" 2>"$tmp/err"; then fail "corridor unit accepted feline"; fi
    grep -q "/materials/panel/filter: feline" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    ;;
  filter_mip)
    # filter-compare --mip-filter (docs/blocks/texture.md "Mip generation"): a bad value exits 2
    # naming the option; the box table equals the run without the option (the scene's textures are
    # box); on docs/scenes/mip_filters.json (sRGB textures) box_linear and lanczos2 change the
    # mipmapped engines' rows but not nearest's or bilinear's (level 0 alone) nor the truth; on a
    # linear scene box_linear is box.
    set +e; "$tu" filter-compare docs/scenes/ui_quad.json --mip-filter kaiser >"$tmp/out" 2>"$tmp/err"; rc=$?; set -e
    [ "$rc" = 2 ] || fail "bad --mip-filter: exit $rc, expected 2"
    grep -q -- "--mip-filter" "$tmp/err" || fail "message does not name --mip-filter: $(cat "$tmp/err")"
    rows() { awk -v m="$2" '$0 ~ /covered pixels/ {f = (m == "" || index($0, "mip filter " m " (")) ; next} /^$/ {f = 0}
                           f && /^(nearest|bilinear|trilinear|feline|ewa)/' "$1"; }
    row() { rows "$1" "$2" | grep -E "^$3 +[0-9]"; }
    sc=docs/scenes/mip_filters.json
    "$tu" filter-compare $sc --ss 2 >"$tmp/def" 2>/dev/null
    "$tu" filter-compare $sc --ss 2 --mip-filter all --plot "$tmp/p" >"$tmp/all" 2>/dev/null
    [ "$(rows "$tmp/def" "" | wc -l)" = 9 ] || fail "default table: $(cat "$tmp/def")"
    for m in box box_linear lanczos2; do
      [ "$(rows "$tmp/all" $m | wc -l)" = 9 ] || fail "$m table: $(cat "$tmp/all")"
      [ -s "$tmp/p/$m/psnr_vs_clocks.png" ] || fail "no $m plot"
    done
    [ "$(rows "$tmp/def" "")" = "$(rows "$tmp/all" box)" ] || fail "box rows differ from the default run"
    "$tu" filter-compare $sc --ss 2 --mip-filter box >"$tmp/box" 2>/dev/null
    [ "$(rows "$tmp/def" "")" = "$(rows "$tmp/box" box)" ] || fail "--mip-filter box differs from the default run"
    ! grep -q "^PSNR vs truth" "$tmp/box" || fail "a side-by-side table for one pyramid"
    for m in box_linear lanczos2; do
      # nearest, bilinear: the same PSNR vs truth, probes, texels, clocks (the float EWA column moves)
      for f in nearest bilinear; do
        [ "$(row "$tmp/all" box $f | awk '{print $2, $6, $7, $8}')" = "$(row "$tmp/all" $m $f | awk '{print $2, $6, $7, $8}')" ] ||
          fail "$f changed with $m"
      done
      # mipmapped engines: another PSNR vs truth (column 2 for trilinear, 3 after the space of "feline N<=8")
      for f in trilinear "feline N<=8" ewa; do
        [ "$(row "$tmp/all" box "$f" | sed "s/^$f//" | awk '{print $1}')" != "$(row "$tmp/all" $m "$f" | sed "s/^$f//" | awk '{print $1}')" ] ||
          fail "$f: the same PSNR vs truth with $m as with box"
      done
    done
    grep -q "^truth image: identical with every pyramid" "$tmp/all" || fail "truth: $(tail -1 "$tmp/all")"
    [ "$(grep -cE '^(nearest|bilinear|trilinear|feline N<=(2|4|8|16)|ewa|ewa K=4) +( +[0-9.]+ dB){3}$' "$tmp/all")" = 9 ] ||
      fail "summary: $(cat "$tmp/all")"
    "$tu" filter-compare docs/scenes/hud_floor.json --ss 1 --mip-filter box,box_linear >"$tmp/lin" 2>/dev/null
    [ "$(rows "$tmp/lin" box)" = "$(rows "$tmp/lin" box_linear)" ] || fail "box_linear differs from box on linear textures"
    ;;
  shard_vectors_cosim)
    # 4 shards == the unsharded run: vector rows tile the set in order; the merged co-simulation
    # (file split by `cosim --shard`, and per-shard vector files) equals the whole file's run
    # (sim_cycles and wall_s are sums over the shards' runs, not compared).
    "$tu" vectors --block reciprocal --set random --count 1003 --seed 3 --out "$tmp/all.vec" 2>/dev/null
    "$tu" cosim --block reciprocal --vectors "$tmp/all.vec" --seed 5 --json >"$tmp/all.json"
    for k in 0 1 2 3; do
      "$tu" vectors --block reciprocal --set random --count 1003 --seed 3 --shard $k/4 --out "$tmp/v$k.vec" 2>/dev/null
      grep -q "^# shard: $k/4 first $(( k * 1003 / 4 ))$" "$tmp/v$k.vec" || fail "shard header of v$k.vec"
      grep -v '^#' "$tmp/v$k.vec" >>"$tmp/rows.txt"
      "$tu" cosim --block reciprocal --vectors "$tmp/all.vec" --seed 5 --shard $k/4 --json >"$tmp/c$k.json"
      "$tu" cosim --block reciprocal --vectors "$tmp/v$k.vec" --seed 5 --json >"$tmp/f$k.json"
    done
    cmp -s <(grep -v '^#' "$tmp/all.vec") "$tmp/rows.txt" || fail "shard rows differ from the unsharded set"
    "$tu" merge "$tmp"/c{3,1,0,2}.json --json "$tmp/m.json"   # any order
    "$tu" merge "$tmp"/f{0,1,2,3}.json >"$tmp/mf.json"
    for m in m mf; do
      python3 - "$tmp/all.json" "$tmp/$m.json" <<'PY' || fail "merged $m differs from the unsharded run"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
skip = {"sim_cycles", "wall_s", "err_sum_sq"}
bad = [k for k in a if k not in skip and a[k] != b.get(k)]
close = abs(a["err_sum_sq"] - b["err_sum_sq"]) <= 1e-12 * a["err_sum_sq"]
if bad or not close or "shard" in b:
    sys.exit("differing keys: %s, err_sum_sq %s vs %s" % (bad, a["err_sum_sq"], b["err_sum_sq"]))
PY
    done
    # A missing, repeated or mixed shard is refused, naming it.
    if "$tu" merge "$tmp"/c{0,1,3}.json 2>"$tmp/err"; then fail "merged 3 of 4 shards"; fi
    grep -q "shards 2 of 4 are missing" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    if "$tu" merge "$tmp"/c{0,1,1,2,3}.json 2>"$tmp/err"; then fail "merged a shard twice"; fi
    grep -q "shard 1/4 given twice" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    if "$tu" cosim --block reciprocal --vectors "$tmp/v1.vec" --shard 0/2 --json 2>"$tmp/err" >/dev/null; then fail "split a shard file"; fi
    grep -q "already shard 1/4" "$tmp/err" || fail "message: $(cat "$tmp/err")"
    if "$tu" vectors --block reciprocal --shard 4/4 --out "$tmp/x.vec" 2>"$tmp/err"; then fail "accepted shard 4/4"; fi
    grep -q "need 0 <= K < N" "$tmp/err" && [ ! -e "$tmp/x.vec" ] || fail "message: $(cat "$tmp/err")"
    ;;
  shard_every_block)
    # Every block with RTL: a random set split by `cosim --shard` into 4 and merged equals the
    # whole file's co-simulation (span-continuing blocks split only where a run starts; shard 0 holds
    # >= 256 vectors, the stall-free prefix latency and II are measured on).
    for f in vectors/golden/*.vec; do
      b=$(basename "$f" .vec)
      "$tu" vectors --block "$b" --set random --count 1200 --seed 11 --out "$tmp/$b.vec" 2>/dev/null
      if ! "$tu" cosim --block "$b" --vectors "$tmp/$b.vec" --json >"$tmp/$b.all.json" 2>"$tmp/$b.err"; then
        grep -q "has no RTL co-simulation model" "$tmp/$b.err" && continue  # a C-model-only variant
        fail "$b: whole run"
      fi
      for k in 0 1 2 3; do "$tu" cosim --block "$b" --vectors "$tmp/$b.vec" --shard $k/4 --json >"$tmp/$b.$k.json" || fail "$b: shard $k"; done
      "$tu" merge "$tmp/$b".[0-3].json --json "$tmp/$b.m.json" || fail "$b: merge"
      python3 - "$tmp/$b.all.json" "$tmp/$b.m.json" <<'PY' || fail "$b: merged run differs from the whole run"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
bad = [k for k in a if k not in ("sim_cycles", "wall_s", "err_sum_sq") and a[k] != b.get(k)]
sys.exit("differing keys: %s" % bad if bad else 0)
PY
    done
    ;;
  shard_report)
    # Report groups round-robin over 4 shards, merged: the unsharded rows (timings excepted) and table.
    "$tu" report --blocks reciprocal,persp,ellipse --count 300 --no-yosys --json "$tmp/all.json" >/dev/null 2>&1
    for k in 0 1 2 3; do
      "$tu" report --blocks reciprocal,persp,ellipse --count 300 --no-yosys --shard $k/4 --json "$tmp/r$k.json" >/dev/null 2>&1
    done
    "$tu" merge "$tmp"/r{2,0,3,1}.json --json "$tmp/m.json" --markdown "$tmp/m.md" >/dev/null 2>&1
    python3 - "$tmp/all.json" "$tmp/m.json" <<'PY' || fail "merged report differs from the unsharded run"
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
t = lambda rows: [{k: v for k, v in r.items() if k not in ("cmodel_ns_per_item", "rtl_sim_items_per_s")} for r in rows]
sys.exit(0 if len(a) > 3 and t(a) == t(b) else 1)
PY
    grep -q "^## ellipse" "$tmp/m.md" && grep -q "texunit merge. of 4" "$tmp/m.md" || fail "merged markdown"
    if "$tu" merge "$tmp"/r0.json "$tmp"/r0.json --json "$tmp/x.json" 2>"$tmp/err"; then fail "merged a report shard twice"; fi
    grep -q "block 'reciprocal' is in shard files 1 and 2" "$tmp/err" && [ ! -e "$tmp/x.json" ] || fail "message: $(cat "$tmp/err")"
    ;;
  *) fail "unknown case" ;;
esac
echo "ok ($case)"
