// Co-simulation top of the texel addressing (block "texel_addr"): tu_texel_addr (CoordW = 32, the
// EWA walk's width) behind one register stage with a valid/ready interface, so that the vector
// harness can drive it with stalls; latency 1, II = 1.
`include "tu_assert.svh"
module tu_texel_addr_sim (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]  wrap_i,
  input  logic [3:0]                          level_i,
  input  logic signed [31:0]                  x_i,
  input  logic signed [31:0]                  y_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::TexAddrW-1:0] addr_o
);
  logic                                en, stage_valid;
  logic [tu_formats_pkg::TexAddrW-1:0] addr;
  tu_pipe_valid #(.Depth(1)) u_valid (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i, .en_o(en),
    .stage_valid_o(stage_valid)
  );
  tu_texel_addr #(.CoordW(32)) u_addr (.base_i, .lw_i, .lh_i, .wrap_i, .level_i, .x_i, .y_i, .addr_o(addr));
  always_ff @(posedge clk_i) begin
    if (en) addr_o <= addr;
  end
  logic unused_stage_valid;
  assign unused_stage_valid = stage_valid;

  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {addr_o})
endmodule
