// Perspective divide unit (B1), per-pixel pipeline, II = 1, latency PerspLatency (8).
// One input = one pixel of a span: the per-scanline seeds p_u0, p_v0, q0 (values at the span
// start), the increments A, D, G and the pixel offset n. Formats and rounding exactly as
// cmodel/blocks/persp (docs/blocks/persp.md):
//   S1 accumulate : n == 0 ? seed : acc + increment          (Direct = 1: seed + n * increment)
//   S2 normalise  : guard q < 2^-PerspGuardLog2 (incl. q <= 0); e = msb(q); M = top 24 bits
//   S3..S6        : tu_recip_core (R ~ 1/M, u25.24)
//   S7 multiply   : p_u * R, p_v * R (two signed PW x 25-bit products)
//   S8 round      : >> (RecipOutF + e - PerspUvF), round half up, saturate to s32.8;
//                   guarded: u = v = max code, flag = 1
`include "tu_assert.svh"
module tu_persp #(
  parameter int Direct = 0  // 1: direct evaluation (three multipliers) instead of accumulators
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]   pu0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]   pv0_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]   q0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]   a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]   d_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]   g_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]  n_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [tu_formats_pkg::PerspUvW-1:0]  u_o,
  output logic [tu_formats_pkg::PerspUvW-1:0]  v_o,
  output logic                                 flag_o
);
  localparam int PW = tu_formats_pkg::PerspPW;
  localparam int QW = tu_formats_pkg::PerspQW;
  logic                                    en, accept;
  logic [tu_formats_pkg::PerspLatency-1:0] stage_valid;

  tu_pipe_valid #(.Depth(tu_formats_pkg::PerspLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );
  assign accept = en && in_valid_i;

  // ---- S1: accumulators (hold the last accepted pixel; only the valid bit moves on bubbles)
  logic [PW-1:0] pu_d, pv_d, pu_q1, pv_q1;
  logic [QW-1:0] q_d, q_q1;
  if (Direct != 0) begin : g_direct
    // seed + n * increment, modulo 2^W like the accumulators (exact for in-range values)
    logic [PW-1:0] pu_m, pv_m;
    logic [QW-1:0] q_m;
    assign pu_m = PW'($signed(a_i) * $signed({1'b0, n_i}));
    assign pv_m = PW'($signed(d_i) * $signed({1'b0, n_i}));
    assign q_m  = QW'($signed(g_i) * $signed({1'b0, n_i}));
    assign pu_d = pu0_i + pu_m;
    assign pv_d = pv0_i + pv_m;
    assign q_d  = q0_i + q_m;
  end else begin : g_incr
    assign pu_d = (n_i == '0) ? pu0_i : pu_q1 + a_i;
    assign pv_d = (n_i == '0) ? pv0_i : pv_q1 + d_i;
    assign q_d  = (n_i == '0) ? q0_i  : q_q1 + g_i;
  end
  always_ff @(posedge clk_i) begin
    if (accept) begin
      pu_q1 <= pu_d;
      pv_q1 <= pv_d;
      q_q1  <= q_d;
    end
  end

  // ---- S2..S8: per-pixel back end
  tu_persp_pixel u_pixel (
    .clk_i, .en_i(en), .pu_i(pu_q1), .pv_i(pv_q1), .q_i(q_q1), .u_o, .v_o, .flag_o
  );

  logic unused;
  assign unused = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, flag_o})
endmodule
