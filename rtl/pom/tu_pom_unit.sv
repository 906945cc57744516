// Per-pixel POM unit (docs/blocks/relief.md §8; C model pom::march):
//   tu_pom_setup (II 1, 7 cycles) -> tu_pom_march (one layer step per clock, k + 3 cycles per
//   pixel, one pixel in flight) -> tu_pom_refine (II 1, 7 cycles).
// Set-up and refinement overlap the march of neighbouring pixels, and the engine accepts the next
// pixel in the last compare cycle of the previous one, so a stream of pixels costs
// sum(k + 1) + PomSetupLatency + PomRefineLatency + 2 cycles without stalls (pom::unit_cycles).
// dT, wrap and the flags travel through the engine with their pixel (its side port).
// DepthPort = 0: the engine's bricks ROM; 1: the external depth RAM (d_* ports, 1-cycle read
// latency) with the map's base and log2 sides given with each pixel (tu_pom_march). side_i is
// carried to side_o with its pixel (unused: tie to 0).
`include "tu_assert.svh"
module tu_pom_unit #(
  parameter int DepthPort = 0,
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vz_i,
  input  logic [tu_formats_pkg::PomSW-1:0]    s_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    n_i,
  input  logic                                wrap_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [SideW-1:0]                    side_i,
  output logic                                d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] d_addr_o,
  input  logic [7:0]                          d_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PomUvW-1:0]   u_o,
  output logic [tu_formats_pkg::PomUvW-1:0]   v_o,
  output logic [tu_formats_pkg::PomNW-1:0]    steps_o,
  output logic [tu_formats_pkg::PomWW-1:0]    w_o,
  output logic                                discard_o,
  output logic                                back_o,
  output logic                                clamped_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int NW  = tu_formats_pkg::PomNW;
  localparam int DW  = tu_formats_pkg::PomDenW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  localparam int XW  = AW + 8 + SideW;   // depth map, side: set-up -> march
  localparam int SSideW = 2 * UvW + 1 + XW;  // T, wrap, depth map, side

  // ---- Set-up --------------------------------------------------------------------------------
  logic           s_valid, s_ready, s_back, s_clamped;
  logic [UvW-1:0] s_du, s_dv;
  logic [NW-1:0]  s_n;
  logic [SSideW-1:0] s_side;
  tu_pom_setup #(.SideW(SSideW)) u_setup (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .vx_i, .vy_i, .vz_i, .s_i, .n_i, .side_i({u_i, v_i, wrap_i, base_i, lw_i, lh_i, side_i}),
    .out_valid_o(s_valid), .out_ready_i(s_ready),
    .du_o(s_du), .dv_o(s_dv), .n_o(s_n), .back_o(s_back), .clamped_o(s_clamped), .side_o(s_side)
  );

  // ---- March ----------------------------------------------------------------------------------
  localparam int MSideW = 2 * UvW + 3 + SideW;  // dT, wrap, back, clamped, side
  logic              m_valid, m_ready;
  logic [UvW-1:0]    m_u, m_v;
  logic [NW-1:0]     m_steps;
  logic [DW-1:0]     m_a, m_den;
  logic [MSideW-1:0] m_side;
  tu_pom_march #(.SideW(MSideW), .DepthPort(DepthPort)) u_march (
    .clk_i, .rst_ni, .in_valid_i(s_valid), .in_ready_o(s_ready),
    .u_i(s_side[SSideW-1 -: UvW]), .v_i(s_side[XW+1 +: UvW]), .du_i(s_du), .dv_i(s_dv), .n_i(s_n),
    .side_i({s_du, s_dv, s_side[XW], s_back, s_clamped, s_side[SideW-1:0]}),
    .base_i(s_side[SideW+8 +: AW]), .lw_i(s_side[SideW+4 +: 4]), .lh_i(s_side[SideW +: 4]),
    .d_req_o, .d_addr_o, .d_data_i,
    .out_valid_o(m_valid), .out_ready_i(m_ready),
    .u_o(m_u), .v_o(m_v), .steps_o(m_steps), .a_o(m_a), .den_o(m_den), .side_o(m_side)
  );

  // ---- Refinement ----------------------------------------------------------------------------
  tu_pom_refine #(.SideW(2 + SideW)) u_refine (
    .clk_i, .rst_ni, .in_valid_i(m_valid), .in_ready_o(m_ready),
    .u_i(m_u), .v_i(m_v), .du_i(m_side[MSideW-1 -: UvW]), .dv_i(m_side[SideW+3 +: UvW]),
    .steps_i(m_steps), .a_i(m_a), .den_i(m_den), .wrap_i(m_side[SideW+2]),
    .side_i(m_side[SideW+1:0]),
    .out_valid_o, .out_ready_i,
    .u_o, .v_o, .steps_o, .w_o, .discard_o, .side_o({back_o, clamped_o, side_o})
  );

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, steps_o, w_o, discard_o, back_o, clamped_o, side_o})
endmodule
