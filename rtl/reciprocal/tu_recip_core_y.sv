// Reciprocal core up to its unrounded result: tu_recip_core's stages 1-3, y = c0 + floor(s dx)
// in RecipC0F fraction bits, three pipeline stages. tu_recip_core's stage 4 is
// R = sat(round_half_up(y)) to RecipOutF fraction bits; the EWA normalisation (tu_ewa_norm_tail)
// takes y instead and folds that rounding into its product:
// for a normalised mantissa R = floor(y / 2^6) + y[5] (never saturates: 2^23 <= R <= 2^24,
// testbench/unit/reciprocal_test.cpp CoreRoundingIsCarryBit, every mantissa).
//   stage 1: ROM lookup (c0, c1, c2) by the top RecipIdxW fraction bits, dx = the rest
//   stage 2: s  = c1 + floor(c2 * dx)      (t1 truncated to RecipT1F fraction bits)
//   stage 3: y  = c0 + floor(s * dx)       (t2 truncated to RecipT2F fraction bits)
`include "tu_assert.svh"

module tu_recip_core_y
(
  input  logic                                            clk_i,
  input  logic                                            en_i,
  input  logic [tu_formats_pkg::RecipMantW-1:0]           m_i,
  output logic signed [tu_formats_pkg::RecipC0W+1:0]      y_o
);
  localparam int P1W = tu_formats_pkg::RecipC2W + tu_formats_pkg::RecipDxW;            // c2 * dx
  localparam int P1F = tu_formats_pkg::RecipC2F + tu_formats_pkg::RecipMantW - 1;
  localparam int P2W = tu_formats_pkg::RecipSW + tu_formats_pkg::RecipDxW + 1;         // s * dx (signed)
  localparam int P2F = tu_formats_pkg::RecipC1F + tu_formats_pkg::RecipMantW - 1;
  localparam int YW  = tu_formats_pkg::RecipC0W + 2;                   // c0 + t2 (signed)

  // Stage 1: ROM
  logic [tu_formats_pkg::RecipC0W-1:0]        c0_rom;
  logic signed [tu_formats_pkg::RecipC1W-1:0] c1_rom;
  logic [tu_formats_pkg::RecipC2W-1:0]        c2_rom;
  tu_recip_rom u_rom (
    .idx_i (m_i[tu_formats_pkg::RecipDxW +: tu_formats_pkg::RecipIdxW]),
    .c0_o  (c0_rom),
    .c1_o  (c1_rom),
    .c2_o  (c2_rom)
  );

  logic [tu_formats_pkg::RecipC0W-1:0]        c0_q1, c0_q2;
  logic signed [tu_formats_pkg::RecipC1W-1:0] c1_q1;
  logic [tu_formats_pkg::RecipC2W-1:0]        c2_q1;
  logic [tu_formats_pkg::RecipDxW-1:0]        dx_q1, dx_q2;

  // Stage 2: s = c1 + t1
  logic [P1W-1:0]              p1;
  logic [tu_formats_pkg::RecipT1W-1:0]         t1;
  logic signed [tu_formats_pkg::RecipSW-1:0]   s_d, s_q2;
  assign p1  = c2_q1 * dx_q1;
  assign t1  = tu_formats_pkg::RecipT1W'(p1 >> (P1F - tu_formats_pkg::RecipT1F));
  assign s_d = c1_q1 + $signed({{(tu_formats_pkg::RecipSW - tu_formats_pkg::RecipT1W){1'b0}}, t1});

  // Stage 3: y = c0 + t2 as one multiply-add, c0 2^T2Sh + s dx, whose top YW bits are y:
  // c0 2^T2Sh has no bits below T2Sh, so floor((c0 2^T2Sh + p2) / 2^T2Sh) = c0 + floor(p2 / 2^T2Sh)
  // = c0 + t2 (t2 keeps every bit of p2 >>> T2Sh: P2W - T2Sh = RecipT2W, checked below).
  // Synthesis (maccmap) then builds one carry-save tree and one carry chain, where the product
  // truncated and then added kept two chains: tu_reciprocal 163.3 -> 173.9 MHz (critical path
  // now stage 2), tu_persp_klane 147.1 MHz before (docs/area-timing.md).
  localparam int T2Sh = P2F - tu_formats_pkg::RecipT2F;
  localparam int XW   = YW + T2Sh;
  logic signed [P2W-1:0]       p2;
  logic signed [XW-1:0]        x3;
  logic signed [YW-1:0]        y_d, y_q3;
  assign p2  = P2W'(s_q2) * $signed({1'b0, dx_q2});
  assign x3  = $signed({2'b00, c0_q2, T2Sh'(0)}) + XW'(p2);
  assign y_d = x3[XW-1:T2Sh];
  `TU_ASSERT_PARAM(g_t2_whole, P2W - T2Sh == tu_formats_pkg::RecipT2W,
                   "t2 = p2 >>> T2Sh must keep every bit of p2 for the fused c0 add")

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      c0_q1 <= c0_rom;
      c1_q1 <= c1_rom;
      c2_q1 <= c2_rom;
      dx_q1 <= m_i[tu_formats_pkg::RecipDxW-1:0];
      s_q2  <= s_d;
      c0_q2 <= c0_q1;
      dx_q2 <= dx_q1;
      y_q3  <= y_d;
    end
  end

  assign y_o = y_q3;

  // The fraction below y: its carry is all the sum needs from it.
  logic unused_low;
  assign unused_low = ^x3[T2Sh-1:0];

  // The leading one of M is implicit in the table index.
  logic unused_msb;
  assign unused_msb = m_i[tu_formats_pkg::RecipMantW-1];
endmodule
