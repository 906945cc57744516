// Pixel footprint (B2), analytic variant: EWA ellipse scaled by q^4, axes, anisotropy clamp and
// mip LOD. Bit-exact with cmodel/blocks/ellipse/ellipse_fx.cpp (fx::analytic); formats in
// docs/blocks/ellipse.md. Latency EllLatency (5), II = 1.
//   S0: horizon guard, leading one of q (mantissa -> tu_recip_core, log2 q), the six products
//   S1: s = Ae'+Ce', d = Ae'-Ce'; block-floating ellipse outputs; normalise s, d, Be' to EllNrmW
//   S2: r = isqrt(d^2 + Be'^2), lam = s + r
//   S3: log2(lam) -> 2 log2 major
//   S4: f = det3 * R (R = 1/q mantissa from the core), log2|f| -> 2 log2 minor, clamp, LOD, flags
// Trilinear's GL LOD (texture/trilinear_lod.hpp): Px' = nUx^2 + nVx^2, Py' = nUy^2 + nVy^2 from the
// S0 products, log2 max(Px', Py') in S1 -> lrho (log2 rho); S4 adds the material's bias and clamps
// to [min lod, max lod] and to its levels [base, top] (tex::trilinear_lod, tu_lod_rule) -> tlod,
// tflags. The same rule on the clamped minor axis gives the EWA's level elod (render_cmodel).
// lod_o is B2's own LOD (floor of the minor axis, [0, max_lod]).
`include "tu_assert.svh"
module tu_ellipse (
  input  logic                                   clk_i,
  input  logic                                   rst_ni,
  input  logic                                   in_valid_i,
  output logic                                   in_ready_o,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nux_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nvx_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nuy_i,
  input  logic [tu_formats_pkg::EllNumW-1:0]     nvy_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]     q_i,
  input  logic [tu_formats_pkg::EllDetW-1:0]     dm_i,
  input  logic [tu_formats_pkg::EllDetExpW-1:0]  dexp_i,
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
  output logic [tu_formats_pkg::EllLogW-1:0]     lrho_o,    // GL log2 rho (s18.10)
  output logic [tu_formats_pkg::EllLodW-1:0]     tlod_o,    // trilinear lod (u12.8)
  output logic [2:0]                             tflags_o,  // tex::TriFlag
  output logic [tu_formats_pkg::EllLodW-1:0]     elod_o     // EWA level: the rule on lmin (u12.8)
);
  localparam int NW  = tu_formats_pkg::EllNumW;
  localparam int NF  = tu_formats_pkg::EllNumF;
  localparam int QW  = tu_formats_pkg::PerspQW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int DW  = tu_formats_pkg::EllDetW;
  localparam int LMW = tu_formats_pkg::EllLogMantW;
  localparam int L1  = tu_formats_pkg::EllLogF + 1;   // internal log fraction bits
  localparam int LW  = tu_formats_pkg::EllLogW;
  localparam int NrW = tu_formats_pkg::EllNrmW;
  localparam int CW  = tu_formats_pkg::EllCoefW;
  localparam int XW  = 2 * NW + 4;                    // exact sums (signed)
  localparam int SqW = 2 * NrW + 4;                   // d^2 + b^2
  localparam int RtW = SqW / 2;                       // isqrt
  localparam int PW  = DW + RW + 1;                   // det3 mantissa * R (signed)
  localparam logic [QW-1:0] GuardVal = QW'(1) << (tu_formats_pkg::PerspF - tu_formats_pkg::PerspGuardLog2);
  localparam logic signed [31:0] LogMax = 32'((1 << (LW - 1)) - 1);
  // -2^(LW-1) bit by bit: Yosys 0.23 drops a unary minus or ~ before a size cast in a localparam
  // (-32'(...) and ~32'(...) both gave +2^(LW-1) - 1 there: sat_log was the constant LogMax in every
  // netlist; docs/area-timing.md "Gate-level simulation").
  localparam logic signed [31:0] LogMin = {{(33 - LW){1'b1}}, {(LW - 1){1'b0}}};
  localparam int RhW = tu_formats_pkg::EllRhoW;
  localparam int BW  = tu_formats_pkg::TexLodBiasW;
  localparam int LDW = tu_formats_pkg::EllLodW;

  // ---------------- helpers ----------------
  function automatic logic signed [31:0] sat_log(input logic signed [31:0] v);
    if (v > LogMax) sat_log = LogMax;
    else if (v < LogMin) sat_log = LogMin;
    else sat_log = v;
  endfunction

  logic en;
  logic [4:0] stage_valid;
  tu_pipe_valid #(.Depth(tu_formats_pkg::EllLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---------------- S0 ----------------
  logic          guard0;
  logic [5:0]    e0;
  logic [QW-1:0] qn0;
  logic [MW-1:0] mq0;
  logic signed [XW-1:0] a0, c0, b0;
  logic signed [2*NW-1:0] pxx, pyy, uxx, uyy, uvx, uvy;
  always_comb begin
    guard0 = q_i[QW-1] || (q_i < GuardVal);
    e0 = '0;
    for (int i = 0; i < QW - 1; i++) begin
      if (q_i[i]) e0 = 6'(i);
    end
    qn0 = q_i << (QW - 1 - 32'(e0));
    mq0 = qn0[QW-1 -: MW];
    pxx = $signed(nvx_i) * $signed(nvx_i);
    pyy = $signed(nvy_i) * $signed(nvy_i);
    uxx = $signed(nux_i) * $signed(nux_i);
    uyy = $signed(nuy_i) * $signed(nuy_i);
    uvx = $signed(nux_i) * $signed(nvx_i);
    uvy = $signed(nuy_i) * $signed(nvy_i);
    a0 = XW'(pxx) + XW'(pyy);
    c0 = XW'(uxx) + XW'(uyy);
    b0 = -((XW'(uvx) + XW'(uvy)) <<< 1);
  end
  // GL LOD sums by screen axis (exact: |n| < 2^47, so each sum < 2^95)
  logic [RhW-1:0] px0, py0;
  assign px0 = RhW'(uxx) + RhW'(pxx);
  assign py0 = RhW'(uyy) + RhW'(pyy);
  logic [L1-1:0] lqf0;  // log2 fraction of q's mantissa
  tu_log2_frac #(.MantW(LMW), .FracW(L1)) u_log_q (.m_i(mq0), .frac_o(lqf0));
  logic [RW-1:0] r_core;  // 1/q mantissa, valid with stage 4
  tu_recip_core u_core (.clk_i, .en_i(en), .m_i(mq0), .r_o(r_core));

  logic [5:0]           e_q1;
  logic [L1-1:0]        lqf_q1;
  logic signed [XW-1:0] a_q1, b_q1, c_q1;
  logic [DW-1:0]        dm_q [4];
  logic [7:0]           dx_q [4];
  logic [13:0]          la_q [4];
  logic [3:0]           ml_q [4];
  logic                 g_q [4];
  logic [5:0]           e_q [4];
  logic [RhW-1:0]       pm_q1;
  logic [BW-1:0]        lb_q [4];
  logic [LDW-1:0]       ln_q [4], lx_q [4];
  logic [3:0]           lbs_q [4], ltp_q [4];
  always_ff @(posedge clk_i) begin
    if (en) begin
      pm_q1  <= px0 > py0 ? px0 : py0;
      lb_q[0] <= lbias_i;
      ln_q[0] <= lminlod_i;
      lx_q[0] <= lmaxlod_i;
      lbs_q[0] <= lbase_i;
      ltp_q[0] <= ltop_i;
      for (int i = 1; i < 4; i++) begin
        lb_q[i] <= lb_q[i-1];
        ln_q[i] <= ln_q[i-1];
        lx_q[i] <= lx_q[i-1];
        lbs_q[i] <= lbs_q[i-1];
        ltp_q[i] <= ltp_q[i-1];
      end
      e_q1   <= e0;
      lqf_q1 <= lqf0;
      a_q1   <= a0;
      b_q1   <= b0;
      c_q1   <= c0;
      dm_q[0] <= dm_i;
      dx_q[0] <= dexp_i;
      la_q[0] <= laniso_i;
      ml_q[0] <= maxlod_i;
      g_q[0]  <= guard0;
      e_q[0]  <= e0;
      for (int i = 1; i < 4; i++) begin
        dm_q[i] <= dm_q[i-1];
        dx_q[i] <= dx_q[i-1];
        la_q[i] <= la_q[i-1];
        ml_q[i] <= ml_q[i-1];
        g_q[i]  <= g_q[i-1];
        e_q[i]  <= e_q[i-1];
      end
    end
  end

  // ---------------- S1 ----------------
  logic [XW-1:0]        s1;
  logic signed [XW-1:0] d1;
  logic [6:0]           ms1, kout1, k1;
  logic                 sz1;
  logic signed [31:0]   lq1;
  always_comb begin
    s1 = XW'(a_q1) + XW'(c_q1);
    d1 = a_q1 - c_q1;
    sz1 = (s1 == '0);
    ms1 = '0;
    for (int i = 0; i < XW; i++) begin
      if (s1[i]) ms1 = 7'(i);
    end
    kout1 = (!sz1 && ms1 > 7'(CW - 3)) ? ms1 - 7'(CW - 3) : 7'd0;
    k1    = (!sz1 && ms1 > 7'(NrW - 1)) ? ms1 - 7'(NrW - 1) : 7'd0;
    lq1   = ((32'(e_q1) - 32'(tu_formats_pkg::PerspF)) <<< L1) + 32'(lqf_q1);
  end
  logic [6:0]         mr1;
  logic [RhW-1:0]     pmn1;
  logic signed [31:0] lp1, lr1;
  logic [L1-1:0]      lpf1;
  always_comb begin
    mr1 = '0;
    for (int i = 0; i < RhW; i++) begin
      if (pm_q1[i]) mr1 = 7'(i);
    end
    pmn1 = pm_q1 << (RhW - 1 - 32'(mr1));
  end
  tu_log2_frac #(.MantW(LMW), .FracW(L1)) u_log_rho (.m_i(pmn1[RhW-1 -: LMW]), .frac_o(lpf1));
  always_comb begin
    // 2 log2 rho = log2 max(Px', Py') - 2 NumF - 4 log2 q (L1 fraction bits); halved, floored
    lp1 = ((32'(mr1) - 32'(2 * NF)) <<< L1) + 32'(lpf1);
    lp1 = lp1 - (lq1 <<< 2);
    lr1 = (pm_q1 == '0) ? LogMin : sat_log(lp1 >>> 2);
  end
  logic signed [31:0] lr_q [3];
  always_ff @(posedge clk_i) begin
    if (en) begin
      lr_q[0] <= lr1;
      lr_q[1] <= lr_q[0];
      lr_q[2] <= lr_q[1];
    end
  end
  logic [CW-1:0]         ae_q2, be_q2, ce_q2;
  logic [5:0]            eexp_q2;
  logic [NrW:0]          sn_q2;
  logic signed [NrW+2:0] dn_q2, bn_q2;
  logic [6:0]            k_q2;
  logic                  sz_q2;
  logic signed [31:0]    lq_q2;
  always_ff @(posedge clk_i) begin
    if (en) begin
      ae_q2   <= CW'(a_q1 >>> kout1);
      ce_q2   <= CW'(c_q1 >>> kout1);
      be_q2   <= CW'(b_q1 >>> kout1);
      eexp_q2 <= 6'(kout1);
      sn_q2   <= (NrW+1)'(s1 >> k1);
      dn_q2   <= (NrW+3)'(d1 >>> k1);
      bn_q2   <= (NrW+3)'(b_q1 >>> k1);
      k_q2    <= k1;
      sz_q2   <= sz1;
      lq_q2   <= lq1;
    end
  end

  // ---------------- S2: integer square root (restoring, floor) ----------------
  logic [SqW-1:0] dd2;
  logic [RtW-1:0] root2;
  logic [RtW+1:0] rem2, test2;
  always_comb begin
    dd2 = SqW'(SqW'(dn_q2) * SqW'(dn_q2)) + SqW'(SqW'(bn_q2) * SqW'(bn_q2));
    root2 = '0;
    rem2 = '0;
    for (int i = RtW - 1; i >= 0; i--) begin
      rem2  = {rem2[RtW-1:0], dd2[2*i+1 -: 2]};
      test2 = {root2, 2'b01};
      root2 = root2 << 1;
      if (rem2 >= test2) begin
        rem2  = rem2 - test2;
        root2 = root2 | RtW'(1);
      end
    end
  end
  logic [RtW:0]       lam_q3;
  logic [6:0]         k_q3;
  logic               sz_q3;
  logic signed [31:0] lq_q3;
  logic [CW-1:0]      ae_q3, be_q3, ce_q3;
  logic [5:0]         eexp_q3;
  always_ff @(posedge clk_i) begin
    if (en) begin
      lam_q3  <= (RtW+1)'(sn_q2) + (RtW+1)'(root2);
      k_q3    <= k_q2;
      sz_q3   <= sz_q2;
      lq_q3   <= lq_q2;
      ae_q3   <= ae_q2;
      be_q3   <= be_q2;
      ce_q3   <= ce_q2;
      eexp_q3 <= eexp_q2;
    end
  end

  // ---------------- S3: log2(lam) ----------------
  logic [4:0]         ml3;
  logic [RtW:0]       lamn3;
  logic signed [31:0] ll3;
  logic [L1-1:0]      llf3;
  always_comb begin
    ml3 = '0;
    for (int i = 0; i <= RtW; i++) begin
      if (lam_q3[i]) ml3 = 5'(i);
    end
    lamn3 = lam_q3 << (RtW - 32'(ml3));
  end
  tu_log2_frac #(.MantW(LMW), .FracW(L1)) u_log_lam (.m_i(LMW'(lamn3 >> (RtW + 1 - LMW))), .frac_o(llf3));
  assign ll3 = ((32'(ml3) + 32'(k_q3) - 32'(2 * NF + 1)) <<< L1) + 32'(llf3);
  logic signed [31:0] ll_q4, lmaj2_q4;
  logic               sz_q4;
  logic [CW-1:0]      ae_q4, be_q4, ce_q4;
  logic [5:0]         eexp_q4;
  always_ff @(posedge clk_i) begin
    if (en) begin
      ll_q4    <= ll3;
      lmaj2_q4 <= ll3 - (lq_q3 <<< 2);
      sz_q4    <= sz_q3;
      ae_q4    <= ae_q3;
      be_q4    <= be_q3;
      ce_q4    <= ce_q3;
      eexp_q4  <= eexp_q3;
    end
  end

  // ---------------- S4: f = det3 / q, minor axis, clamp, LOD ----------------
  logic signed [PW-1:0] p4;
  logic [PW-1:0]        ap4, apn4;
  logic [6:0]           mp4;
  logic                 fz4;
  logic signed [31:0]   off4, lf4, fexp4, lmaj4, cap4, lmin4, lod4, top4;
  logic [4:0]           flags4;
  always_comb begin
    p4  = $signed(dm_q[3]) * $signed({1'b0, r_core});
    ap4 = p4[PW-1] ? PW'(-p4) : PW'(p4);
    fz4 = (ap4 == '0);
    mp4 = '0;
    for (int i = 0; i < PW; i++) begin
      if (ap4[i]) mp4 = 7'(i);
    end
    apn4  = ap4 << (PW - 1 - 32'(mp4));
    off4  = 32'($signed(dx_q[3])) - 32'(DW - 2) - 32'(tu_formats_pkg::RecipOutF) +
            32'(tu_formats_pkg::PerspF) - 32'(e_q[3]);
    fexp4 = 32'(mp4) + off4;
    if (fexp4 > 32'sd127) fexp4 = 32'sd127;
    if (fexp4 < -32'sd128) fexp4 = -32'sd128;
  end
  logic [L1-1:0] lff4;
  tu_log2_frac #(.MantW(LMW), .FracW(L1)) u_log_f (.m_i(apn4[PW-1 -: LMW]), .frac_o(lff4));
  always_comb begin
    lf4   = ((32'(mp4) + off4) <<< L1) + 32'(lff4);
    flags4 = '0;
    lmaj4 = sat_log(lmaj2_q4 >>> 2);
    cap4  = sat_log(lmaj4 - 32'(la_q[3]));
    if (fz4) begin
      flags4[1] = 1'b1;
      flags4[2] = 1'b1;
      lmin4 = cap4;
    end else begin
      lmin4 = sat_log(((lf4 <<< 1) - ll_q4) >>> 2);
      if (cap4 > lmin4) begin
        flags4[2] = 1'b1;
        lmin4 = cap4;
      end
    end
    top4 = 32'(ml_q[3]) <<< tu_formats_pkg::EllLodF;
    lod4 = lmin4 >>> (tu_formats_pkg::EllLogF - tu_formats_pkg::EllLodF);
    if (lod4 < 0) begin
      flags4[4] = 1'b1;
      lod4 = 0;
    end else if (lod4 > top4) begin
      flags4[3] = 1'b1;
      lod4 = top4;
    end
    if (sz_q4) begin  // point footprint
      flags4 = 5'b10010;
      lmaj4 = LogMin;
      lmin4 = LogMin;
      lod4 = 0;
    end
  end
  // The sampler's rule (tex::trilinear_lod) on the values output (0 on the horizon, as the C model).
  logic [LDW-1:0] tlod4, elod4;
  logic [2:0]     tflags4, eflags4;
  tu_lod_rule u_tri_rule (
    .l_i(g_q[3] ? 32'sd0 : lr_q[2]), .bias_i(lb_q[3]), .minlod_i(ln_q[3]), .maxlod_i(lx_q[3]),
    .base_i(lbs_q[3]), .top_i(ltp_q[3]), .lod_o(tlod4), .flags_o(tflags4)
  );
  tu_lod_rule u_ewa_rule (
    .l_i(g_q[3] ? 32'sd0 : lmin4), .bias_i(lb_q[3]), .minlod_i(ln_q[3]), .maxlod_i(lx_q[3]),
    .base_i(lbs_q[3]), .top_i(ltp_q[3]), .lod_o(elod4), .flags_o(eflags4)
  );
  always_ff @(posedge clk_i) begin
    if (en) begin
      tlod_o   <= tlod4;
      tflags_o <= tflags4;
      elod_o   <= elod4;
      if (g_q[3]) begin
        ae_o <= '0; be_o <= '0; ce_o <= '0; eexp_o <= '0; fm_o <= '0; fexp_o <= '0;
        lmaj_o <= '0; lmin_o <= '0; lod_o <= '0; flags_o <= 5'b00001;
        lrho_o <= '0;
      end else begin
        ae_o    <= ae_q4;
        be_o    <= be_q4;
        ce_o    <= ce_q4;
        eexp_o  <= eexp_q4;
        fm_o    <= fz4 ? '0 : apn4[PW-1 -: tu_formats_pkg::EllFmW];
        fexp_o  <= fz4 ? '0 : 8'(fexp4);
        lmaj_o  <= LW'(lmaj4);
        lmin_o  <= LW'(lmin4);
        lod_o   <= tu_formats_pkg::EllLodW'(lod4);
        flags_o <= flags4;
        lrho_o  <= LW'(lr_q[2]);
      end
    end
  end

  logic unused;
  assign unused = ^{stage_valid, qn0[QW-MW-1:0], apn4[PW-tu_formats_pkg::EllFmW-1:0], pmn1[RhW-LMW-1:0], eflags4};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {ae_o, be_o, ce_o, eexp_o, fm_o, fexp_o, lmaj_o, lmin_o, lod_o, flags_o, lrho_o, tlod_o, tflags_o, elod_o})
endmodule
