// Clip volume, degree-3 polynomial (mm_p3 coefficients), parallel / Estrin form (II = 1):
//   stage 1: a2 = floor(a * a), u = c2 + floor(c3 * a), w = c0 + floor(c1 * a)  (three multipliers)
//   stage 2: t = w + floor(u * a2)                                        (one multiplier)
//   stage 3: v = fold(round(t))
// (each coefficient and w join a product's carry-save tree: one carry chain per stage)
// Four multipliers, latency ClipEstrinLatency = 3 (one less than Horner).
`include "tu_assert.svh"
module tu_clip_estrin (
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
  localparam int AW   = tu_formats_pkg::ClipAW;
  localparam int Lat  = tu_formats_pkg::ClipEstrinLatency;
  localparam int F    = tu_formats_pkg::ClipCoefF;
  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  logic signed [tu_formats_pkg::ClipCoefW-1:0] c0, c1, c2, c3;
  tu_clip_coef_mm3 u_coef (.c0_o(c0), .c1_o(c1), .c2_o(c2), .c3_o(c3));

  logic [AW-1:0] a;
  logic neg, neg_q1, neg_q2;
  localparam int A2W = 2 * AW - (2 * tu_formats_pkg::ClipInF - F);  // floor(a * a) to F bits
  localparam int HW  = 2 * AccW;
  logic [2*AW-1:0] a2_full;
  logic [A2W-1:0] a2, a2_q1;
  logic signed [AccW-1:0] u, w, u_q1, w_q1, t, t_q2;
  logic signed [HW-1:0] hp;
  logic [tu_formats_pkg::ClipOutW-1:0] v_d, v_q3;
  tu_clip_abs u_abs (.d_i, .a_o(a), .neg_o(neg));
  // a * a has 2 * ClipInF fraction bits; floor to ClipCoefF (a^2 <= 1/4, no wrap).
  assign a2_full = a * a;
  assign a2 = A2W'(a2_full >> (2 * tu_formats_pkg::ClipInF - F));
  // u = c2 + floor(c3 a), w = c0 + floor(c1 a): the coefficients inside the multiply-adds
  tu_clip_mulfloor u_mu (.x_i(AccW'(c3)), .a_i(a), .c_i(AccW'(c2)), .y_o(u));
  tu_clip_mulfloor u_mw (.x_i(AccW'(c1)), .a_i(a), .c_i(AccW'(c0)), .y_o(w));
  // t = w + floor(u a2) = floor((u a2 + w 2^F) / 2^F): one multiply-add, wrapped to ClipAccW
  // (the same sum as s + t of the straight form: c0 + w and (c2 + u) a2 added in two stages)
  assign hp = HW'(u_q1) * HW'($signed({1'b0, a2_q1})) + (HW'(w_q1) <<< F);
  assign t  = AccW'(hp >>> F);
  tu_clip_fold u_fold (.acc_i(t_q2), .neg_i(neg_q2), .v_o(v_d));

  always_ff @(posedge clk_i) begin
    if (en) begin
      a2_q1 <= a2;  u_q1 <= u;  w_q1 <= w;  neg_q1 <= neg;
      t_q2  <= t;                           neg_q2 <= neg_q1;
      v_q3  <= v_d;
    end
  end
  assign v_o = v_q3;

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {v_o})
endmodule
