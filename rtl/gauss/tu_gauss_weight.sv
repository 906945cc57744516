// Gaussian pixel-model weight w = (1 - Q/2)^8 (0 for Q > 1), three squarings, II = 1.
//   stage 1: t = 1 - Q/2 (u16.15), s1 = round_half_up(t^2)  (u17.16), formed without t as one
//            carry-save sum of the input's bits: with q = Q's raw code (GaussQF = 14 fraction
//            bits; Q/2 has GaussTF = 15 with the same code), q' = q mod 2^14 and q < 2^14,
//              t^2 = (2^15 - q)^2 = q'^2 - 2^16 q' + 2^30,
//            q'^2 as a squarer (q'_i 2^(2i) and q'_i q'_j 2^(i+j+1), i < j: half the partial
//            products of a multiplier, so each input bit drives about 14 gates, not 32), and
//            q = 2^14 (q' = 0, t^2 = 2^28) by the row q_14 (2^28 - 2^30) (mod 2^32); the rounding
//            constant is one more row. The same t^2 for every q <= 2^14; q > 2^14 (Q > 1) gives
//            w = 0 whatever s1 is (every code: GaussWeightRtl.EveryQCodeEqualsCModel).
//   stage 2: s2 = round_half_up(s1^2)     stage 3: w = round_half_up(s2^2), 0 outside
// Latency GaussLatency = 3.
`include "tu_assert.svh"
module tu_gauss_weight (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::GaussQW-1:0]  q_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::GaussSqW-1:0] w_o
);
  localparam int SqW = tu_formats_pkg::GaussSqW;
  localparam int SqF = tu_formats_pkg::GaussSqF;
  localparam int TW  = tu_formats_pkg::GaussTW;
  localparam int TF  = tu_formats_pkg::GaussTF;
  localparam int Lat = tu_formats_pkg::GaussLatency;
  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  logic out_d, out_q1, out_q2;
  logic [2*TW-1:0] p1;
  logic [2*SqW-1:0] p2, p3;
  logic [SqW-1:0] s1, s2, s3, s1_q, s2_q, w_q;
  assign out_d = q_i > tu_formats_pkg::GaussQW'(1 << tu_formats_pkg::GaussQF);
  // p1 = t^2 + 2^(2 TF - SqF - 1) (the rounding) modulo 2^(2 TW), q <= 2^QF
  localparam int QF = tu_formats_pkg::GaussQF;  // TF = QF + 1 (Q/2's code is Q's)
  localparam int PW = 2 * TW;
  logic [QF-1:0] qm;
  assign qm = q_i[QF-1:0];
  always_comb begin
    p1 = PW'((64'd1 << (2*TF)) + (64'd1 << (2*TF - SqF - 1))) - (PW'(qm) << (TF + 1))
       + (q_i[QF] ? PW'((64'd1 << (2*QF)) - (64'd1 << (2*TF))) : PW'(0));
    for (int i = 0; i < QF; i++) begin
      p1 = p1 + ({PW{qm[i]}} & (((PW'(qm) >> (i + 1)) << (2*i + 2)) | (PW'(1) << (2*i))));
    end
  end
  assign s1 = SqW'(p1 >> (2*TF - SqF));
  assign p2 = s1_q * s1_q;
  assign s2 = SqW'((p2 + (2*SqW)'(1 << (SqF - 1))) >> SqF);
  assign p3 = s2_q * s2_q;
  assign s3 = SqW'((p3 + (2*SqW)'(1 << (SqF - 1))) >> SqF);

  always_ff @(posedge clk_i) begin
    if (en) begin
      s1_q <= s1;  out_q1 <= out_d;
      s2_q <= s2;  out_q2 <= out_q1;
      w_q  <= out_q2 ? '0 : s3;
    end
  end
  assign w_o = w_q;

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {w_o})
endmodule
