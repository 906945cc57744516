// Per-span set-up of the B2 derivative numerators (seed-001 §2.7 recurrences, corrected; exactly
// ellipse::fx::numerators_span): from the per-triangle constants
//   kux = A I - C G, kvx = D I - F G, kuy = B I - C H, kvy = E I - F H, m = A H - B G, nn = D H - E G
// (exact, 2 PerspF fraction bits, computed once per triangle by the triangle set-up) the span
// seeds on row y at x0:
//   nux = kux + m y, nvx = kvx + nn y (constant along the row), nuy0 = kuy - m x0, nvy0 = kvy - nn x0.
// Latency 2 (S1: four products with the 12-bit indices, S2: sums), II = 1, same as
// tu_persp_setup. side_i is carried along unchanged.
`include "tu_assert.svh"
module tu_num_setup #(
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::EllNxW-1:0]   kux_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   kvx_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   kuy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   kvy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   m_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nn_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] x0_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] y_i,
  input  logic [SideW-1:0]                    side_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::EllNxW-1:0]   nux_o,
  output logic [tu_formats_pkg::EllNxW-1:0]   nvx_o,
  output logic [tu_formats_pkg::EllNxW-1:0]   nuy_o,
  output logic [tu_formats_pkg::EllNxW-1:0]   nvy_o,
  output logic [tu_formats_pkg::EllNxW-1:0]   m_o,
  output logic [tu_formats_pkg::EllNxW-1:0]   nn_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int NW = tu_formats_pkg::EllNxW;
  localparam int XW = tu_formats_pkg::PerspXyW;
  logic       en;
  logic [1:0] stage_valid;
  tu_pipe_valid #(.Depth(2)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // S1: products (modulo 2^NW: exact for every value within the documented bound)
  logic signed [XW:0] x0_s, y_s;
  assign x0_s = $signed({1'b0, x0_i});
  assign y_s  = $signed({1'b0, y_i});
  logic [NW-1:0]    my_q, ny_q, mx_q, nx_q, kux_q, kvx_q, kuy_q, kvy_q, m_q, nn_q;
  logic [SideW-1:0] side_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      my_q   <= NW'($signed(m_i) * y_s);
      ny_q   <= NW'($signed(nn_i) * y_s);
      mx_q   <= NW'($signed(m_i) * x0_s);
      nx_q   <= NW'($signed(nn_i) * x0_s);
      kux_q  <= kux_i;
      kvx_q  <= kvx_i;
      kuy_q  <= kuy_i;
      kvy_q  <= kvy_i;
      m_q    <= m_i;
      nn_q   <= nn_i;
      side_q <= side_i;
    end
  end
  // S2: sums
  always_ff @(posedge clk_i) begin
    if (en) begin
      nux_o  <= kux_q + my_q;
      nvx_o  <= kvx_q + ny_q;
      nuy_o  <= kuy_q - mx_q;
      nvy_o  <= kvy_q - nx_q;
      m_o    <= m_q;
      nn_o   <= nn_q;
      side_o <= side_q;
    end
  end

  logic unused;
  assign unused = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  // Two groups: Verilator 5.006 emits broken C++ for the sampled copy of one 1,300-bit value.
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {nux_o, nvx_o, nuy_o, nvy_o, m_o, nn_o})
  `TU_ASSERT_HANDSHAKE(OutHandshakeSide, out_valid_o, out_ready_i, side_o)
endmodule
