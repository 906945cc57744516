// Gaussian pixel-model weight from a 1-D table indexed by Q (no square root), linear
// interpolation, II = 1, latency 3. Exactly gauss::Table1D(kWtabRtlLog2N)::lookup
// (cmodel/blocks/gauss/weight.cpp, docs/blocks/gaussian.md):
//   stage 1: idx = Q >> Fb, f = Q mod 2^Fb; ROM row idx -> e0 = e[idx], e1 = e[idx+1] (registered)
//   stage 2: d = (e1 - e0) * f (signed)                                           (registered)
//   stage 3: w = e0 + floor((d + 2^(Fb-1)) / 2^Fb), 0 if Q > 1                     (registered)
// The ROM tu_wtab1d_rom is generated from the C model's table (`texunit gen-rtl`).
`include "tu_assert.svh"
module tu_weight_table_1d #(
  parameter int Log2N = 8  // table size N = 2^Log2N (+1 entries); gauss::kWtabRtlLog2N
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic                                   in_valid_i,
  output logic                                   in_ready_o,
  input  logic [tu_formats_pkg::GaussQW-1:0]     q_i,
  output logic                                   out_valid_o,
  input  logic                                   out_ready_i,
  output logic [tu_formats_pkg::WtabEntryW-1:0]  w_o
);
  localparam int QF  = tu_formats_pkg::GaussQF;
  localparam int EW  = tu_formats_pkg::WtabEntryW;
  localparam int Fb  = QF - Log2N;        // interpolation fraction bits
  localparam int IdxW = Log2N + 1;        // 0..N
  localparam int DW  = EW + 1;            // e1 - e0, signed
  localparam int PW  = DW + Fb + 1;       // (e1 - e0) * f, signed
  localparam int Lat = 3;
  logic           en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- stage 1: ROM read
  logic          out_d, out_q1, out_q2;
  logic [EW-1:0] e0_rom, e1_rom, e0_q1, e1_q1, e0_q2;
  logic [Fb-1:0] f_q1;
  assign out_d = q_i > tu_formats_pkg::GaussQW'(1 << QF);
  tu_wtab1d_rom u_rom (.idx_i(q_i[Fb +: IdxW]), .e0_o(e0_rom), .e1_o(e1_rom));

  // ---- stage 2: lerp multiply
  logic signed [DW-1:0] diff;
  logic signed [PW-1:0] prod_d, prod_q2;
  assign diff   = $signed({1'b0, e1_q1}) - $signed({1'b0, e0_q1});
  assign prod_d = PW'(diff) * $signed({1'b0, f_q1});

  // ---- stage 3: round half up, add, zero outside the ellipse
  logic signed [PW-1:0] rnd;
  logic [EW-1:0]        w_d, w_q3;
  assign rnd = (prod_q2 + PW'(1 << (Fb - 1))) >>> Fb;
  assign w_d = out_q2 ? '0 : EW'(PW'($signed({1'b0, e0_q2})) + rnd);

  always_ff @(posedge clk_i) begin
    if (en) begin
      e0_q1 <= e0_rom;  e1_q1 <= e1_rom;  f_q1 <= q_i[Fb-1:0];  out_q1 <= out_d;
      e0_q2 <= e0_q1;   prod_q2 <= prod_d;                      out_q2 <= out_q1;
      w_q3  <= w_d;
    end
  end
  assign w_o = w_q3;

  logic unused;
  assign unused = ^{stage_valid, q_i[tu_formats_pkg::GaussQW-1:Fb+IdxW]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {w_o})
endmodule
