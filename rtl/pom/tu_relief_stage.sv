// Relief (POM) stage of the texture unit (docs/blocks/relief.md, "Relief stage of the texture
// unit"; C model relief::shift_texel_uv_fx). Between the B1/B2 join and the filter: each pixel's
// B1 codes (u, v) are shifted by its material's POM relief.
//   * B1 codes (TexUvF fraction, level-0 texels of a 2^lw x 2^lh colour texture) become texture
//     repeats with PomUvF bits: the fraction of one repeat, f = (u << PomUvF-TexUvF) >> lw, is
//     marched; the repeat part (u with its low lw + PomUvF - TexUvF bits cleared) is kept aside.
//   * tu_pom_layers (N for pom_adaptive; the material's layers for pom_fixed and the iteration cap
//     of iterative parallax) -> tu_pom_unit (DepthPort = 1: the depth map in the external RAM,
//     wrap = 1; its march engine for POM pixels, its iterative-parallax engine for iter_i pixels,
//     HasPom / HasIterParallax from the unit configuration leave one out).
//   * Back: u' = repeat part | (T'' << lw) >> (PomUvF - TexUvF) (floored when lw > 8: the
//     shift_code of the C model).
// Order: every pixel enters a sideband FIFO; shifted ones also enter the POM path. The output
// joins the FIFO head with the POM result when the head is shifted (head-of-line), so pixels
// without a shift stream at 1 pixel / clock and wait only for older shifted pixels.
// Stream cycles without back-pressure: relief::stage_cycles (same structure, cycle by cycle).
// Distance-map pixels (dm_i; HasDistanceMap from the unit configuration): tu_pom_unit's
// tu_dm_trace with the map at dbase_i (dlayers_i layers, the depth map's side) and the cap layers_i
// (the driver's relief::dm_cap); steps_o = map steps + finish reads.
// flags_o: relief::ReliefFlag bits {back (POM, distance map), nonconv (iterative), Vz guard};
// steps_o: march steps or iterations (0 when not shifted).
`include "tu_assert.svh"
module tu_relief_stage #(
  parameter int SideW = 1,
  // Relief engines (the texture-unit top passes tu_unit_cfg_pkg's HasPom / HasIterParallax)
  parameter int HasPom = 1,
  parameter int HasIterParallax = 1,
  parameter int HasDistanceMap = 1,
  // Sideband FIFO entries: more than the pixels the POM path holds (3 + 7 + 2 + 7), so a
  // full POM path never stalls the pixels behind it for lack of FIFO room.
  parameter int FifoDepth = 32
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  v_i,
  input  logic [3:0]                           lw_i,
  input  logic [3:0]                           lh_i,
  input  logic                                 rel_i,
  input  logic                                 guard_i,
  input  logic                                 adaptive_i,
  input  logic                                 iter_i,
  input  logic                                 dm_i,
  input  logic [tu_formats_pkg::DmLayersW-1:0] dlayers_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  dbase_i,
  input  logic [tu_formats_pkg::PomNW-1:0]     layers_i,
  input  logic [tu_formats_pkg::PomSW-1:0]     scale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  hbase_i,
  input  logic [3:0]                           hlw_i,
  input  logic [3:0]                           hlh_i,
  input  logic [SideW-1:0]                     side_i,
  input  logic                                 view_valid_i,
  output logic                                 view_ready_o,
  input  logic                                 view_ok_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vz_i,
  input  logic [tu_formats_pkg::PomCW-1:0]     vc_i,
  output logic                                 d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]  d_addr_o,
  input  logic [7:0]                           d_data_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [tu_formats_pkg::PerspUvW-1:0]  u_o,
  output logic [tu_formats_pkg::PerspUvW-1:0]  v_o,
  output logic [tu_formats_pkg::PomNW-1:0]     n_o,
  output logic [tu_formats_pkg::PomNW-1:0]     steps_o,
  output logic [2:0]                           flags_o,
  output logic [SideW-1:0]                     side_o
);
  localparam int UvW  = tu_formats_pkg::PerspUvW;
  localparam int PUvW = tu_formats_pkg::PomUvW;
  localparam int PF   = tu_formats_pkg::PomUvF;
  localparam int Sh   = tu_formats_pkg::PomUvF - tu_formats_pkg::TexUvF;  // 8
  localparam int NW   = tu_formats_pkg::PomNW;
  localparam int VW   = tu_formats_pkg::PomVzW;
  localparam int SW   = tu_formats_pkg::PomSW;
  localparam int AW   = tu_formats_pkg::TexAddrW;
  localparam int LL   = tu_formats_pkg::PomLayersLatency;
  localparam logic [NW-1:0] Nmin = NW'(4);  // pom::kDefaultNmin (relief::layers_at)

  // ---- Input: FIFO entry for every pixel, POM path for shifted ones ------------------------
  localparam int FW = 1 + 2 * UvW + 8 + SideW;  // shift, u, v, lw, lh, side
  logic          shift, f_in_ready, l_in_ready, fire;
  logic          f_valid, f_ready;
  logic [FW-1:0] f_data;
  assign shift        = rel_i && !guard_i && view_ok_i;
  assign in_ready_o   = f_in_ready && (!rel_i || view_valid_i) && (!shift || l_in_ready);
  assign view_ready_o = in_valid_i && rel_i && f_in_ready && (!shift || l_in_ready);
  assign fire         = in_valid_i && in_ready_o;

  tu_fifo #(.Width(FW), .Depth(FifoDepth)) u_fifo (
    .clk_i, .rst_ni, .in_valid_i(fire), .in_ready_o(f_in_ready),
    .in_data_i({shift, u_i, v_i, lw_i, lh_i, side_i}),
    .out_valid_o(f_valid), .out_ready_i(f_ready), .out_data_o(f_data)
  );

  // Fraction of one texture repeat, PomUvF bits: bits [lw + Sh - 1 -: PomUvF] of u << Sh.
  function automatic logic [PF-1:0] frac(input logic [UvW-1:0] c, input logic [3:0] l);
    frac = PF'({c, Sh'(0)} >> l);
  endfunction

  // ---- Layers N (3 stages; its side data moves in lockstep under an identical controller) ----
  localparam int LyW  = tu_formats_pkg::DmLayersW;
  localparam int LW = 2 * PF + 3 * VW + SW + NW + 3 + LyW + 2 * AW + 8;
  logic          l_valid, l_out_valid, l_en, m_ready;
  logic [NW-1:0] l_n;
  logic [LL-1:0] l_stage_valid;
  logic [LW-1:0] l_side_q [LL];
  logic          l_ctrl_ready, l_ctrl_valid, l_neg;
  assign l_valid = fire && shift;
  tu_pom_layers u_layers (
    .clk_i, .rst_ni, .in_valid_i(l_valid), .in_ready_o(l_in_ready),
    .vz_i, .c_i(vc_i), .nmin_i(Nmin), .nmax_i(layers_i),
    .out_valid_o(l_out_valid), .out_ready_i(m_ready), .n_o(l_n), .neg_o(l_neg)
  );
  tu_pipe_valid #(.Depth(LL)) u_lside (
    .clk_i, .rst_ni, .in_valid_i(l_valid), .in_ready_o(l_ctrl_ready),
    .out_valid_o(l_ctrl_valid), .out_ready_i(m_ready), .en_o(l_en), .stage_valid_o(l_stage_valid)
  );
  always_ff @(posedge clk_i) begin
    if (l_en) begin
      l_side_q[0] <= {frac(u_i, lw_i), frac(v_i, lh_i), vx_i, vy_i, vz_i, scale_i, layers_i,
                      adaptive_i && !iter_i && !dm_i, iter_i, dm_i, dlayers_i, dbase_i, hbase_i, hlw_i, hlh_i};
      for (int k = 1; k < LL; k++) l_side_q[k] <= l_side_q[k-1];
    end
  end
  logic [PF-1:0] m_fu, m_fv;
  logic [VW-1:0] m_vx, m_vy, m_vz;
  logic [SW-1:0] m_s;
  logic [NW-1:0] m_layers, m_n;
  logic          m_adaptive, m_iter, m_dm;
  logic [LyW-1:0] m_dlayers;
  logic [AW-1:0] m_hbase, m_dbase;
  logic [3:0]    m_hlw, m_hlh;
  assign {m_fu, m_fv, m_vx, m_vy, m_vz, m_s, m_layers, m_adaptive, m_iter, m_dm, m_dlayers, m_dbase,
          m_hbase, m_hlw, m_hlh} =
      l_side_q[LL-1];
  assign m_n = m_adaptive ? l_n : m_layers;

  // ---- POM unit (wrap: the march stays in one repeat) ---------------------------------------
  logic            p_valid, p_ready;
  logic [PUvW-1:0] p_u, p_v;
  logic [NW-1:0]   p_n, p_steps;
  logic [tu_formats_pkg::PomWW-1:0] p_w;
  logic            p_discard, p_back, p_clamped, p_nonconv, p_iter;
  tu_pom_unit #(.DepthPort(1), .SideW(NW + 1), .HasMarch(HasPom), .HasIter(HasIterParallax),
                .HasDm(HasDistanceMap)) u_pom (
    .clk_i, .rst_ni, .in_valid_i(l_out_valid), .in_ready_o(m_ready),
    .u_i(PUvW'(m_fu)), .v_i(PUvW'(m_fv)), .vx_i(m_vx), .vy_i(m_vy), .vz_i(m_vz), .s_i(m_s),
    .n_i(m_n), .wrap_i(1'b1), .iter_i(m_iter), .dm_i(m_dm), .dlayers_i(m_dlayers), .dbase_i(m_dbase),
    .base_i(m_hbase), .lw_i(m_hlw), .lh_i(m_hlh),
    .side_i({m_iter, m_n}),
    .d_req_o, .d_addr_o, .d_data_i,
    .out_valid_o(p_valid), .out_ready_i(p_ready),
    .u_o(p_u), .v_o(p_v), .steps_o(p_steps), .w_o(p_w), .discard_o(p_discard),
    .back_o(p_back), .clamped_o(p_clamped), .nonconv_o(p_nonconv), .side_o({p_iter, p_n})
  );

  // ---- Output: FIFO head, joined with the POM result when shifted ---------------------------
  logic             h_shift;
  logic [UvW-1:0]   h_u, h_v;
  logic [3:0]       h_lw, h_lh;
  assign {h_shift, h_u, h_v, h_lw, h_lh, side_o} = f_data;
  assign out_valid_o = f_valid && (!h_shift || p_valid);
  assign f_ready     = out_ready_i && (!h_shift || p_valid);
  assign p_ready     = f_valid && h_shift && out_ready_i;

  // Repeat part of c | T'' in level-0 texel codes: (t << l) >> Sh (floored) below bit l + Sh.
  function automatic logic [UvW-1:0] put_back(input logic [UvW-1:0] c, input logic [PF-1:0] t,
                                              input logic [3:0] l);
    logic [UvW-1:0] keep;
    keep = ~((UvW'(1) << (5'(l) + 5'(Sh))) - UvW'(1));
    put_back = (c & keep) | UvW'(((UvW+Sh)'(t) << l) >> Sh);
  endfunction
  assign u_o = h_shift ? put_back(h_u, p_u[PF-1:0], h_lw) : h_u;
  assign v_o = h_shift ? put_back(h_v, p_v[PF-1:0], h_lh) : h_v;
  assign n_o = h_shift ? p_n : '0;
  assign steps_o = h_shift ? p_steps : '0;
  // relief::ReliefFlag: the back flag is POM's (the iterative method reports no mirroring)
  assign flags_o = h_shift ? {p_back && !p_iter, p_nonconv, p_clamped} : 3'b0;

  // T'' is in [0, 1) (wrap); the weight is the unit's diagnostic, discard is never raised with
  // wrap; the layers controller twins tu_pom_layers' own.
  logic unused;
  assign unused = ^{p_u[PUvW-1:PF], p_v[PUvW-1:PF], p_w, p_discard,
                    l_neg, l_ctrl_ready, l_ctrl_valid, l_stage_valid};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, n_o, steps_o, flags_o, side_o})
  `TU_ASSERT_HANDSHAKE(InHandshake, in_valid_i, in_ready_o, {u_i, v_i, lw_i, lh_i, rel_i, guard_i, adaptive_i, iter_i, dm_i, dlayers_i, dbase_i, layers_i, scale_i, hbase_i, hlw_i, hlh_i, side_i})
endmodule
