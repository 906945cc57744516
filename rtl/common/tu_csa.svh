// Carry-save multiply-add, the one description used by the perspective pixel pipeline (S7,
// tu_persp_pixel) and the EWA normalisation (clock B, tu_ewa_norm_tail): a clock that must hold a
// product but not its carry chain leaves x = a m + b0 a + add as a {carry, sum} pair with
// sum + carry = x (mod 2^CsaW); the next clock adds the pair.
// Included inside a module body that declares, before the `include:
//   localparam int CsaW  word length of a (already extended: sign or zero), add, sum and carry
//   localparam int CsaM  bits of the multiplier m
//   localparam int CsaB  1: a row b0 a after the CsaM rows (tu_ewa_norm_tail's rounding bit), 0: none
// Rows: a m[j] 2^j for j < CsaM, then (CsaB) b0 a, then add; every 3 rows become 2 (sum,
// carry << 1) per level of 3:2 compressors until 2 are left, all modulo 2^CsaW. Live rows stay at
// the front: the groups of 3 before the last live row are full, a group with 1 or 2 live rows
// passes them on, groups of zeros give zeros (constant-folded by synthesis).
// The rows are an unpacked array of words, not one packed vector of CsaRows words, so that the
// simulator (Verilator) does not shift and mask the whole 1,700-2,100-bit vector for each row
// (afvis, 3,000 random vectors: 5.79 -> 4.71 CPU s; the unrolled tree is still most of an
// engine's simulation).
// TU_SIM_PRODUCT_MUL (simulation only; testbench/cosim/CMakeLists.txt defines it for the
// Vtu_texture_unit* models and the EWA engine models Vtu_ewa, Vtu_ewa_k4, Vtu_afvis, Vtu_feline):
// the same x as one product, returned as sum = x, carry = 0; every user adds sum and carry (or
// their low bits' carry) before it looks at x, so its outputs are bit-identical. The block models
// Vtu_persp, Vtu_persp_klane, Vtu_objspace_sample and Vtu_ewa_normalise (ewa_normalise_rtl_test),
// Icarus, Yosys and the gate level keep the tree (docs/performance.md section 11).
// No include guard on purpose: each including module gets its own copy (its own widths).
`ifdef TU_SIM_PRODUCT_MUL
function automatic logic [2*CsaW-1:0] csa_mul(input logic [CsaW-1:0] a, input logic [CsaM-1:0] m,
                                              input logic b0, input logic [CsaW-1:0] add);
  csa_mul = {CsaW'(0), a * CsaW'(m) + ((CsaB != 0 && b0) ? a : CsaW'(0)) + add};
endfunction
`else
localparam int CsaRows = CsaM + CsaB + 1;
// levels of 3:2 compressors that bring n rows down to 2
function automatic int csa_levels(input int n0);
  int n, l;
  n = n0;
  l = 0;
  for (int i = 0; i < 64; i++) begin
    if (n > 2) begin
      n = (n / 3) * 2 + n % 3;
      l = l + 1;
    end
  end
  csa_levels = l;
endfunction
localparam int CsaLvl = csa_levels(CsaRows);

function automatic logic [2*CsaW-1:0] csa_mul(input logic [CsaW-1:0] a, input logic [CsaM-1:0] m,
                                              input logic b0, input logic [CsaW-1:0] add);
  logic [CsaW-1:0] cur [CsaRows];
  logic [CsaW-1:0] nxt [CsaRows];
  logic [CsaW-1:0] x, y, z;
  for (int j = 0; j < CsaM; j++) cur[j] = {CsaW{m[j]}} & (a << j);
  if (CsaB != 0) cur[CsaRows-2] = {CsaW{b0}} & a;
  cur[CsaRows-1] = add;
  for (int l = 0; l < CsaLvl; l++) begin
    for (int i = 0; i < CsaRows; i++) nxt[i] = '0;
    for (int g = 0; g < CsaRows / 3; g++) begin
      x = cur[3*g];
      y = cur[3*g+1];
      z = cur[3*g+2];
      nxt[2*g]   = x ^ y ^ z;
      nxt[2*g+1] = ((x & y) | (x & z) | (y & z)) << 1;
    end
    for (int k = 0; k < CsaRows % 3; k++) nxt[2*(CsaRows/3)+k] = cur[3*(CsaRows/3)+k];
    for (int i = 0; i < CsaRows; i++) cur[i] = nxt[i];
  end
  csa_mul = {cur[1], cur[0]};
endfunction
`endif
