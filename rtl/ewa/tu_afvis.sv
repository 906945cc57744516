// AF with parallax visibility (seed 003 §6, docs/blocks/afvis.md §5): an EWA engine that filters
// only the footprint texels the eye sees over the relief, bit-exact with afvis::filter
// (cmodel/blocks/afvis/afvis.cpp). The EWA set-up (tu_ewa_setup, unchanged: level, box, walk
// start values) and P = S Vxy / max(|Vz|, PomVzMin) (tu_pom_setup with N = 1: the relief step's
// own parallax) run side by side on the accepted pixel; their records join at the hand-over to the
// visibility walker (tu_afvis_walk: row scan, row buffer, per-texel depth trace, accumulate,
// normalise), so pixel i+1's set-up overlaps pixel i's walk as in tu_ewa. The depth map is read
// through its own port (1-cycle latency; the texture unit gives it a second read port on the
// depth RAM). No border weights (a material with clip and af_visibility is refused by the driver)
// and no B1-guard path (the texture unit sends shifted pixels only, never guarded).
// Cycles: ewa::StreamModel with PixelCost::afv_walk = afvis::Out::clocks.
`include "tu_assert.svh"
module tu_afvis #(
  parameter int CordUnroll = 2,
  parameter int SqrtStep   = 4
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  in_valid_i,
  output logic                                  in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ae_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ce_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   be_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmaj_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmin_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lod_i,
  input  logic [4:0]                            eflags_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   base_i,
  input  logic [3:0]                            lw_i,
  input  logic [3:0]                            lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]    wrap_i,
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  // the pixel's quantised tangent-space view and the material's relief
  input  logic [tu_formats_pkg::PomVzW-1:0]     vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vz_i,
  input  logic [tu_formats_pkg::PomSW-1:0]      scale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   hbase_i,  // depth map in the depth RAM
  input  logic [3:0]                            hlw_i,
  input  logic [3:0]                            hlh_i,
  input  logic [7:0]                            dmin_i,   // its smallest code
  input  logic [7:0]                            bias_i,   // trace bias (depth codes)
  input  logic                                  rule_i,   // 0 every texel, 1 the seed's row rule
  output logic                                  tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   tex_addr_o,
  input  logic [31:0]                           tex_data_i,
  output logic                                  d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   d_addr_o,
  input  logic [7:0]                            d_data_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  inside_o,
  output logic [4:0]                            flags_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  kept_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  traced_o,
  output logic [23:0]                           steps_o
);
  localparam int XiW = tu_formats_pkg::EwaXiW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  localparam int UvW = tu_formats_pkg::PomUvW;
  // configuration travels with the record (the set-up holds one pixel)
  logic [AW-1:0] base_q, hbase_q;
  logic [3:0]    lw_q, lh_q, hlw_q, hlh_q;
  logic [2*tu_formats_pkg::WrapW-1:0] wrap_q;
  logic [1:0]    wsrc_q;
  logic [7:0]    dmin_q, bias_q;
  logic          rule_q;
  logic          su_ready, ps_ready, fire;
  assign in_ready_o = su_ready && ps_ready;
  assign fire = in_valid_i && in_ready_o;
  always_ff @(posedge clk_i) begin
    if (fire) begin
      base_q <= base_i;  lw_q <= lw_i;    lh_q <= lh_i;    wrap_q <= wrap_i;  wsrc_q <= wsrc_i;
      hbase_q <= hbase_i; hlw_q <= hlw_i; hlh_q <= hlh_i;  dmin_q <= dmin_i;  bias_q <= bias_i;
      rule_q <= rule_i;
    end
  end

  logic                 rec_valid, rec_ready, ps_valid, w_ready;
  logic [3:0]           r_level;
  logic [4:0]           r_flags;
  logic                 r_guard;
  logic signed [31:0]   r_x0, r_x1, r_y0, r_y1, r_cu, r_cv;
  logic [tu_formats_pkg::EwaCountW-1:0] r_box;
  logic signed [XiW-1:0] r_xi0, r_eta0, r_dxi, r_deta, r_dxiy, r_detay;
  logic signed [63:0]   r_q0, r_dq0, r_ddq, r_ey0, r_ddqy, r_dqy;
  tu_ewa_setup #(.CordUnroll(CordUnroll), .SqrtStep(SqrtStep)) u_setup (
    .clk_i, .rst_ni, .in_valid_i(in_valid_i && ps_ready), .in_ready_o(su_ready), .u_i, .v_i, .ae_i, .ce_i,
    .be_i, .lmaj_i, .lmin_i, .lod_i, .eflags_i, .guard_i(1'b0), .top_i(lw_i > lh_i ? lw_i : lh_i), .cap_i,
    .clip_i(1'b0), .rec_valid_o(rec_valid), .rec_ready_i(rec_ready), .level_o(r_level), .flags_o(r_flags),
    .guard_o(r_guard), .x0_o(r_x0), .x1_o(r_x1), .y0_o(r_y0), .y1_o(r_y1), .box_o(r_box), .cu_o(r_cu),
    .cv_o(r_cv), .xi0_o(r_xi0), .eta0_o(r_eta0), .dxi_o(r_dxi), .deta_o(r_deta), .dxiy_o(r_dxiy),
    .detay_o(r_detay), .q0_o(r_q0), .dq0_o(r_dq0), .ddq_o(r_ddq), .ey0_o(r_ey0), .ddqy_o(r_ddqy), .dqy_o(r_dqy)
  );
  // P: tu_pom_setup's pu, pv (N = 1; dT, N and the flags are the march's)
  logic [UvW-1:0] p_du, p_dv, p_pu, p_pv;
  logic [tu_formats_pkg::PomNW-1:0] p_n;
  logic p_back, p_clamped;
  logic p_side;
  tu_pom_setup #(.SideW(1)) u_par (
    .clk_i, .rst_ni, .in_valid_i(in_valid_i && su_ready), .in_ready_o(ps_ready), .vx_i, .vy_i, .vz_i,
    .s_i(scale_i), .n_i(tu_formats_pkg::PomNW'(1)), .side_i(1'b0), .out_valid_o(ps_valid),
    .out_ready_i(w_ready && rec_valid), .du_o(p_du), .dv_o(p_dv), .pu_o(p_pu), .pv_o(p_pv), .n_o(p_n),
    .back_o(p_back), .clamped_o(p_clamped), .side_o(p_side)
  );
  // the set-up takes PomSetupLatency < its own clocks: P waits at the join, the record never does
  assign rec_ready = w_ready && ps_valid;

  tu_afvis_walk u_walk (
    .clk_i, .rst_ni, .rec_valid_i(rec_valid && ps_valid), .rec_ready_o(w_ready), .level_i(r_level),
    .flags_i(r_flags), .x0_i(r_x0), .x1_i(r_x1), .y0_i(r_y0), .y1_i(r_y1), .box_i(r_box),
    .cu_i(r_cu), .cv_i(r_cv), .xi0_i(r_xi0), .eta0_i(r_eta0), .dxi_i(r_dxi), .deta_i(r_deta),
    .dxiy_i(r_dxiy), .detay_i(r_detay), .q0_i(r_q0), .dq0_i(r_dq0), .ddq_i(r_ddq),
    .ey0_i(r_ey0), .ddqy_i(r_ddqy), .dqy_i(r_dqy), .base_i(base_q), .lw_i(lw_q), .lh_i(lh_q),
    .wrap_i(wrap_q), .wsrc_i(wsrc_q), .pu_i(p_pu), .pv_i(p_pv), .hbase_i(hbase_q), .hlw_i(hlw_q),
    .hlh_i(hlh_q), .dmin_i(dmin_q), .bias_i(bias_q), .rule_i(rule_q),
    .tex_req_o, .tex_addr_o, .tex_data_i, .d_req_o, .d_addr_o, .d_data_i,
    .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o,
    .kept_o, .traced_o, .steps_o
  );

  logic unused;
  assign unused = ^{r_guard, p_du, p_dv, p_n, p_back, p_clamped, p_side};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o, kept_o, traced_o, steps_o})
endmodule
