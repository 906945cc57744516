// Per-pixel relief unit (docs/blocks/relief.md §8, §11; C model pom::march, pom::iter_parallax):
//   tu_pom_setup (II 1, 7 cycles) -> engine -> tu_pom_refine (II 1, 7 cycles), engine =
//   tu_pom_march (POM: one layer step per clock, k + 1 cycles per pixel in a stream, one pixel
//   marching and one in its output register) or tu_iter_parallax (iter_i: one iteration per clock,
//   k + 3 cycles per pixel, one pixel in flight).
// Set-up and refinement overlap the march of neighbouring pixels, and the march engine accepts the
// next pixel in the last compare cycle of the previous one, so a stream of POM pixels costs
// sum(k + 1) + PomSetupLatency + PomRefineLatency + 2 cycles without stalls (pom::unit_cycles).
// dT, wrap and the flags travel through the engine with their pixel (its side port).
// Iterative pixels: direction (P, 1) (pom::ipx_dir_normalised: P from the set-up's stage 5),
// cap = n_i; the result (fract(T)) passes the refinement with k = 0 (w = 0, T'' = T wrapped).
// The two engines share the depth port, so a pixel enters an engine only when the other holds no
// pixel (the march's count of pixels, the iterative engine's Idle): order and the port need no
// arbitration; a method switch costs the drain of the other engine. HasMarch / HasIter leave an
// engine out (a pixel of the missing method runs on the other one).
// Distance-map pixels (dm_i, HasDm): tu_dm_trace (§13.8) with P from the set-up's stage 5, cap n_i,
// the map at dbase_i with dlayers_i layers (side 2^lw_i, square), the finish against the depth map
// at base_i; one pixel in flight (Idle, Run, Done), handed over like iterative pixels; its result
// (fract(x)) passes the refinement with k = 0.
// DepthPort = 0: the engines' bricks ROMs (HasIter = 0 only); 1: the external depth RAM (d_* ports,
// 1-cycle read latency) with the map's base and log2 sides given with each pixel. side_i is
// carried to side_o with its pixel (unused: tie to 0).
`include "tu_assert.svh"
module tu_pom_unit #(
  parameter int DepthPort = 0,
  parameter int SideW = 1,
  parameter int HasMarch = 1,
  parameter int HasIter = 0,
  parameter int HasDm = 0   // the distance-map tracer (DepthPort = 1 only)
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
  input  logic                                iter_i,   // iterative parallax (cap n_i)
  input  logic                                dm_i,     // distance map (cap n_i)
  input  logic [tu_formats_pkg::DmLayersW-1:0] dlayers_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] dbase_i,
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
  output logic                                nonconv_o,  // iterative: cap reached, |d| >= eps
  output logic [SideW-1:0]                    side_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int NW  = tu_formats_pkg::PomNW;
  localparam int DW  = tu_formats_pkg::PomDenW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  localparam int LyW = tu_formats_pkg::DmLayersW;
  localparam int XW  = AW + 8 + SideW;   // depth map, side: set-up -> engine
  localparam int SSideW = 2 * UvW + 3 + tu_formats_pkg::PomSW + LyW + AW + XW;  // iter, dm, T, wrap, S, distance map, depth map, side

  // A unit with one engine runs every pixel on it.
  logic iter, dm;
  assign dm   = (HasDm != 0) && (dm_i || (HasMarch == 0 && HasIter == 0));
  assign iter = (HasIter != 0) && !dm && (iter_i || HasMarch == 0);

  // ---- Set-up --------------------------------------------------------------------------------
  logic           s_valid, s_ready, s_back, s_clamped;
  logic [UvW-1:0] s_du, s_dv, s_pu, s_pv;
  logic [NW-1:0]  s_n;
  logic [SSideW-1:0] s_side;
  tu_pom_setup #(.SideW(SSideW)) u_setup (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o,
    .vx_i, .vy_i, .vz_i, .s_i, .n_i, .side_i({iter, dm, u_i, v_i, wrap_i, s_i, dlayers_i, dbase_i, base_i, lw_i, lh_i, side_i}),
    .out_valid_o(s_valid), .out_ready_i(s_ready),
    .du_o(s_du), .dv_o(s_dv), .pu_o(s_pu), .pv_o(s_pv), .n_o(s_n), .back_o(s_back),
    .clamped_o(s_clamped), .side_o(s_side)
  );
  logic           s_iter, s_dm, s_wrap;
  logic [UvW-1:0] s_u, s_v;
  logic [tu_formats_pkg::PomSW-1:0] s_s;
  logic [LyW-1:0] s_dlayers;
  logic [AW-1:0]  s_dbase, s_base;
  logic [3:0]     s_lw, s_lh;
  logic [SideW-1:0] s_user;
  assign {s_iter, s_dm, s_u, s_v, s_wrap, s_s, s_dlayers, s_dbase, s_base, s_lw, s_lh, s_user} = s_side;

  // ---- Engines ---------------------------------------------------------------------------------
  localparam int MSideW = 2 * UvW + 3 + SideW;  // dT, wrap, back, clamped, side
  logic              m_in_valid, m_in_ready, m_valid, m_ready, m_req;
  logic [AW-1:0]     m_addr;
  logic [UvW-1:0]    m_u, m_v;
  logic [NW-1:0]     m_steps;
  logic [DW-1:0]     m_a, m_den;
  logic [MSideW-1:0] m_side;
  logic              i_in_valid, i_in_ready, i_valid, i_ready, i_req, i_nonconv;
  logic [AW-1:0]     i_addr;
  logic [15:0]       i_u, i_v;
  logic [NW-1:0]     i_iters;
  logic [MSideW-1:0] i_side;
  logic              x_in_valid, x_in_ready, x_valid, x_ready, x_req;
  logic [AW-1:0]     x_addr;
  logic [15:0]       x_u, x_v;
  logic [NW-1:0]     x_steps;
  logic [MSideW-1:0] x_side;
  logic [1:0]        m_cnt_q;  // pixels in the march engine (marching, output register)
  logic              m_empty, i_empty, x_empty;
  assign m_empty = (m_cnt_q == 2'd0);
  assign i_empty = i_in_ready;  // tu_iter_parallax is ready only when it holds no pixel
  assign x_empty = x_in_ready;  // tu_dm_trace likewise

  assign m_in_valid = s_valid && !s_iter && !s_dm && i_empty && x_empty;
  assign i_in_valid = s_valid && s_iter && m_empty && x_empty;
  assign x_in_valid = s_valid && s_dm && m_empty && i_empty;
  assign s_ready = s_dm ? (x_in_ready && m_empty && i_empty)
                 : s_iter ? (i_in_ready && m_empty && x_empty) : (m_in_ready && i_empty && x_empty);

  if (HasMarch != 0) begin : g_march
    tu_pom_march #(.SideW(MSideW), .DepthPort(DepthPort)) u_march (
      .clk_i, .rst_ni, .in_valid_i(m_in_valid), .in_ready_o(m_in_ready),
      .u_i(s_u), .v_i(s_v), .du_i(s_du), .dv_i(s_dv), .n_i(s_n),
      .side_i({s_du, s_dv, s_wrap, s_back, s_clamped, s_user}),
      .base_i(s_base), .lw_i(s_lw), .lh_i(s_lh),
      .d_req_o(m_req), .d_addr_o(m_addr), .d_data_i,
      .out_valid_o(m_valid), .out_ready_i(m_ready),
      .u_o(m_u), .v_o(m_v), .steps_o(m_steps), .a_o(m_a), .den_o(m_den), .side_o(m_side)
    );
  end else begin : g_no_march
    assign m_in_ready = 1'b0;
    assign m_valid = 1'b0;
    assign m_req = 1'b0;
    assign m_addr = '0;
    assign m_u = '0;
    assign m_v = '0;
    assign m_steps = '0;
    assign m_a = '0;
    assign m_den = '0;
    assign m_side = '0;
    logic unused_m;
    assign unused_m = ^{m_in_valid, m_ready, s_du, s_dv};
  end

  if (HasIter != 0) begin : g_iter
    tu_iter_parallax #(.DepthPort(DepthPort), .SideW(MSideW)) u_iter (
      .clk_i, .rst_ni, .in_valid_i(i_in_valid), .in_ready_o(i_in_ready),
      .u_i(s_u), .v_i(s_v), .su_i(s_pu), .sv_i(s_pv),
      .sh_i(UvW'(1) << tu_formats_pkg::PomUvF), .cap_i(s_n),
      .side_i({UvW'(0), UvW'(0), s_wrap, s_back, s_clamped, s_user}),
      .base_i(s_base), .lw_i(s_lw), .lh_i(s_lh),
      .d_req_o(i_req), .d_addr_o(i_addr), .d_data_i,
      .out_valid_o(i_valid), .out_ready_i(i_ready),
      .u_o(i_u), .v_o(i_v), .iters_o(i_iters), .nonconv_o(i_nonconv), .side_o(i_side)
    );
  end else begin : g_no_iter
    assign i_in_ready = 1'b1;  // empty
    assign i_valid = 1'b0;
    assign i_req = 1'b0;
    assign i_addr = '0;
    assign i_u = '0;
    assign i_v = '0;
    assign i_iters = '0;
    assign i_nonconv = 1'b0;
    assign i_side = '0;
    logic unused_i;
    assign unused_i = ^{i_in_valid, i_ready, s_pu, s_pv};
  end

  if (HasDm != 0) begin : g_dm
    tu_dm_trace #(.SideW(MSideW)) u_dm (
      .clk_i, .rst_ni, .in_valid_i(x_in_valid), .in_ready_o(x_in_ready),
      .u_i(s_u), .v_i(s_v), .pu_i(s_pu), .pv_i(s_pv), .s_i(s_s), .cap_i(s_n),
      .layers_i(s_dlayers), .hbase_i(s_base), .dbase_i(s_dbase), .lw_i(s_lw),
      .side_i({UvW'(0), UvW'(0), s_wrap, s_back, s_clamped, s_user}),
      .d_req_o(x_req), .d_addr_o(x_addr), .d_data_i,
      .out_valid_o(x_valid), .out_ready_i(x_ready),
      .u_o(x_u), .v_o(x_v), .steps_o(x_steps), .side_o(x_side)
    );
  end else begin : g_no_dm
    assign x_in_ready = 1'b1;  // empty
    assign x_valid = 1'b0;
    assign x_req = 1'b0;
    assign x_addr = '0;
    assign x_u = '0;
    assign x_v = '0;
    assign x_steps = '0;
    assign x_side = '0;
    logic unused_x;
    assign unused_x = ^{x_in_valid, x_ready, s_s, s_dlayers, s_dbase};
  end

  // One engine holds pixels at a time: the depth port and the refinement's input are its.
  assign d_req_o  = m_req || i_req || x_req;
  assign d_addr_o = x_req ? x_addr : i_req ? i_addr : m_addr;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) m_cnt_q <= '0;
    else m_cnt_q <= m_cnt_q + 2'(m_in_valid && m_in_ready) - 2'(m_valid && m_ready);
  end

  // ---- Refinement (iterative, distance map: k = 0, so T'' = fract(T)) ------------------------
  logic              r_valid, r_ready, r_iter;
  logic [UvW-1:0]    r_u, r_v;
  logic [NW-1:0]     r_k, r_iters;
  logic [DW-1:0]     r_a, r_den;
  logic [MSideW-1:0] r_side;
  assign r_valid = m_valid || i_valid || x_valid;
  assign m_ready = r_ready;
  assign i_ready = r_ready;
  assign x_ready = r_ready;
  assign r_iter  = i_valid || x_valid;
  assign r_u     = i_valid ? UvW'(i_u) : x_valid ? UvW'(x_u) : m_u;
  assign r_v     = i_valid ? UvW'(i_v) : x_valid ? UvW'(x_v) : m_v;
  assign r_k     = r_iter ? '0 : m_steps;
  assign r_a     = r_iter ? '0 : m_a;
  assign r_den   = r_iter ? '0 : m_den;
  assign r_side  = i_valid ? i_side : x_valid ? x_side : m_side;
  logic [NW-1:0] f_steps;
  logic          f_iter;
  tu_pom_refine #(.SideW(2 + NW + 2 + SideW)) u_refine (
    .clk_i, .rst_ni, .in_valid_i(r_valid), .in_ready_o(r_ready),
    .u_i(r_u), .v_i(r_v), .du_i(r_side[MSideW-1 -: UvW]), .dv_i(r_side[SideW+3 +: UvW]),
    .steps_i(r_k), .a_i(r_a), .den_i(r_den), .wrap_i(r_side[SideW+2]),
    .side_i({r_iter, i_nonconv && i_valid, i_valid ? i_iters : x_steps, r_side[SideW+1:0]}),
    .out_valid_o, .out_ready_i,
    .u_o, .v_o, .steps_o(f_steps), .w_o, .discard_o,
    .side_o({f_iter, nonconv_o, r_iters, back_o, clamped_o, side_o})
  );
  assign steps_o = f_iter ? r_iters : f_steps;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, steps_o, w_o, discard_o, back_o, clamped_o, nonconv_o, side_o})
endmodule
