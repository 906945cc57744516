// One output register stage with a valid/ready interface, for the co-simulation tops of the
// combinational blocks (tu_texel_decode_sim, tu_bc1_decode_sim): the vector harness drives them
// with stalls; latency 1, II = 1. The valid register is tu_pipe_valid's Depth 1 written out: with
// these tops instantiating tu_pipe_valid too, a bug of Verilator 5.006 mis-elaborates its Depth
// generate elsewhere in the tree.
`include "tu_assert.svh"
module tu_out_reg #(
  parameter int W = 32
) (
  input  logic         clk_i,
  input  logic         rst_ni,
  input  logic         in_valid_i,
  output logic         in_ready_o,
  input  logic [W-1:0] d_i,
  output logic         out_valid_o,
  input  logic         out_ready_i,
  output logic [W-1:0] q_o
);
  logic en, valid_q;
  assign en          = !valid_q || out_ready_i;
  assign in_ready_o  = en;
  assign out_valid_o = valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= 1'b0;
    else if (en) valid_q <= in_valid_i;
  end
  always_ff @(posedge clk_i) begin
    if (en) q_o <= d_i;
  end

  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {q_o})
endmodule
