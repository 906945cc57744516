// Co-simulation top of the texel decode stage (block "texel_decode"): tu_texel_decode (every
// format, sRGB, 32-bit words) behind one register stage with a valid/ready interface, so that the
// vector harness can drive it with stalls; latency 1, II = 1.
`include "tu_assert.svh"
module tu_texel_decode_sim (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               in_valid_i,
  output logic                               in_ready_o,
  input  logic [31:0]                        word_i,
  input  logic [tu_formats_pkg::TexFmtW-1:0] fmt_i,
  input  logic                               srgb_i,
  output logic                               out_valid_o,
  input  logic                               out_ready_i,
  output logic [31:0]                        rgba_o
);
  logic        en, stage_valid;
  logic [31:0] rgba;
  // one valid register (as tu_pipe_valid Depth 1; written out: Verilator 5.006 mis-elaborates
  // tu_pipe_valid's Depth generate elsewhere in the tree when these tops instantiate it too)
  logic valid_q;
  assign en          = !valid_q || out_ready_i;
  assign in_ready_o  = en;
  assign out_valid_o = valid_q;
  assign stage_valid = valid_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= 1'b0;
    else if (en) valid_q <= in_valid_i;
  end
  tu_texel_decode u_dec (.word_i, .fmt_i, .srgb_i, .rgba_o(rgba));
  always_ff @(posedge clk_i) begin
    if (en) rgba_o <= rgba;
  end
  logic unused_stage_valid;
  assign unused_stage_valid = stage_valid;

  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o})
endmodule
