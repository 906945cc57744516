// Pixel footprint (B2), recurrence variant: the seed's forward differences (seed 001 §2,
// corrected) Ux = nUx / (q (q+G)), Vx = nVx / (q (q+G)), Uy = nUy / (q (q+H)), Vy = nVy / (q (q+H)),
// then the analytic unit (tu_ellipse) on J with q := 1. Bit-exact with
// cmodel/blocks/ellipse/ellipse_fx.cpp (fx::recurrence = analytic(rec_front)); formats in
// docs/blocks/ellipse.md. Latency EllRecLatency (EllRecFrontLatency 6 + EllLatency 5), II = 1.
// The numerators (+M, +N per row, -M, -N per pixel) and q(x+1) = q + G, q(y+1) = q + H come from
// the span walk's recurrence registers (tu_span_expand).
//   F0: horizon guard on q, q+G, q+H; dX = q (q+G), dY = q (q+H) (exact); leading one, mantissas
//       -> two tu_recip_core (4 stages)
//   F4: J = round_half_up(n R >> (RecipOutF + e - 2 PerspF)), saturated to s(EllNumW).EllNumF
//   F5: det J = Ux Vy - Uy Vx (exact), normalised to the det3 float format (dm truncated)
//   then tu_ellipse on (J, q := 1 or 0 on the horizon, det J): log2 q = 0 and 1/q = R(1.0) = 1.
module tu_ellipse_rec (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic                                   in_valid_i,
  output logic                                   in_ready_o,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nux_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nvx_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nuy_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nvy_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]     q_i,
  input  logic [tu_formats_pkg::EllRecQW-1:0]    qg_i,      // q(x+1) = q + G
  input  logic [tu_formats_pkg::EllRecQW-1:0]    qh_i,      // q(y+1) = q + H
  input  logic [tu_formats_pkg::EllAnisoW-1:0]   laniso_i,
  input  logic [tu_formats_pkg::EllMaxLodW-1:0]  maxlod_i,
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] lbias_i,   // trilinear: lod bias, min / max lod
  input  logic [tu_formats_pkg::EllLodW-1:0]     lminlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]     lmaxlod_i,
  input  logic [3:0]                             lbase_i,   // the material's levels (tex::level_range)
  input  logic [3:0]                             ltop_i,
  output logic                                   out_valid_o,
  input  logic                                   out_ready_i,
  output logic [tu_formats_pkg::EllCoefW-1:0]    ae_o,
  output logic [tu_formats_pkg::EllCoefW-1:0]    be_o,
  output logic [tu_formats_pkg::EllCoefW-1:0]    ce_o,
  output logic [tu_formats_pkg::EllEexpW-1:0]    eexp_o,
  output logic [tu_formats_pkg::EllFmW-1:0]      fm_o,
  output logic [tu_formats_pkg::EllFexpW-1:0]    fexp_o,
  output logic [tu_formats_pkg::EllLogW-1:0]     lmaj_o,
  output logic [tu_formats_pkg::EllLogW-1:0]     lmin_o,
  output logic [tu_formats_pkg::EllLodW-1:0]     lod_o,
  output logic [4:0]                             flags_o,
  output logic [tu_formats_pkg::EllLogW-1:0]     lrho_o,
  output logic [tu_formats_pkg::EllLodW-1:0]     tlod_o,
  output logic [2:0]                             tflags_o,
  output logic [tu_formats_pkg::EllLodW-1:0]     elod_o     // EWA level (tu_ellipse)
);
  localparam int NW  = tu_formats_pkg::EllNumW;
  localparam int NF  = tu_formats_pkg::EllNumF;
  localparam int QW  = tu_formats_pkg::PerspQW;
  localparam int GW  = tu_formats_pkg::EllRecQW;
  localparam int DnW = tu_formats_pkg::EllRecDW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int PW  = tu_formats_pkg::EllRecPW;
  localparam int JdW = tu_formats_pkg::EllRecJdW;
  localparam int DW  = tu_formats_pkg::EllDetW;
  localparam int EW  = tu_formats_pkg::EllDetExpW;
  localparam int FL  = tu_formats_pkg::EllRecFrontLatency;
  localparam int CL  = FL - 2;  // reciprocal core stages
  localparam int ShOff = tu_formats_pkg::RecipOutF - 2 * tu_formats_pkg::PerspF;
  localparam logic [GW-1:0] GuardVal = GW'(1) << (tu_formats_pkg::PerspF - tu_formats_pkg::PerspGuardLog2);
  localparam logic signed [PW:0] JMax = ((PW+1)'(1) <<< (NW - 1)) - (PW+1)'(1);
  localparam logic signed [PW:0] JMin = ~JMax;  // -2^(NW-1) (Yosys 0.23 drops a localparam's minus)

  // Leading one of a denominator (> 0) and its RecipMantW-bit truncated mantissa.
  function automatic logic [6:0] msb_of(input logic [DnW-1:0] v);
    msb_of = '0;
    for (int i = 0; i < DnW; i++) begin
      if (v[i]) msb_of = 7'(i);
    end
  endfunction
  // round_half_up(n R >> sh), saturated to s(EllNumW)
  function automatic logic [NW-1:0] jac(input logic [NW-1:0] n, input logic [RW-1:0] r,
                                        input logic [6:0] sh);
    logic signed [PW:0] p;
    p = (PW+1)'($signed(n) * $signed({1'b0, r}));
    p = (p + ((PW+1)'(1) <<< (sh - 7'd1))) >>> sh;
    if (p > JMax) jac = NW'(JMax);
    else if (p < JMin) jac = NW'(JMin);
    else jac = NW'(p);
  endfunction

  logic fen, f_out_valid, b_in_ready;
  logic [FL-1:0] f_stage_valid;
  tu_pipe_valid #(.Depth(FL)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o(f_out_valid), .out_ready_i(b_in_ready),
    .en_o(fen), .stage_valid_o(f_stage_valid)
  );

  // ---------------- F0: guard, denominators, mantissas ----------------
  logic                guard0;
  logic [DnW-1:0]      dx0, dy0;
  logic [6:0]          ex0, ey0;
  logic [DnW-1:0]      dxn0, dyn0;
  always_comb begin
    guard0 = q_i[QW-1] || (GW'(q_i) < GuardVal) || qg_i[GW-1] || (qg_i < GuardVal) ||
             qh_i[GW-1] || (qh_i < GuardVal);
    dx0  = DnW'(q_i) * DnW'(qg_i);  // both > 0 unless guarded (then unused)
    dy0  = DnW'(q_i) * DnW'(qh_i);
    ex0  = msb_of(dx0);
    ey0  = msb_of(dy0);
    dxn0 = dx0 << (DnW - 1 - 32'(ex0));
    dyn0 = dy0 << (DnW - 1 - 32'(ey0));
  end
  logic [RW-1:0] rx, ry;  // valid with front stage CL
  tu_recip_core u_core_x (.clk_i, .en_i(fen), .m_i(dxn0[DnW-1 -: MW]), .r_o(rx));
  tu_recip_core u_core_y (.clk_i, .en_i(fen), .m_i(dyn0[DnW-1 -: MW]), .r_o(ry));

  // numerators, shifts and the guard wait for the reciprocals
  logic [NW-1:0] nux_q [CL], nvx_q [CL], nuy_q [CL], nvy_q [CL];
  logic [6:0]    shx_q [CL], shy_q [CL];
  logic          g_q [FL-1];  // guard, to the back end's q
  always_ff @(posedge clk_i) begin
    if (fen) begin
      nux_q[0] <= nux_i;
      nvx_q[0] <= nvx_i;
      nuy_q[0] <= nuy_i;
      nvy_q[0] <= nvy_i;
      shx_q[0] <= 7'(32'(ex0) + ShOff);
      shy_q[0] <= 7'(32'(ey0) + ShOff);
      g_q[0]   <= guard0;
      for (int i = 1; i < CL; i++) begin
        nux_q[i] <= nux_q[i-1];
        nvx_q[i] <= nvx_q[i-1];
        nuy_q[i] <= nuy_q[i-1];
        nvy_q[i] <= nvy_q[i-1];
        shx_q[i] <= shx_q[i-1];
        shy_q[i] <= shy_q[i-1];
      end
      for (int i = 1; i < FL - 1; i++) g_q[i] <= g_q[i-1];
    end
  end

  // ---------------- F4: Jacobian ----------------
  logic [NW-1:0] ux_q, vx_q, uy_q, vy_q;
  always_ff @(posedge clk_i) begin
    if (fen) begin
      ux_q <= jac(nux_q[CL-1], rx, shx_q[CL-1]);
      vx_q <= jac(nvx_q[CL-1], rx, shx_q[CL-1]);
      uy_q <= jac(nuy_q[CL-1], ry, shy_q[CL-1]);
      vy_q <= jac(nvy_q[CL-1], ry, shy_q[CL-1]);
    end
  end

  // ---------------- F5: det J in the det3 float format ----------------
  logic signed [JdW-1:0] det5;
  logic [JdW-1:0]        adet5, adn5;
  logic [6:0]            md5;
  logic signed [DW-1:0]  dm5;
  always_comb begin
    det5  = JdW'($signed(ux_q) * $signed(vy_q)) - JdW'($signed(uy_q) * $signed(vx_q));
    adet5 = det5[JdW-1] ? JdW'(-det5) : JdW'(det5);
    md5   = '0;
    for (int i = 0; i < JdW; i++) begin
      if (adet5[i]) md5 = 7'(i);
    end
    adn5 = adet5 << (JdW - 1 - 32'(md5));
    dm5  = DW'({1'b0, adn5[JdW-1 -: DW-1]});
    if (det5[JdW-1]) dm5 = -dm5;
  end
  logic [NW-1:0] bux, bvx, buy, bvy;
  logic [QW-1:0] bq;
  logic [DW-1:0] bdm;
  logic [EW-1:0] bdexp;
  always_ff @(posedge clk_i) begin
    if (fen) begin
      bux   <= ux_q;
      bvx   <= vx_q;
      buy   <= uy_q;
      bvy   <= vy_q;
      bq    <= g_q[FL-2] ? '0 : QW'(1) << tu_formats_pkg::PerspF;
      bdm   <= adet5 == '0 ? '0 : dm5;
      bdexp <= adet5 == '0 ? '0 : EW'(32'(md5) - 2 * NF);
    end
  end

  // per-pixel parameters ride along the front
  logic [tu_formats_pkg::EllAnisoW-1:0]   la_q [FL];
  logic [tu_formats_pkg::EllMaxLodW-1:0]  ml_q [FL];
  logic [tu_formats_pkg::TexLodBiasW-1:0] lb_q [FL];
  logic [tu_formats_pkg::EllLodW-1:0]     ln_q [FL], lx_q [FL];
  logic [3:0]                             lbs_q [FL], ltp_q [FL];
  always_ff @(posedge clk_i) begin
    if (fen) begin
      lbs_q[0] <= lbase_i;
      ltp_q[0] <= ltop_i;
      la_q[0] <= laniso_i;
      ml_q[0] <= maxlod_i;
      lb_q[0] <= lbias_i;
      ln_q[0] <= lminlod_i;
      lx_q[0] <= lmaxlod_i;
      for (int i = 1; i < FL; i++) begin
        la_q[i] <= la_q[i-1];
        ml_q[i] <= ml_q[i-1];
        lb_q[i] <= lb_q[i-1];
        ln_q[i] <= ln_q[i-1];
        lx_q[i] <= lx_q[i-1];
        lbs_q[i] <= lbs_q[i-1];
        ltp_q[i] <= ltp_q[i-1];
      end
    end
  end

  // ---------------- back end: the analytic unit on J ----------------
  tu_ellipse u_back (
    .clk_i, .rst_ni, .in_valid_i(f_out_valid), .in_ready_o(b_in_ready),
    .nux_i(bux), .nvx_i(bvx), .nuy_i(buy), .nvy_i(bvy), .q_i(bq), .dm_i(bdm), .dexp_i(bdexp),
    .laniso_i(la_q[FL-1]), .maxlod_i(ml_q[FL-1]), .lbias_i(lb_q[FL-1]), .lminlod_i(ln_q[FL-1]),
    .lmaxlod_i(lx_q[FL-1]), .lbase_i(lbs_q[FL-1]), .ltop_i(ltp_q[FL-1]),
    .out_valid_o, .out_ready_i,
    .ae_o, .be_o, .ce_o, .eexp_o, .fm_o, .fexp_o, .lmaj_o, .lmin_o, .lod_o, .flags_o,
    .lrho_o, .tlod_o, .tflags_o, .elod_o
  );

  logic unused;
  assign unused = ^{f_stage_valid, dxn0[DnW-MW-1:0], dyn0[DnW-MW-1:0],
                    adn5[JdW-DW:0]};
endmodule
