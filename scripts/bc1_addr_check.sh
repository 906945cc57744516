#!/usr/bin/env bash
# tu_bc1_addr (the texture unit's BC1 block address, docs/blocks/texture.md "BC1 in the unit")
# against the layouts it joins, in Icarus Verilog: for every texel (x, y) of every level of every
# texture 2^lw x 2^lh with lw, lh in 0..7 (and 20,000 random texels of textures up to 4096 x 4096,
# random bases), the texel address of tu_texel_addr's layout (tex::texel_addr: base +
# levelbase(L) + y * width_L + x; the border colour at base - 1) must map to the block word
# base + blockbase(L) + (y >> 2) * max(1, width_L / 4) + (x >> 2) and texel 4 (y & 3) + (x & 3)
# (tex::bc1_texel, the C model's block order in Texture::words). Prints the vector count and the
# mismatches; exit 1 on a mismatch.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v iverilog >/dev/null || { echo "SKIP: iverilog not installed"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp/vec.hex" <<'PY'
import random, sys
AW = 26
def lbase(lw, lh, L):
    return sum(1 << (max(0, lw - k) + max(0, lh - k)) for k in range(L))
def bbase(lw, lh, L):
    return sum(1 << (max(0, max(0, lw - k) - 2) + max(0, max(0, lh - k) - 2)) for k in range(L))
def vec(base, lw, lh, L, x, y):
    wl, hl = max(0, lw - L), max(0, lh - L)
    a = base + lbase(lw, lh, L) + (y << wl) + x
    blk = bbase(lw, lh, L) + (y >> 2) * max(1, (1 << wl) >> 2) + (x >> 2)
    return a % (1 << AW), (base + blk) % (1 << AW), 4 * (y & 3) + (x & 3)
rng = random.Random(24)
rows = []
def emit(base, lw, lh, a, e, t):
    rows.append("%07x %07x %x %x %07x %x" % (a, base, lw, lh, e, t))
for lw in range(8):
    for lh in range(8):
        base = rng.randrange(1, 1 << 22)
        emit(base, lw, lh, base - 1, base - 1, 0)  # the border colour
        for L in range(max(lw, lh) + 1):
            for y in range(1 << max(0, lh - L)):
                for x in range(1 << max(0, lw - L)):
                    emit(base, lw, lh, *vec(base, lw, lh, L, x, y))
for _ in range(20000):
    lw, lh = rng.randrange(13), rng.randrange(13)
    base = rng.randrange(1, (1 << AW) - 23000000)
    L = rng.randrange(max(lw, lh) + 1)
    x, y = rng.randrange(1 << max(0, lw - L)), rng.randrange(1 << max(0, lh - L))
    emit(base, lw, lh, *vec(base, lw, lh, L, x, y))
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
print(len(rows), file=open(sys.argv[1] + ".n", "w"))
PY
n=$(cat "$tmp/vec.hex.n")
cat >"$tmp/tb.sv" <<SV
module tb;
  logic [25:0] addr, base, exp_addr, got_addr;
  logic [3:0]  lw, lh, exp_t, got_t;
  integer f, r, n, bad;
  tu_bc1_addr dut (.addr_i(addr), .base_i(base), .lw_i(lw), .lh_i(lh), .addr_o(got_addr), .texel_o(got_t));
  initial begin
    f = \$fopen("$tmp/vec.hex", "r");
    n = 0; bad = 0;
    while (\$fscanf(f, "%h %h %h %h %h %h\n", addr, base, lw, lh, exp_addr, exp_t) == 6) begin
      #1;
      if (got_addr !== exp_addr || got_t !== exp_t) begin
        if (bad < 5) \$display("MISMATCH addr %h base %h lw %0d lh %0d: got %h/%0d expected %h/%0d", addr, base, lw, lh, got_addr, got_t, exp_addr, exp_t);
        bad = bad + 1;
      end
      n = n + 1;
    end
    \$display("tu_bc1_addr: %0d vectors, %0d mismatches", n, bad);
    \$finish;
  end
endmodule
SV
iverilog -g2012 -o "$tmp/sim" rtl/0_pkg/tu_formats_pkg.sv rtl/top/tu_bc1_addr.sv "$tmp/tb.sv" 2>&1 | grep -v sorry || true
vvp -n "$tmp/sim" | tee "$tmp/out"
grep -q " $n vectors, 0 mismatches" "$tmp/out"
