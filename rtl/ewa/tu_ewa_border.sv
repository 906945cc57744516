// EWA sub-texel border weight of one walked texel (docs/blocks/ewa.md "Border weights"),
// bit-exact with ewa::fx::border + apply_border:
//   S1      gu, gv = K^T (xi, eta) >> 16 (wrapped to EwaGradW); zone tests Q < 1/4, Q > 9/4
//   S2      g2 = gu^2 + gv^2
//   S3..26  r = floor(sqrt Q), |g| = floor(sqrt g2)  (tu_isqrt_pipe x 2, 24 stages)
//   S27     num = (1 - r) r, den = |g| 2^10, band = 2 |num| < 4097 den, n = |num| + den / 2
//   S28..39 |d| = n / den  (tu_udiv_pipe, 12 stages)
//   S40     d = sign(num) |d| (ClipIn s13.12)
//   clip    v(d): tu_clip_p1 (ClipVariant 0, mm_p1) | tu_clip_horner (1, mm_p3) | tu_clip_estrin
//           (2, mm_p3_estrin), advancing with this pipeline's enable
//   last    w = inside ? w_i : band ? ((Q < 1 ? w_i : 2^-8) v + 2^15) >> 16 : 0
// Latency 41 + the clip scheme's, II = 1 (one tu_pipe_valid for the whole pipeline).
`include "tu_assert.svh"
module tu_ewa_border #(
  parameter int ClipVariant = 0
) (
  input  logic                                     clk_i,
  input  logic                                     rst_ni,
  input  logic                                     in_valid_i,
  output logic                                     in_ready_o,
  input  logic [62:0]                              q_i,      // u63.44 (EwaQW)
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] xi_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] eta_i,
  input  logic signed [tu_formats_pkg::EwaKW-1:0]  kxu_i,
  input  logic signed [tu_formats_pkg::EwaKW-1:0]  kxv_i,
  input  logic signed [tu_formats_pkg::EwaKW-1:0]  kyu_i,
  input  logic signed [tu_formats_pkg::EwaKW-1:0]  kyv_i,
  input  logic [tu_formats_pkg::GaussSqW-1:0]      w_i,      // the weight source at Q (Q < 1)
  output logic                                     out_valid_o,
  input  logic                                     out_ready_i,
  output logic [1:0]                               zone_o,   // 0 inside, 1 band, 2 outside
  output logic [tu_formats_pkg::ClipInW-1:0]       d_o,      // band only, else 0
  output logic [tu_formats_pkg::GaussSqW-1:0]      w_o
);
  localparam int GW    = tu_formats_pkg::EwaGradW;
  localparam int GF    = tu_formats_pkg::EwaGradF;
  localparam int RW    = tu_formats_pkg::EwaRootW;
  localparam int KW    = tu_formats_pkg::EwaKW;
  localparam int XW    = tu_formats_pkg::EwaXiW;
  localparam int WW    = tu_formats_pkg::GaussSqW;
  localparam int CW    = tu_formats_pkg::ClipInW;
  localparam int CF    = tu_formats_pkg::ClipInF;
  localparam int GSh   = 2 * tu_formats_pkg::EwaKF + tu_formats_pkg::EwaPosF - GF;  // 16
  localparam int QF    = 2 * GF;                                                     // 44
  localparam int Sq    = RW;          // root stages
  localparam int DivW  = CF;          // quotient bits: |d| <= 2^(ClipInF-1) + 1 in the band
  localparam int ClipLat = ClipVariant == 1 ? tu_formats_pkg::ClipHornerLatency
                         : ClipVariant == 2 ? tu_formats_pkg::ClipEstrinLatency
                                            : tu_formats_pkg::ClipP1Latency;
  localparam int Lat   = 1 + 1 + Sq + 1 + DivW + 1 + ClipLat + 1;
  localparam int NumW  = 2 * RW + 2;  // (2^22 - r) r, signed
  localparam int DenW  = RW + GF - CF;  // |g| 2^(GF - CF)
  localparam int ND    = NumW + 1;

  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- S1: gradient, zone tests
  localparam int PW = KW + XW + 1;
  logic signed [PW-1:0] gu_full, gv_full;
  assign gu_full = PW'(kxu_i * xi_i) + PW'(kyu_i * eta_i);
  assign gv_full = PW'(kxv_i * xi_i) + PW'(kyv_i * eta_i);
  logic signed [GW-1:0] gu1_q, gv1_q;
  logic                 lo1_q, hi1_q, lt1_q;
  logic [2*RW-1:0]      q1_q;
  logic [WW-1:0]        w1_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      gu1_q <= gu_full[GSh +: GW];
      gv1_q <= gv_full[GSh +: GW];
      lo1_q <= q_i < (63'(1) << (QF - 2));
      hi1_q <= q_i > (63'(9) << (QF - 2));
      lt1_q <= q_i < (63'(1) << QF);
      q1_q  <= q_i[2*RW-1:0];
      w1_q  <= w_i;
    end
  end

  // ---- S2: g2
  logic [2*RW-1:0] g2_q, q2_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      g2_q <= (2*RW)'(gu1_q * gu1_q) + (2*RW)'(gv1_q * gv1_q);
      q2_q <= q1_q;
    end
  end
  // side data S1 -> S27: zone flags, Q < 1, w
  localparam int SideW = 3 + WW;
  logic [SideW-1:0] side2_q, side26;
  always_ff @(posedge clk_i) if (en) side2_q <= {lo1_q, hi1_q, lt1_q, w1_q};

  // ---- S3..S26: roots
  logic [RW-1:0] r26, g26;
  tu_isqrt_pipe #(.InW(2*RW)) u_rq (.clk_i, .en_i(en), .x_i(q2_q), .r_o(r26));
  tu_isqrt_pipe #(.InW(2*RW)) u_rg (.clk_i, .en_i(en), .x_i(g2_q), .r_o(g26));
  tu_brdf_delay #(.W(SideW), .Depth(Sq)) u_side1 (.clk_i, .en_i(en), .d_i(side2_q), .q_o(side26));

  // ---- S27: numerator, denominator, band
  logic signed [NumW-1:0] num;
  logic [NumW-1:0]        mag;
  logic [DenW-1:0]        den;
  assign num = (NumW'(1) <<< GF) - NumW'($signed({1'b0, r26}));
  logic signed [NumW-1:0] nump;
  assign nump = num * NumW'($signed({1'b0, r26}));
  assign mag  = nump[NumW-1] ? NumW'(-nump) : NumW'(nump);
  assign den  = DenW'(g26) << (GF - CF);
  logic [ND-1:0] n27_q;
  logic [DenW-1:0] den27_q;
  logic band27_q, neg27_q, pos27_q;
  logic [SideW-1:0] side27_q, side39;
  always_ff @(posedge clk_i) begin
    if (en) begin
      band27_q <= (ND+13)'(mag) * (ND+13)'(2) < (ND+13)'(den) * (ND+13)'((1 << CF) + 1);
      neg27_q  <= nump[NumW-1];
      pos27_q  <= !nump[NumW-1] && nump != '0;
      n27_q    <= ND'(mag) + ND'(den[DenW-1:1]);
      den27_q  <= den;
      side27_q <= side26;
    end
  end

  // ---- S28..S39: |d| = n / den
  logic [DivW-1:0] dm39;
  logic [2:0]      fl39;
  tu_udiv_pipe #(.NW(ND), .DW(DenW), .QW(DivW)) u_div (.clk_i, .en_i(en), .n_i(n27_q), .d_i(den27_q), .q_o(dm39));
  tu_brdf_delay #(.W(SideW + 3), .Depth(DivW)) u_side2 (
    .clk_i, .en_i(en), .d_i({side27_q, band27_q, neg27_q, pos27_q}), .q_o({side39, fl39}));

  // ---- S40: d and the zone
  logic [CW-1:0]    d40_q;
  logic [1:0]       zone40_q;
  logic [WW:0]      wl40_q;   // {Q < 1, w}
  always_ff @(posedge clk_i) begin
    if (en) begin
      // side39 = {lo, hi, lt, w}; fl39 = {band, neg, pos}
      if (side39[SideW-1])      zone40_q <= 2'd0;
      else if (side39[SideW-2]) zone40_q <= 2'd2;
      else if (fl39[2])         zone40_q <= 2'd1;
      else                      zone40_q <= fl39[0] ? 2'd0 : 2'd2;
      d40_q  <= (!side39[SideW-1] && !side39[SideW-2] && fl39[2])
                ? (fl39[1] ? CW'(-$signed({1'b0, dm39})) : CW'(dm39)) : '0;
      wl40_q <= side39[WW:0];
    end
  end

  // ---- clip volume v(d), advancing with en (always valid inside; see tu_ewa_walk's weights)
  logic [tu_formats_pkg::ClipOutW-1:0] v;
  logic [1:0] clip_hs_unused;
  if (ClipVariant == 1) begin : g_horner
    tu_clip_horner u_clip (.clk_i, .rst_ni, .in_valid_i(1'b1), .in_ready_o(clip_hs_unused[0]),
      .d_i(d40_q), .out_valid_o(clip_hs_unused[1]), .out_ready_i(en), .v_o(v));
  end else if (ClipVariant == 2) begin : g_estrin
    tu_clip_estrin u_clip (.clk_i, .rst_ni, .in_valid_i(1'b1), .in_ready_o(clip_hs_unused[0]),
      .d_i(d40_q), .out_valid_o(clip_hs_unused[1]), .out_ready_i(en), .v_o(v));
  end else begin : g_p1
    tu_clip_p1 u_clip (.clk_i, .rst_ni, .in_valid_i(1'b1), .in_ready_o(clip_hs_unused[0]),
      .d_i(d40_q), .out_valid_o(clip_hs_unused[1]), .out_ready_i(en), .v_o(v));
  end
  logic [CW-1:0]  dc;
  logic [1:0]     zonec;
  logic [WW:0]    wlc;
  tu_brdf_delay #(.W(CW + 2 + WW + 1), .Depth(ClipLat)) u_side3 (
    .clk_i, .en_i(en), .d_i({d40_q, zone40_q, wl40_q}), .q_o({dc, zonec, wlc}));

  // ---- last: the weight
  localparam int EdgeW = 1 << (tu_formats_pkg::GaussSqF - 8);  // w(1) = 2^-8
  logic [WW-1:0] wb;
  logic [WW+tu_formats_pkg::ClipOutW-1:0] prod;
  assign wb   = wlc[WW] ? wlc[WW-1:0] : WW'(EdgeW);
  assign prod = (WW+tu_formats_pkg::ClipOutW)'(wb) * (WW+tu_formats_pkg::ClipOutW)'(v)
              + (WW+tu_formats_pkg::ClipOutW)'(1 << (tu_formats_pkg::ClipOutF - 1));
  always_ff @(posedge clk_i) begin
    if (en) begin
      zone_o <= zonec;
      d_o    <= dc;
      unique case (zonec)
        2'd0:    w_o <= wlc[WW-1:0];
        2'd1:    w_o <= WW'(prod >> tu_formats_pkg::ClipOutF);
        default: w_o <= '0;
      endcase
    end
  end

  logic unused;
  assign unused = ^{stage_valid, clip_hs_unused, q_i[62:2*RW], gu_full, gv_full};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {zone_o, d_o, w_o})
endmodule
