// Co-simulation top of the texel decode stage (block "texel_decode"): tu_texel_decode (every
// format, sRGB, 32-bit words) behind one register stage with a valid/ready interface (tu_out_reg),
// so that the vector harness can drive it with stalls; latency 1, II = 1.
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
  logic [31:0] rgba;
  tu_texel_decode u_dec (.word_i, .fmt_i, .srgb_i, .rgba_o(rgba));
  tu_out_reg #(.W(32)) u_reg (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .d_i(rgba), .out_valid_o, .out_ready_i, .q_o(rgba_o)
  );
endmodule
