// Texel-depth texturing (seed 001 §3, a B1 variant), per-pixel pipeline, II = 1, latency
// TexelDepthLatency (10). One input = one pixel of a span with the span's per-scanline record:
// q1, q2 (B1's exact q at the span ends x0, x1, s44.40), T1 = (t1u, t1v) and T2 = (t2u, t2v)
// (B1's outputs at the ends, s32.8), the last offset m2 = x1 - x0 and the pixel's offset m.
// The seed's w(s) = z1 s / (z2 - s (z2 - z1)) with z = 1/q and s = m / m2 is
// w = m q2 / (m2 q1 + m (q2 - q1)) (no per-scanline reciprocal); T = T1 + (T2 - T1) w
// (eq. 2.32-2.33). Formats and rounding exactly as cmodel/blocks/persp/texel_depth.hpp:
//   S1      : guard (an end's q < 2^-PerspGuardLog2, incl. q <= 0); accumulators
//             N = m == 0 ? 0 : N + q2, D = m == 0 ? m2 q1 : D + (q2 - q1) (TexelDepthAccW bits,
//             exact when unguarded); w = 0 (m == 0 or m2 == 0) / w = 1 (m >= m2) selects;
//             dT = T2 - T1
//   S2      : e = msb(D), M = top RecipMantW bits of D (truncate)
//   S3..S6  : tu_recip_core (R ~ 1/M, u25.24), B1's reciprocal
//   S7      : N * R
//   S8      : w = round_half_up(N R 2^-(RecipOutF + e - TexelDepthWF)), clamped to [0, 1] (u1.24)
//   S9      : dTu * w, dTv * w
//   S10     : T = T1 + round_half_up(dT w 2^-TexelDepthWF), saturate to s32.8;
//             guarded: u = v = max code, flag = 1
// The accumulators load on m == 0 (a span's first pixel), like tu_persp's: pixels of a span
// arrive in order m = 0, 1, 2, ...
`include "tu_assert.svh"
module tu_texel_depth (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PerspQW-1:0]   q1_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]   q2_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  t1u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  t1v_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  t2u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  t2v_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]  m2_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]  m_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [tu_formats_pkg::PerspUvW-1:0]  u_o,
  output logic [tu_formats_pkg::PerspUvW-1:0]  v_o,
  output logic                                 flag_o
);
  localparam int QW = tu_formats_pkg::PerspQW;
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int XW = tu_formats_pkg::PerspXyW;
  localparam int AW = tu_formats_pkg::TexelDepthAccW;
  localparam int WF = tu_formats_pkg::TexelDepthWF;
  localparam int MW = tu_formats_pkg::RecipMantW;
  localparam int RW = tu_formats_pkg::RecipOutW;
  localparam int EW = 6;                  // msb position of D, 0..AW-1
  localparam int DtW = UW + 1;            // T2 - T1: signed, exact
  localparam int NrW = AW + RW;           // N * R: unsigned, exact
  localparam int WW = WF + 1;             // w code 0..2^WF
  localparam int TpW = DtW + WW;          // dT * w: signed, exact
  localparam int TsW = TpW - WF + 1;      // T1 + rounded dT w: signed
  localparam int CoreLat = tu_formats_pkg::RecipCoreLatency;
  localparam logic [QW-1:0] GuardVal = QW'(1) << (tu_formats_pkg::PerspF - tu_formats_pkg::PerspGuardLog2);
  localparam logic [WW-1:0] WOne = WW'(1) << WF;
  localparam logic signed [TsW-1:0] SatMax = TsW'({1'b0, {(UW-1){1'b1}}});
  // -2^(UW-1) written bit by bit (Yosys 0.23 drops the minus of a negated localparam cast).
  localparam logic signed [TsW-1:0] SatMin = {{(TsW-UW+1){1'b1}}, {(UW-1){1'b0}}};
  localparam logic [UW-1:0] CodeMax = {1'b0, {(UW-1){1'b1}}};
  localparam logic [UW-1:0] CodeMin = {1'b1, {(UW-1){1'b0}}};

  logic                                         en, accept;
  logic [tu_formats_pkg::TexelDepthLatency-1:0] stage_valid;
  tu_pipe_valid #(.Depth(tu_formats_pkg::TexelDepthLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );
  assign accept = en && in_valid_i;

  // ---- S1: guard, accumulators, selects, dT (registered on accept; bubbles move valid only)
  logic [AW-1:0]         n_d, d_d, n_q1, d_q1, d_load;
  logic signed [QW:0]    dq;  // q2 - q1, sign-extended into the D accumulator
  logic                  guard_d, wz_d, wo_d, guard_q1, wz_q1, wo_q1;
  logic [UW-1:0]         t1u_q1, t1v_q1;
  logic signed [DtW-1:0] dtu_d, dtv_d, dtu_q1, dtv_q1;
  assign dq = $signed({q2_i[QW-1], q2_i}) - $signed({q1_i[QW-1], q1_i});
  assign d_load = AW'($unsigned(m2_i) * $unsigned(q1_i[AW-XW-1:0]));  // unguarded: q1 < 2^(QW-1)
  always_comb begin
    n_d     = (m_i == '0) ? '0 : n_q1 + AW'(q2_i);
    d_d     = (m_i == '0) ? d_load : d_q1 + AW'(dq);
    guard_d = q1_i[QW-1] || (q1_i < GuardVal) || q2_i[QW-1] || (q2_i < GuardVal);
    wz_d    = (m_i == '0) || (m2_i == '0);
    wo_d    = m_i >= m2_i;
    dtu_d   = $signed({t2u_i[UW-1], t2u_i}) - $signed({t1u_i[UW-1], t1u_i});
    dtv_d   = $signed({t2v_i[UW-1], t2v_i}) - $signed({t1v_i[UW-1], t1v_i});
  end
  always_ff @(posedge clk_i) begin
    if (accept) begin
      n_q1     <= n_d;
      d_q1     <= d_d;
      guard_q1 <= guard_d;
      wz_q1    <= wz_d;
      wo_q1    <= wo_d;
      t1u_q1   <= t1u_i;
      t1v_q1   <= t1v_i;
      dtu_q1   <= dtu_d;
      dtv_q1   <= dtv_d;
    end
  end

  // ---- S2: leading-one detect of D, normalise (truncate to MW bits)
  logic [EW-1:0] msb;
  logic [AW-1:0] nrm;
  always_comb begin
    msb = '0;
    for (int i = 0; i < AW; i++) begin
      if (d_q1[i]) msb = EW'(i);
    end
    nrm = d_q1 << (AW - 1 - 32'(msb));
  end

  // Delay lines from S2: index k holds the value of stage S(2+k). N meets R at S6
  // (n_q[CoreLat]); e and the w selects meet N R at S7 ([CoreLat+1]); dT meets w at S8
  // ([CoreLat+2]); T1 and the guard meet dT w at S9 ([CoreLat+3]).
  logic [MW-1:0]         m_q2;
  logic [AW-1:0]         n_q   [CoreLat+1];
  logic [EW-1:0]         e_q   [CoreLat+2];
  logic                  wz_q  [CoreLat+2];
  logic                  wo_q  [CoreLat+2];
  logic signed [DtW-1:0] dtu_q [CoreLat+3];
  logic signed [DtW-1:0] dtv_q [CoreLat+3];
  logic [UW-1:0]         t1u_q [CoreLat+4];
  logic [UW-1:0]         t1v_q [CoreLat+4];
  logic                  g_q   [CoreLat+4];
  always_ff @(posedge clk_i) begin
    if (en) begin
      m_q2     <= nrm[AW-1 -: MW];
      n_q[0]   <= n_q1;
      e_q[0]   <= msb;
      wz_q[0]  <= wz_q1;
      wo_q[0]  <= wo_q1;
      dtu_q[0] <= dtu_q1;
      dtv_q[0] <= dtv_q1;
      t1u_q[0] <= t1u_q1;
      t1v_q[0] <= t1v_q1;
      g_q[0]   <= guard_q1;
      for (int i = 1; i <= CoreLat; i++) n_q[i] <= n_q[i-1];
      for (int i = 1; i <= CoreLat + 1; i++) begin
        e_q[i]  <= e_q[i-1];
        wz_q[i] <= wz_q[i-1];
        wo_q[i] <= wo_q[i-1];
      end
      for (int i = 1; i <= CoreLat + 2; i++) begin
        dtu_q[i] <= dtu_q[i-1];
        dtv_q[i] <= dtv_q[i-1];
      end
      for (int i = 1; i <= CoreLat + 3; i++) begin
        t1u_q[i] <= t1u_q[i-1];
        t1v_q[i] <= t1v_q[i-1];
        g_q[i]   <= g_q[i-1];
      end
    end
  end

  // ---- S3..S6: reciprocal core
  logic [RW-1:0] r;
  tu_recip_core u_core (.clk_i, .en_i(en), .m_i(m_q2), .r_o(r));

  // ---- S7: N * R
  logic [NrW-1:0] nr_q7;
  always_ff @(posedge clk_i) begin
    if (en) nr_q7 <= NrW'(n_q[CoreLat]) * NrW'(r);
  end

  // ---- S8: w = N R >> (RecipOutF + e - WF), round half up, clamp to 1; the end selects
  logic [7:0]     sh;
  logic [NrW:0]   w_rnd;
  logic [WW-1:0]  w_d, w_q8;
  always_comb begin
    sh = 8'(tu_formats_pkg::RecipOutF) + 8'(e_q[CoreLat+1]) - 8'(WF);
    w_rnd = ({1'b0, nr_q7} + ((sh == 8'd0) ? '0 : ((NrW+1)'(1) << (sh - 8'd1)))) >> sh;
    if (wz_q[CoreLat+1])         w_d = '0;
    else if (wo_q[CoreLat+1])    w_d = WOne;
    else if (w_rnd > (NrW+1)'(WOne)) w_d = WOne;
    else                         w_d = w_rnd[WW-1:0];
  end
  always_ff @(posedge clk_i) begin
    if (en) w_q8 <= w_d;
  end

  // ---- S9: dT * w (signed x unsigned)
  logic signed [TpW-1:0] pu_q9, pv_q9, w_ext;
  assign w_ext = TpW'({1'b0, w_q8});
  always_ff @(posedge clk_i) begin
    if (en) begin
      pu_q9 <= TpW'(dtu_q[CoreLat+2]) * w_ext;
      pv_q9 <= TpW'(dtv_q[CoreLat+2]) * w_ext;
    end
  end

  // ---- S10: T1 + round_half_up(dT w 2^-WF), saturate; guard
  localparam logic signed [TpW-1:0] Half = TpW'(1) << (WF - 1);
  logic signed [TsW-1:0] ru, rv;
  logic signed [TsW-1:0] tu, tv;
  logic [UW-1:0]         u_d, v_d, u_q, v_q;
  logic                  flag_q;
  always_comb begin
    ru = TsW'((pu_q9 + Half) >>> WF);
    rv = TsW'((pv_q9 + Half) >>> WF);
    tu = TsW'($signed(t1u_q[CoreLat+3])) + ru;
    tv = TsW'($signed(t1v_q[CoreLat+3])) + rv;
    if (g_q[CoreLat+3] || tu > SatMax) u_d = CodeMax;
    else if (tu < SatMin)        u_d = CodeMin;
    else                         u_d = tu[UW-1:0];
    if (g_q[CoreLat+3] || tv > SatMax) v_d = CodeMax;
    else if (tv < SatMin)        v_d = CodeMin;
    else                         v_d = tv[UW-1:0];
  end
  always_ff @(posedge clk_i) begin
    if (en) begin
      u_q    <= u_d;
      v_q    <= v_d;
      flag_q <= g_q[CoreLat+3];
    end
  end
  assign u_o    = u_q;
  assign v_o    = v_q;
  assign flag_o = flag_q;

  logic unused;
  assign unused = ^{stage_valid, nrm[AW-MW-1:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, flag_o})
endmodule
