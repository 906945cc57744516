// Direct-evaluation variant of the perspective divide unit (area comparison and co-simulation):
// p = seed + n * increment per pixel (three multipliers) instead of the accumulators.
`include "tu_assert.svh"
module tu_persp_direct (
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
  tu_persp #(.Direct(1)) u_persp (.*);

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, flag_o})
endmodule
