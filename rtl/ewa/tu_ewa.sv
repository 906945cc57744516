// EWA filter engine (B5), bit-exact with ewa::fx::filter (cmodel/blocks/ewa/ewa_fx.cpp,
// docs/blocks/ewa.md "RTL"): set-up units (tu_ewa_setup: CORDIC direction, level loop with the
// texel cap, walk start values) and a walker connected by a one-record hand-over, so the set-up
// of pixel i+1 overlaps the walk of pixel i.
//   Lanes = 1: tu_ewa_walk, one texel per clock, then drain and normalisation (one texel port)
//   Lanes = 4: tu_ewa_walk_lanes, a 2 x 2 block per clock over four bank ports, drain and
//              normalisation pipelined under the next pixel's walk (issue 23)
//   Setups   : set-up units taking the pixels in turn (records handed over in order), so that
//              the set-up (>= 30 clocks) keeps up with the 2 x 2 walk
// Data-dependent cycles; exact count: ewa::stream_cycles (cmodel/blocks/ewa/ewa_cycles.hpp,
// EngineParams lanes / setup_units / out_depth / lane_clip).
`include "tu_assert.svh"
module tu_ewa #(
  parameter int CordUnroll = 2,
  parameter int SqrtStep   = 4,
  // sub-texel border weights (tu_ewa_border in the walk; a pixel's clip_i turns them on) and their
  // clip volume: 0 mm_p1 (tu_clip_p1), 1 mm_p3 (tu_clip_horner), 2 mm_p3_estrin (tu_clip_estrin)
  parameter int HasClip     = 0,
  parameter int ClipVariant = 0,
  parameter int Lanes       = 1,  // texels per clock: 1 or 4 (2 x 2)
  parameter int Setups      = 1,  // set-up units: 1, or 2 .. 4 with Lanes = 4
  parameter int OutDepth    = 8   // Lanes = 4: pixels between hand-over and output
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
  // texel ports (1-cycle read latency): Lanes = 4: port b = bank b (tu_ewa_walk_lanes)
  output logic [Lanes-1:0]                      tex_req_o,
  output logic [Lanes*tu_formats_pkg::TexAddrW-1:0] tex_addr_o,
  input  logic [Lanes*32-1:0]                   tex_data_i,
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
  localparam int NW  = tu_formats_pkg::EwaCountW;
  localparam int WrW = 2 * tu_formats_pkg::WrapW;
  `TU_ASSERT_PARAM(g_lanes, Lanes == 1 || Lanes == 4, "Lanes must be 1 or 4")
  `TU_ASSERT_PARAM(g_setups, Setups == 1 || (Setups >= 2 && Setups <= 4 && Lanes == 4),
                   "Setups must be 1, or 2 .. 4 with Lanes = 4 (the cycle model's configurations)")
  localparam int SW = Setups > 1 ? $clog2(Setups) : 1;  // set-up unit index
  logic clip_on;
  assign clip_on = HasClip != 0 && clip_i;

  // ---- set-up units, fed in turn (wr_q) and read in turn (rd_q): records stay in order
  logic [SW-1:0] wr_q, rd_q;
  logic [Setups-1:0] s_in_ready, s_rec_valid;
  logic              rec_valid, rec_ready;
  // per unit: its record and the pixel's texture / weight configuration (held with its pixel)
  logic [3:0]           u_level [Setups];
  logic [4:0]           u_flags [Setups];
  logic                 u_guard [Setups];
  logic signed [31:0]   u_x0 [Setups], u_x1 [Setups], u_y0 [Setups], u_y1 [Setups], u_cu [Setups], u_cv [Setups];
  logic [NW-1:0]        u_box [Setups];
  logic signed [XiW-1:0] u_xi0 [Setups], u_eta0 [Setups], u_dxi [Setups], u_deta [Setups], u_dxiy [Setups],
                         u_detay [Setups];
  logic signed [63:0]   u_q0 [Setups], u_dq0 [Setups], u_ddq [Setups], u_ey0 [Setups], u_ddqy [Setups], u_dqy [Setups];
  logic [AW-1:0]        u_base [Setups];
  logic [3:0]           u_lw [Setups], u_lh [Setups];
  logic [WrW-1:0]       u_wrap [Setups];
  logic [1:0]           u_wsrc [Setups];
  logic                 u_clip [Setups];
  for (genvar j = 0; j < Setups; j++) begin : g_setup
    logic sel_in, acc;
    assign sel_in = Setups == 1 || wr_q == SW'(j);
    assign acc = in_valid_i && sel_in && s_in_ready[j];
    always_ff @(posedge clk_i) begin
      if (acc) begin
        u_base[j] <= base_i;
        u_lw[j]   <= lw_i;
        u_lh[j]   <= lh_i;
        u_wrap[j] <= wrap_i;
        u_wsrc[j] <= wsrc_i;
        u_clip[j] <= clip_on;
      end
    end
    tu_ewa_setup #(.CordUnroll(CordUnroll), .SqrtStep(SqrtStep), .Align(Lanes == 4 ? 1 : 0)) u_setup (
      .clk_i, .rst_ni, .in_valid_i(in_valid_i && sel_in), .in_ready_o(s_in_ready[j]), .u_i, .v_i, .ae_i,
      .ce_i, .be_i, .lmaj_i, .lmin_i, .lod_i, .eflags_i, .guard_i, .top_i(lw_i > lh_i ? lw_i : lh_i), .cap_i,
      .clip_i(clip_on), .rec_valid_o(s_rec_valid[j]), .rec_ready_i(rec_ready && (Setups == 1 || rd_q == SW'(j))),
      .level_o(u_level[j]), .flags_o(u_flags[j]), .guard_o(u_guard[j]), .x0_o(u_x0[j]), .x1_o(u_x1[j]),
      .y0_o(u_y0[j]), .y1_o(u_y1[j]), .box_o(u_box[j]), .cu_o(u_cu[j]), .cv_o(u_cv[j]), .xi0_o(u_xi0[j]),
      .eta0_o(u_eta0[j]), .dxi_o(u_dxi[j]), .deta_o(u_deta[j]), .dxiy_o(u_dxiy[j]), .detay_o(u_detay[j]),
      .q0_o(u_q0[j]), .dq0_o(u_dq0[j]), .ddq_o(u_ddq[j]), .ey0_o(u_ey0[j]), .ddqy_o(u_ddqy[j]), .dqy_o(u_dqy[j])
    );
  end
  logic [SW-1:0] rs;  // the unit whose record is next
  assign rs         = Setups == 1 ? '0 : rd_q;
  assign in_ready_o = s_in_ready[Setups == 1 ? '0 : wr_q];
  assign rec_valid  = s_rec_valid[rs];
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_q <= '0;
      rd_q <= '0;
    end else begin
      if (Setups > 1 && in_valid_i && in_ready_o) wr_q <= wr_q == SW'(Setups - 1) ? '0 : wr_q + 1'b1;
      if (Setups > 1 && rec_valid && rec_ready) rd_q <= rd_q == SW'(Setups - 1) ? '0 : rd_q + 1'b1;
    end
  end

  if (Lanes == 4) begin : g_lanes
    tu_ewa_walk_lanes #(.HasClip(HasClip), .ClipVariant(ClipVariant), .OutDepth(OutDepth)) u_walk (
      .clk_i, .rst_ni, .rec_valid_i(rec_valid), .rec_ready_o(rec_ready), .level_i(u_level[rs]),
      .flags_i(u_flags[rs]), .guard_i(u_guard[rs]), .x0_i(u_x0[rs]), .x1_i(u_x1[rs]), .y0_i(u_y0[rs]),
      .y1_i(u_y1[rs]), .box_i(u_box[rs]), .cu_i(u_cu[rs]), .cv_i(u_cv[rs]), .xi0_i(u_xi0[rs]),
      .eta0_i(u_eta0[rs]), .dxi_i(u_dxi[rs]), .deta_i(u_deta[rs]), .dxiy_i(u_dxiy[rs]), .detay_i(u_detay[rs]),
      .q0_i(u_q0[rs]), .dq0_i(u_dq0[rs]), .ddq_i(u_ddq[rs]), .ey0_i(u_ey0[rs]), .ddqy_i(u_ddqy[rs]),
      .dqy_i(u_dqy[rs]), .base_i(u_base[rs]), .lw_i(u_lw[rs]), .lh_i(u_lh[rs]), .wrap_i(u_wrap[rs]),
      .wsrc_i(u_wsrc[rs]), .clip_i(u_clip[rs]), .tex_req_o, .tex_addr_o, .tex_data_i,
      .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o
    );
  end else begin : g_seq
    tu_ewa_walk #(.HasClip(HasClip), .ClipVariant(ClipVariant)) u_walk (
      .clk_i, .rst_ni, .rec_valid_i(rec_valid), .rec_ready_o(rec_ready), .level_i(u_level[rs]),
      .flags_i(u_flags[rs]), .guard_i(u_guard[rs]), .x0_i(u_x0[rs]), .x1_i(u_x1[rs]), .y0_i(u_y0[rs]),
      .y1_i(u_y1[rs]), .box_i(u_box[rs]), .cu_i(u_cu[rs]), .cv_i(u_cv[rs]), .xi0_i(u_xi0[rs]),
      .eta0_i(u_eta0[rs]), .dxi_i(u_dxi[rs]), .deta_i(u_deta[rs]), .dxiy_i(u_dxiy[rs]), .detay_i(u_detay[rs]),
      .q0_i(u_q0[rs]), .dq0_i(u_dq0[rs]), .ddq_i(u_ddq[rs]), .ey0_i(u_ey0[rs]), .ddqy_i(u_ddqy[rs]),
      .dqy_i(u_dqy[rs]), .base_i(u_base[rs]), .lw_i(u_lw[rs]), .lh_i(u_lh[rs]), .wrap_i(u_wrap[rs]),
      .wsrc_i(u_wsrc[rs]), .clip_i(u_clip[rs]), .tex_req_o(tex_req_o[0]), .tex_addr_o(tex_addr_o[AW-1:0]),
      .tex_data_i(tex_data_i[31:0]),
      .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o
    );
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o})
endmodule
