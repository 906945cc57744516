// EWA filter engine (B5), bit-exact with ewa::fx::filter (cmodel/blocks/ewa/ewa_fx.cpp,
// docs/blocks/ewa.md "RTL"): a set-up unit (tu_ewa_setup: CORDIC direction, level loop with the
// texel cap, walk start values) and a walker (tu_ewa_walk: one texel per clock, weights,
// accumulation, normalisation) connected by a one-record hand-over, so the set-up of pixel i+1
// overlaps the walk of pixel i. Data-dependent cycles; exact count: ewa::stream_cycles
// (cmodel/blocks/ewa/ewa_cycles.hpp).
`include "tu_assert.svh"
module tu_ewa #(
  parameter int CordUnroll = 2,
  parameter int SqrtStep   = 4,
  // sub-texel border weights (tu_ewa_border in the walk; a pixel's clip_i turns them on) and their
  // clip volume: 0 mm_p1 (tu_clip_p1), 1 mm_p3 (tu_clip_horner), 2 mm_p3_estrin (tu_clip_estrin)
  parameter int HasClip     = 0,
  parameter int ClipVariant = 0
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
  input  logic                                  guard_i,  // B1 guard: the texture's mean (top level)
  input  logic [tu_formats_pkg::TexAddrW-1:0]   base_i,
  input  logic [3:0]                            lw_i,
  input  logic [3:0]                            lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]     wrap_i,  // {v, u} Wrap* codes (tu_texel_addr)
  input  logic [1:0]                            wsrc_i,   // 0 formula, 1 1-D table, 2 2-D table
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,    // max_texels
  input  logic                                  clip_i,   // border weights (HasClip units)
  output logic                                  tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   tex_addr_o,
  input  logic [31:0]                           tex_data_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  inside_o,
  output logic [4:0]                            flags_o
);
  localparam int XiW = tu_formats_pkg::EwaXiW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  // texture / weight configuration travels with the record (the set-up holds one pixel)
  logic [AW-1:0] base_q;
  logic [3:0]    lw_q, lh_q;
  logic [2*tu_formats_pkg::WrapW-1:0] wrap_q;
  logic [1:0]    wsrc_q;
  logic          clip_q;
  logic          clip_on;
  assign clip_on = HasClip != 0 && clip_i;
  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) begin
      base_q  <= base_i;
      lw_q    <= lw_i;
      lh_q    <= lh_i;
      wrap_q  <= wrap_i;
      wsrc_q  <= wsrc_i;
      clip_q  <= clip_on;
    end
  end

  logic                 rec_valid, rec_ready;
  logic [3:0]           r_level;
  logic [4:0]           r_flags;
  logic                 r_guard;
  logic signed [31:0]   r_x0, r_x1, r_y0, r_y1, r_cu, r_cv;
  logic [tu_formats_pkg::EwaCountW-1:0] r_box;
  logic signed [XiW-1:0] r_xi0, r_eta0, r_dxi, r_deta, r_dxiy, r_detay;
  logic signed [63:0]   r_q0, r_dq0, r_ddq, r_ey0, r_ddqy, r_dqy;
  tu_ewa_setup #(.CordUnroll(CordUnroll), .SqrtStep(SqrtStep)) u_setup (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .u_i, .v_i, .ae_i, .ce_i, .be_i, .lmaj_i, .lmin_i,
    .lod_i, .eflags_i, .guard_i, .top_i(lw_i > lh_i ? lw_i : lh_i), .cap_i, .clip_i(clip_on),
    .rec_valid_o(rec_valid), .rec_ready_i(rec_ready), .level_o(r_level), .flags_o(r_flags), .guard_o(r_guard),
    .x0_o(r_x0), .x1_o(r_x1), .y0_o(r_y0), .y1_o(r_y1), .box_o(r_box), .cu_o(r_cu), .cv_o(r_cv),
    .xi0_o(r_xi0), .eta0_o(r_eta0), .dxi_o(r_dxi), .deta_o(r_deta), .dxiy_o(r_dxiy),
    .detay_o(r_detay), .q0_o(r_q0), .dq0_o(r_dq0), .ddq_o(r_ddq), .ey0_o(r_ey0),
    .ddqy_o(r_ddqy), .dqy_o(r_dqy)
  );
  tu_ewa_walk #(.HasClip(HasClip), .ClipVariant(ClipVariant)) u_walk (
    .clk_i, .rst_ni, .rec_valid_i(rec_valid), .rec_ready_o(rec_ready), .level_i(r_level),
    .flags_i(r_flags), .guard_i(r_guard), .x0_i(r_x0), .x1_i(r_x1), .y0_i(r_y0), .y1_i(r_y1), .box_i(r_box),
    .cu_i(r_cu), .cv_i(r_cv), .xi0_i(r_xi0), .eta0_i(r_eta0), .dxi_i(r_dxi), .deta_i(r_deta),
    .dxiy_i(r_dxiy), .detay_i(r_detay), .q0_i(r_q0), .dq0_i(r_dq0), .ddq_i(r_ddq),
    .ey0_i(r_ey0), .ddqy_i(r_ddqy), .dqy_i(r_dqy), .base_i(base_q), .lw_i(lw_q), .lh_i(lh_q),
    .wrap_i(wrap_q), .wsrc_i(wsrc_q), .clip_i(clip_q), .tex_req_o, .tex_addr_o, .tex_data_i,
    .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o
  );

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o})
endmodule
