// Clip volume, 3-segment piecewise linear (variant mm_p1): comparator + segment table + one
// multiply-add. Stage 1: |d|, segment select, m = floor(c1 * a). Stage 2: c0 + m, round, fold.
// Latency ClipP1Latency = 2, II = 1.
`include "tu_assert.svh"
module tu_clip_p1 (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::ClipInW-1:0]  d_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::ClipOutW-1:0] v_o
);
  localparam int AccW = tu_formats_pkg::ClipAccW;
  logic en;
  logic [tu_formats_pkg::ClipP1Latency-1:0] stage_valid;
  tu_pipe_valid #(.Depth(tu_formats_pkg::ClipP1Latency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  logic [tu_formats_pkg::ClipAW-1:0] a;
  logic neg, neg_q1;
  logic signed [tu_formats_pkg::ClipCoefW-1:0] c0, c1;
  logic signed [AccW-1:0] m, m_q1, c0_q1, acc;
  logic [tu_formats_pkg::ClipOutW-1:0] v_d, v_q2;
  tu_clip_abs u_abs (.d_i, .a_o(a), .neg_o(neg));
  tu_clip_seg_mm1 u_seg (.a_i(a), .c0_o(c0), .c1_o(c1));
  tu_clip_mulfloor u_mul (.x_i(AccW'(c1)), .a_i(a), .c_i(AccW'(0)), .y_o(m));
  assign acc = c0_q1 + m_q1;
  tu_clip_fold u_fold (.acc_i(acc), .neg_i(neg_q1), .v_o(v_d));

  always_ff @(posedge clk_i) begin
    if (en) begin
      m_q1   <= m;
      c0_q1  <= AccW'(c0);
      neg_q1 <= neg;
      v_q2   <= v_d;
    end
  end
  assign v_o = v_q2;

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {v_o})
endmodule
