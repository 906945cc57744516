// Gaussian pixel-model weight from a 2-D quarter-symmetric table indexed by (|xi|, |eta|), bilinear
// interpolation, II = 1, latency 4. Exactly gauss::Table2D(kWtab2dRtlLog2N)::lookup
// (cmodel/blocks/gauss/weight.cpp, docs/blocks/gaussian.md); Fb = GaussXiF - Log2N:
//   stage 1: x = |xi|, y = |eta|; i = x >> Fb, j = y >> Fb, fx, fy = low Fb bits;
//            ROM row {j, i} -> the cell corners e00, e10, e01, e11                 (registered)
//   stage 2: p0 = (e10 - e00) * fx + 2^(Fb-1), p1 = (e11 - e01) * fx + 2^(Fb-1) (signed; the
//            rounding term inside the multiply-add), d = e01 - e00                   (registered)
//   stage 3: r0 = e00 + floor(p0 / 2^Fb) (r1 = e01 + floor(p1 / 2^Fb) likewise);
//            p2 = (r1 - r0) * fy + 2^(Fb-1) with r1 - r0 = d + floor(p1 / 2^Fb) - floor(p0 / 2^Fb)
//            (one three-input add before the multiply-add, not r0, r1 and their difference in
//            series; r0, r1 are lerps between two entries, so in [0, 2^EW): no wrap) (registered)
//   stage 4: w = r0 + floor(p2 / 2^Fb), 0 if x > 1 or y > 1                         (registered)
// The ROM tu_wtab2d_rom is generated from the C model's table (`texunit gen-rtl`).
`include "tu_assert.svh"
module tu_weight_table_2d #(
  parameter int Log2N = 5  // N = 2^Log2N cells per axis (+1 entries); gauss::kWtab2dRtlLog2N
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic                                   in_valid_i,
  output logic                                   in_ready_o,
  input  logic [tu_formats_pkg::GaussXiW-1:0]    xi_i,
  input  logic [tu_formats_pkg::GaussXiW-1:0]    eta_i,
  output logic                                   out_valid_o,
  input  logic                                   out_ready_i,
  output logic [tu_formats_pkg::WtabEntryW-1:0]  w_o
);
  localparam int XW   = tu_formats_pkg::GaussXiW;
  localparam int XF   = tu_formats_pkg::GaussXiF;
  localparam int EW   = tu_formats_pkg::WtabEntryW;
  localparam int Fb   = XF - Log2N;      // interpolation fraction bits
  localparam int AW   = Log2N + 1;       // cell index 0..N
  localparam int DW   = EW + 1;          // e1 - e0, signed
  localparam int PW   = DW + Fb + 1;     // (e1 - e0) * f, signed
  localparam int Lat  = 4;
  logic           en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- stage 1: |xi|, |eta|, ROM read
  logic [XW-1:0] x, y;
  logic          out_d, out_q1, out_q2, out_q3;
  logic [EW-1:0] e00_rom, e10_rom, e01_rom, e11_rom;
  logic [EW-1:0] e00_q1, e10_q1, e01_q1, e11_q1, e00_q2, r0_q3;
  logic [Fb-1:0] fx_q1, fy_q1, fy_q2;
  assign x     = xi_i[XW-1]  ? XW'(-xi_i)  : xi_i;
  assign y     = eta_i[XW-1] ? XW'(-eta_i) : eta_i;
  assign out_d = (x > XW'(1 << XF)) || (y > XW'(1 << XF));
  tu_wtab2d_rom u_rom (
    .idx_i({y[Fb +: AW], x[Fb +: AW]}),
    .e00_o(e00_rom), .e10_o(e10_rom), .e01_o(e01_rom), .e11_o(e11_rom)
  );

  // ---- stage 2: the two x-lerp multiply-adds (with the rounding term), the y difference
  logic signed [DW-1:0] dx0, dx1, dy0_d, dy0_q2;
  logic signed [PW-1:0] p0_d, p1_d, p0_q2, p1_q2;
  assign dx0   = $signed({1'b0, e10_q1}) - $signed({1'b0, e00_q1});
  assign dx1   = $signed({1'b0, e11_q1}) - $signed({1'b0, e01_q1});
  assign dy0_d = $signed({1'b0, e01_q1}) - $signed({1'b0, e00_q1});
  assign p0_d  = PW'(dx0) * $signed({1'b0, fx_q1}) + PW'(1 << (Fb - 1));
  assign p1_d  = PW'(dx1) * $signed({1'b0, fx_q1}) + PW'(1 << (Fb - 1));

  // ---- stage 3: round the x-lerps, y-lerp multiply
  logic [EW-1:0]        r0_d;
  logic signed [DW-1:0] dy;
  logic signed [PW-1:0] p2_d, p2_q3;
  // the C model's lerp: e + floor((p + 2^(Fb-1)) / 2^Fb), the 2^(Fb-1) already in p
  logic signed [PW-1:0] rnd0, rnd1, rnd2;
  assign rnd0 = p0_q2 >>> Fb;
  assign rnd1 = p1_q2 >>> Fb;
  assign r0_d = EW'(PW'($signed({1'b0, e00_q2})) + rnd0);
  assign dy   = DW'(PW'(dy0_q2) + rnd1 - rnd0);  // r1 - r0
  assign p2_d = PW'(dy) * $signed({1'b0, fy_q2}) + PW'(1 << (Fb - 1));

  // ---- stage 4: round the y-lerp, zero outside [-1, 1]^2
  logic [EW-1:0] w_d, w_q4;
  assign rnd2 = p2_q3 >>> Fb;
  assign w_d  = out_q3 ? '0 : EW'(PW'($signed({1'b0, r0_q3})) + rnd2);

  always_ff @(posedge clk_i) begin
    if (en) begin
      e00_q1 <= e00_rom;  e10_q1 <= e10_rom;  e01_q1 <= e01_rom;  e11_q1 <= e11_rom;
      fx_q1  <= x[Fb-1:0];  fy_q1 <= y[Fb-1:0];  out_q1 <= out_d;
      e00_q2 <= e00_q1;  dy0_q2 <= dy0_d;  p0_q2 <= p0_d;  p1_q2 <= p1_d;
      fy_q2  <= fy_q1;   out_q2 <= out_q1;
      r0_q3  <= r0_d;    p2_q3 <= p2_d;   out_q3 <= out_q2;
      w_q4   <= w_d;
    end
  end
  assign w_o = w_q4;

  logic unused;
  assign unused = ^{stage_valid, x[XW-1:Fb+AW], y[XW-1:Fb+AW]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {w_o})
endmodule
