// Clip volume, degree-3 polynomial (variant mm_p3), Horner form, fully pipelined (II = 1):
//   stage 1: t = c2 + floor(c3 * a)     stage 2: t = c1 + floor(t * a)
//   stage 3: t = c0 + floor(t * a)      stage 4: v = fold(round(t))
// (each stage one multiply-add: the coefficient joins the product's carry-save tree)
// Three multipliers, latency ClipHornerLatency = 4.
`include "tu_assert.svh"
module tu_clip_horner (
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
  localparam int Lat  = tu_formats_pkg::ClipHornerLatency;
  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  logic signed [tu_formats_pkg::ClipCoefW-1:0] c0, c1, c2, c3;
  tu_clip_coef_mm3 u_coef (.c0_o(c0), .c1_o(c1), .c2_o(c2), .c3_o(c3));

  logic [tu_formats_pkg::ClipAW-1:0] a, a_q1, a_q2;
  logic neg, neg_q1, neg_q2, neg_q3;
  logic signed [AccW-1:0] t1, t2, t3, t_q1, t_q2, t_q3, acc;
  logic [tu_formats_pkg::ClipOutW-1:0] v_d, v_q4;
  tu_clip_abs u_abs (.d_i, .a_o(a), .neg_o(neg));
  // Each stage adds the next coefficient inside its multiply-add (tu_clip_mulfloor's c_i): the
  // registers hold c2 + t1, c1 + t2, c0 + t3 (the same sums modulo 2^ClipAccW).
  tu_clip_mulfloor u_m1 (.x_i(AccW'(c3)), .a_i(a), .c_i(AccW'(c2)), .y_o(t1));
  tu_clip_mulfloor u_m2 (.x_i(t_q1), .a_i(a_q1), .c_i(AccW'(c1)), .y_o(t2));
  tu_clip_mulfloor u_m3 (.x_i(t_q2), .a_i(a_q2), .c_i(AccW'(c0)), .y_o(t3));
  assign acc = t_q3;
  tu_clip_fold u_fold (.acc_i(acc), .neg_i(neg_q3), .v_o(v_d));

  always_ff @(posedge clk_i) begin
    if (en) begin
      t_q1 <= t1;  a_q1 <= a;    neg_q1 <= neg;
      t_q2 <= t2;  a_q2 <= a_q1; neg_q2 <= neg_q1;
      t_q3 <= t3;                neg_q3 <= neg_q2;
      v_q4 <= v_d;
    end
  end
  assign v_o = v_q4;

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {v_o})
endmodule
