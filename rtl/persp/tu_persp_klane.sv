// Perspective divide, k-lane unit: K consecutive pixels of a span per clock (II = 1, latency
// PerspLatency). One input = a group of K pixels starting at span offset n (a multiple of K):
//   S1 lanes : n == 0 ? lane_j = seed + j * inc (adder chain) : lane_j += K * inc (shift)
//   S2..S8   : K copies of tu_persp_pixel (K reciprocal cores)
// Bit-identical to the C model's Model::span_klane<K> (and to every other traversal).
`include "tu_assert.svh"
module tu_persp_klane #(
  parameter int K = 4  // lanes, a power of two
) (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic                                   in_valid_i,
  output logic                                   in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]     pu0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]     pv0_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]     q0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]     a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]     d_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]     g_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]    n_i,
  output logic                                   out_valid_o,
  input  logic                                   out_ready_i,
  output logic [K*tu_formats_pkg::PerspUvW-1:0]  u_o,     // lane j in bits [j*UvW +: UvW]
  output logic [K*tu_formats_pkg::PerspUvW-1:0]  v_o,
  output logic [K-1:0]                           flag_o
);
  localparam int PW = tu_formats_pkg::PerspPW;
  localparam int QW = tu_formats_pkg::PerspQW;
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int LogK = $clog2(K);

  logic                                    en, accept;
  logic [tu_formats_pkg::PerspLatency-1:0] stage_valid;
  tu_pipe_valid #(.Depth(tu_formats_pkg::PerspLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );
  assign accept = en && in_valid_i;

  // Lane seeds: seed + j * inc as shift-and-add of the constant j; step K * inc by a shift.
  logic [PW-1:0] ka, kd;
  logic [QW-1:0] kg;
  assign ka = a_i << LogK;
  assign kd = d_i << LogK;
  assign kg = g_i << LogK;

  for (genvar j = 0; j < K; j++) begin : g_lane
    logic [PW-1:0] pu_s, pv_s, pu_q, pv_q;
    logic [QW-1:0] q_s, q_q;
    always_comb begin
      pu_s = pu0_i;
      pv_s = pv0_i;
      q_s  = q0_i;
      for (int b = 0; b < LogK; b++) begin
        if (((j >> b) & 1) != 0) begin
          pu_s = pu_s + (a_i << b);
          pv_s = pv_s + (d_i << b);
          q_s  = q_s + (g_i << b);
        end
      end
    end
    always_ff @(posedge clk_i) begin
      if (accept) begin
        pu_q <= (n_i == '0) ? pu_s : pu_q + ka;
        pv_q <= (n_i == '0) ? pv_s : pv_q + kd;
        q_q  <= (n_i == '0) ? q_s : q_q + kg;
      end
    end
    tu_persp_pixel u_pixel (
      .clk_i, .en_i(en), .pu_i(pu_q), .pv_i(pv_q), .q_i(q_q),
      .u_o(u_o[j*UW +: UW]), .v_o(v_o[j*UW +: UW]), .flag_o(flag_o[j])
    );
  end

  logic unused;
  assign unused = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, flag_o})
endmodule
