// The EWA normalisation's products (ewa::fx::normalise, cmodel/blocks/ewa/ewa_fx.cpp), split over
// two register levels so that no clock holds a product, a carry chain and a variable shift:
//   channel = min(255, floor((acc_c R + 2^(sh-1)) / 2^sh)),  sh = RecipOutF + p,  p = msb(wsum)
// with R = sat(round_half_up(y / 2^6)) from the reciprocal core's unrounded y (tu_recip_core_y).
//   clock A (K - p, acc_i): a_c = acc_c 2^(K-p) (K = WsumW - 1, exact, < 2^(K+9) unless big_c),
//                          big_c = acc_c >= 2^(p+9): then acc_c R >= 2^(p+9) 2^23 = 256 2^sh
//                          (R >= 2^23 for every mantissa), so the channel saturates to 255
//   clock B (y_i):         a_c R + 2^(RecipOutF+K-1) as a carry-save pair: rows a_c R_hi[j] 2^j,
//                          a_c y[5] (R = R_hi + y[5], R_hi = floor(y / 2^6): the core's rounding
//                          without its carry chain; no saturation, 2^23 <= R <= 2^24) and the
//                          rounding term, 3:2 compressor levels (rtl/common/tu_csa.svh, as in
//                          tu_persp_pixel)
//   clock C (rgba_o):      x = sum + carry (the one carry chain), x >> (RecipOutF + K) (a fixed
//                          shift: a_c is pre-shifted), saturate at 255; combinational, the caller
//                          registers it
// so the same integers: acc_c R / 2^sh = a_c R / 2^(RecipOutF + K).
// Timing: p_i in clock A - 1 and A (each channel registers its own copy of K - p_i every clock: one
// flip-flop per channel drives that channel's shifter only), acc_i in clock A; y_i (the core's
// stage-3 register) in clock A + 1; rgba_o in A + 2.
module tu_ewa_norm_tail #(
  parameter int AccW  = tu_formats_pkg::EwaAccW,   // per-channel weighted sum
  parameter int WsumW = tu_formats_pkg::EwaWsumW   // weight sum (p <= WsumW - 1)
) (
  input  logic                                        clk_i,
  input  logic [6:0]                                  p_i,    // clock A - 1 (held through A)
  input  logic [4*AccW-1:0]                           acc_i,  // channel c at [c AccW +: AccW]
  input  logic signed [tu_formats_pkg::RecipC0W+1:0]  y_i,
  output logic [31:0]                                 rgba_o
);
  localparam int K    = WsumW - 1;
  localparam int AW   = K + 9;                          // pre-shifted sum
  localparam int RW   = tu_formats_pkg::RecipOutW;
  localparam int YW   = tu_formats_pkg::RecipC0W + 2;
  localparam int RndShift = tu_formats_pkg::RecipC0F - tu_formats_pkg::RecipOutF;
  localparam int Sh   = tu_formats_pkg::RecipOutF + K;  // fixed shift
  localparam int SW   = AW + RW;                        // a R + 2^(Sh-1) < 2^(AW+RW-1) + 2^(Sh-1)

  // ---- clock B: carry-save pair of a R + 2^(Sh-1)
  // tu_csa.svh: the rows and the compressor tree, shared with tu_persp_pixel.
  localparam int CsaW = SW;
  localparam int CsaM = RW;
  localparam int CsaB = 1;
`include "tu_csa.svh"
  logic [RW-1:0] rh;
  logic          rb;
  assign rh = RW'(y_i >>> RndShift);
  assign rb = y_i[RndShift-1];

  for (genvar c = 0; c < 4; c++) begin : g_ch
    // clock A - 1: the shift amount K - p, one register per channel (keep: Yosys would merge
    // the four identical flip-flops back into one driving all four shifters)
    logic [6:0]        sh_q;
    (* keep *) always_ff @(posedge clk_i) sh_q <= 7'(K) - p_i;
    // clock A: pre-shift, overflow flag
    logic [AccW+K-1:0] ax;
    logic [AW-1:0]     a_q;
    logic              big_q, big2_q;
    assign ax = (AccW+K)'(acc_i[c*AccW +: AccW]) << sh_q;
    always_ff @(posedge clk_i) begin
      a_q   <= AW'(ax);
      big_q <= (ax >> AW) != '0;
    end
    // clock B: carry-save pair
    logic [SW-1:0] s_d, c_d, s_q, c_q;
    assign {c_d, s_d} = csa_mul(SW'(a_q), rh, rb, SW'(1) << (Sh - 1));
    always_ff @(posedge clk_i) begin
      s_q    <= s_d;
      c_q    <= c_d;
      big2_q <= big_q;
    end
    // clock C: the carry chain, a fixed shift, saturation
    logic [SW-1:0]    x;
    logic [SW-Sh-1:0] hi;
    assign x  = s_q + c_q;
    assign hi = x[SW-1:Sh];
    assign rgba_o[8*c +: 8] = big2_q || hi > (SW-Sh)'(255) ? 8'd255 : hi[7:0];
    logic unused_lo;
    assign unused_lo = ^x[Sh-1:0];
  end

  logic unused;
  assign unused = ^{y_i[YW-1:RW+RndShift]};
endmodule
