// Feline filter engine (the probe-based anisotropic filter of docs/blocks/feline.md, the Feline
// engine of tu_texture_unit), bit-exact with feline::fx::filter (cmodel/blocks/feline/feline_fx.cpp):
// a set-up unit (tu_feline_setup: probe count, probe lod, the major axis, the probe line) and a
// prober joined by a one-record hand-over, then the EWA's normalisation (tu_ewa_normalise):
//   probe i = 0 .. N-1, k = 2i - (N-1): (u, v) + k h rounded half up to TexUvF bits, saturated
//   to PerspUvW (k, |k| in registers stepped with i); Q = (|k| tq)^2 >> (2 FelTF - GaussQF)
//   (saturated to GaussQW bits; |k| tq and Q each registered) into tu_gauss_weight (3 clocks):
//   the weight 5 clocks after the issue; the position into the one tu_trilinear at the probe lod (16
//   clocks a probe, 9 with one level); at its output acc_c += w c, wsum += w (exact);
//   after the last probe: tu_ewa_normalise (6 clocks) while the next pixel's probes run.
// A B1-guard pixel: one probe through tu_trilinear's guard pass (the top level's texel), output as is.
// Cycles (no back-pressure; feline::EngineModel, cmodel/blocks/feline/feline_cycles.hpp):
//   accepted at a, record ready at a + S (S = 1 guard, 2 for N = 1, 3 + 2 I/U for N >= 2);
//   hand-over h = max(a + S, the prober's last probe output of the previous pixel); the set-up
//   accepts again at h + 1; probes at h + 1 + j P (P = 16, 9 with one level), the last output at
//   h + N P, the pixel out valid 7 clocks later (guard: 1).
`include "tu_assert.svh"
module tu_feline #(
  parameter int CordUnroll = 2  // CORDIC iterations per clock of the set-up's direction
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
  input  logic [tu_formats_pkg::EllLogW-1:0]    lrho_i,
  input  logic [4:0]                            eflags_i,
  input  logic                                  guard_i,
  input  logic [tu_formats_pkg::FelProbeW-1:0]  nmax_i,
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] bias_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    minlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    maxlod_i,
  input  logic [3:0]                            lbase_i,
  input  logic [3:0]                            ltop_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   base_i,
  input  logic [3:0]                            lw_i,
  input  logic [3:0]                            lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]     wrap_i,   // {v, u} Wrap* codes (tu_texel_addr)
  output logic                                  tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   tex_addr_o,
  input  logic [31:0]                           tex_data_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,   // floor(probe lod) (guard: the top level)
  output logic [tu_formats_pkg::EwaCountW-1:0]  texels_o,  // 8 per probe, 4 with one level; guard 1
  output logic [tu_formats_pkg::FelProbeW-1:0]  probes_o,  // N (guard: 0, no filter)
  output logic [2:0]                            flags_o    // feline::fx::Flag
);
  localparam int UW  = tu_formats_pkg::PerspUvW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  localparam int PW  = tu_formats_pkg::FelProbeW;
  localparam int StW = tu_formats_pkg::FelStepW;
  localparam int TF  = tu_formats_pkg::FelTF;
  localparam int Sh  = tu_formats_pkg::FelSigF - tu_formats_pkg::TexUvF;  // offset rounding
  localparam int QW  = tu_formats_pkg::GaussQW;
  localparam int QSh = 2 * TF - tu_formats_pkg::GaussQF;
  localparam int WW  = tu_formats_pkg::GaussSqW;
  localparam int AcW = tu_formats_pkg::FelAccW;
  localparam int WsW = tu_formats_pkg::FelWsumW;
  localparam int KW  = PW + 1;    // k = 2i - (N-1), signed
  localparam int OW  = StW + KW;  // k h
  localparam int TW  = PW + TF;   // |k| tq

  // texture configuration, with the pixel from acceptance to the hand-over
  logic [AW-1:0] base_q, base_p;
  logic [3:0]    lw_q, lh_q, lw_p, lh_p;
  logic [2*tu_formats_pkg::WrapW-1:0] wrap_q, wrap_p;
  logic signed [UW-1:0] u_q, v_q;
  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) begin
      base_q <= base_i;
      lw_q   <= lw_i;
      lh_q   <= lh_i;
      wrap_q <= wrap_i;
      u_q    <= $signed(u_i);
      v_q    <= $signed(v_i);
    end
  end

  logic                  rec_valid, rec_ready;
  logic [PW-1:0]         r_n;
  logic [tu_formats_pkg::EllLodW-1:0] r_lod;
  logic                  r_single, r_guard;
  logic signed [StW-1:0] r_hu, r_hv;
  logic [TF-1:0]         r_tq;
  logic [2:0]            r_flags;
  tu_feline_setup #(.CordUnroll(CordUnroll)) u_setup (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .ae_i, .ce_i, .be_i, .lmaj_i, .lmin_i, .lrho_i,
    .eflags_i, .guard_i, .nmax_i, .bias_i, .minlod_i, .maxlod_i, .lbase_i, .ltop_i,
    .top_i(lw_i > lh_i ? lw_i : lh_i),
    .rec_valid_o(rec_valid), .rec_ready_i(rec_ready), .n_o(r_n), .lod_o(r_lod), .single_o(r_single),
    .guard_o(r_guard), .hu_o(r_hu), .hv_o(r_hv), .tq_o(r_tq), .flags_o(r_flags)
  );

  // ---- prober: the pixel's record, probe i in flight
  typedef enum logic [1:0] {PIdle, PIssue, PWait} pstate_e;
  pstate_e pst_q;
  logic [PW-1:0]         n_p, i_q;
  // k = 2i - (N-1) and |k| in registers, stepped with i (they were formed from n_p and i_q in the
  // issue clock, in front of the offsets k h and of |k| tq)
  logic signed [KW-1:0]  k_q;
  logic [PW-1:0]         ka_q;
  function automatic logic [PW-1:0] abs_k(input logic signed [KW-1:0] kk);
    abs_k = kk < 0 ? PW'(-kk) : PW'(kk);
  endfunction
  logic [tu_formats_pkg::EllLodW-1:0] lod_p;
  logic                  single_p, guard_p;
  logic signed [StW-1:0] hu_p, hv_p;
  logic [TF-1:0]         tq_p;
  logic [2:0]            flags_p;
  logic signed [UW-1:0]  uc_p, vc_p;

  logic tri_in_ready, tri_out_valid, tri_take, last, last_ok, take_rec;
  logic [31:0] tri_rgba;
  logic [3:0]  tri_level;
  logic        norm_busy, out_q;  // normaliser running; output register full
  assign last     = i_q == n_p - PW'(1);
  assign last_ok  = !norm_busy && !out_q;  // the pixel's sums may go to the normaliser
  assign tri_take = pst_q == PWait && tri_out_valid && (!last || last_ok);
  // the next record is taken with the last probe's output, so its first probe issues at once
  assign take_rec = pst_q == PIdle || (tri_take && last);
  assign rec_ready = take_rec;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) pst_q <= PIdle;
    else begin
      unique case (pst_q)
        PIdle:   if (rec_valid) pst_q <= PIssue;
        PIssue:  if (tri_in_ready) pst_q <= PWait;
        PWait:   if (tri_take) pst_q <= !last ? PIssue : rec_valid ? PIssue : PIdle;
        default: pst_q <= PIdle;
      endcase
    end
  end
  always_ff @(posedge clk_i) begin
    if (take_rec && rec_valid) begin
      n_p      <= r_n;
      lod_p    <= r_lod;
      single_p <= r_single;
      guard_p  <= r_guard;
      hu_p     <= r_hu;
      hv_p     <= r_hv;
      tq_p     <= r_tq;
      flags_p  <= r_flags;
      uc_p     <= u_q;
      vc_p     <= v_q;
      base_p   <= base_q;
      lw_p     <= lw_q;
      lh_p     <= lh_q;
      wrap_p   <= wrap_q;
      i_q      <= '0;
      k_q      <= -$signed(KW'(r_n - PW'(1)));  // i = 0: exactly 2i - KW'(N - 1)
      ka_q     <= abs_k(-$signed(KW'(r_n - PW'(1))));
    end else if (tri_take) begin
      i_q  <= i_q + PW'(1);
      k_q  <= k_q + KW'(2);
      ka_q <= abs_k(k_q + KW'(2));
    end
  end

  // probe i's position (into tu_trilinear's input register) and weight input
  logic signed [OW-1:0] ou, ov;
  logic signed [UW:0]   pu, pv;
  logic [UW-1:0]        pu_sat, pv_sat;
  logic [TW-1:0]        t_q;
  logic [2*TW-1:0]      tt;
  logic [QW-1:0]        q, q_q;
  function automatic logic [UW-1:0] sat_uv(input logic signed [UW:0] x);
    if (x > $signed((UW+1)'({1'b0, {(UW-1){1'b1}}}))) sat_uv = {1'b0, {(UW-1){1'b1}}};
    else if (x < -$signed((UW+1)'({1'b0, 1'b1, {(UW-1){1'b0}}}))) sat_uv = {1'b1, {(UW-1){1'b0}}};
    else sat_uv = UW'(x);
  endfunction
  always_comb begin
    ou = (OW'(k_q) * OW'(hu_p) + $signed(OW'(1) <<< (Sh - 1))) >>> Sh;
    ov = (OW'(k_q) * OW'(hv_p) + $signed(OW'(1) <<< (Sh - 1))) >>> Sh;
    // |k h| >> Sh < 2^(StW + PW - Sh) = 2^29: within one bit of u's s32.8 range
    pu = (UW+1)'(uc_p) + (UW+1)'(ou);
    pv = (UW+1)'(vc_p) + (UW+1)'(ov);
    pu_sat = sat_uv(pu);
    pv_sat = sat_uv(pv);
    tt = (2*TW)'(t_q) * (2*TW)'(t_q);
    q  = (tt >> QSh) > (2*TW)'({QW{1'b1}}) ? {QW{1'b1}} : QW'(tt >> QSh);
  end
  logic issue;
  assign issue = pst_q == PIssue && tri_in_ready;

  tu_trilinear u_tri (
    .clk_i, .rst_ni, .in_valid_i(pst_q == PIssue), .in_ready_o(tri_in_ready),
    .u_i(pu_sat), .v_i(pv_sat), .lod_i(lod_p), .guard_i(guard_p), .base_i(base_p), .lw_i(lw_p), .lh_i(lh_p),
    .wrap_i(wrap_p), .tex_req_o, .tex_addr_o, .tex_data_i,
    .out_valid_o(tri_out_valid), .out_ready_i(tri_take), .rgba_o(tri_rgba), .level_o(tri_level)
  );
  // the probe's weight: t = |k| tq registered at the issue, Q = t^2 >> QSh (saturated) one clock
  // later, tu_gauss_weight (3 clocks): w 5 clocks after the issue (the trilinear output comes >= 8
  // clocks after)
  logic          wv1_q, wv2_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wv1_q <= 1'b0;
      wv2_q <= 1'b0;
    end else begin
      wv1_q <= issue;
      wv2_q <= wv1_q;
    end
  end
  always_ff @(posedge clk_i) begin
    t_q <= TW'(ka_q) * TW'(tq_p);
    q_q <= q;
  end
  logic          w_valid, w_ready_unused;
  logic [WW-1:0] w, w_q;
  tu_gauss_weight u_w (
    .clk_i, .rst_ni, .in_valid_i(wv2_q), .in_ready_o(w_ready_unused), .q_i(q_q),
    .out_valid_o(w_valid), .out_ready_i(1'b1), .w_o(w)
  );
  always_ff @(posedge clk_i) if (w_valid) w_q <= w;

  // ---- weighted sums (exact): the first probe of a pixel starts them
  logic [AcW-1:0] acc_q [4];
  logic [WsW-1:0] wsum_q;
  always_ff @(posedge clk_i) begin
    if (tri_take) begin
      for (int c = 0; c < 4; c++)
        acc_q[c] <= (i_q == '0 ? '0 : acc_q[c]) + AcW'(w_q) * AcW'(tri_rgba[8*c +: 8]);
      wsum_q <= (i_q == '0 ? '0 : wsum_q) + WsW'(w_q);
    end
  end

  // ---- normalisation (acc read 5 clocks after the load: the next pixel's first sum comes >= 8 later)
  logic       load_q;
  logic [2:0] ncnt_q;
  logic [31:0] nrgba;
  tu_ewa_normalise #(.AccW(AcW), .WsumW(WsW)) u_norm (
    .clk_i, .load_i(load_q), .wsum_i(wsum_q), .acc_i({acc_q[3], acc_q[2], acc_q[1], acc_q[0]}), .rgba_o(nrgba)
  );
  assign norm_busy = load_q || ncnt_q != '0;
  logic last_take;
  assign last_take = tri_take && last;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      load_q <= 1'b0;
      ncnt_q <= '0;
      out_q  <= 1'b0;
    end else begin
      load_q <= last_take && !guard_p;
      if (load_q) ncnt_q <= 3'd1;
      else if (ncnt_q == 3'(tu_formats_pkg::EwaNormCycles - 1)) ncnt_q <= '0;
      else if (ncnt_q != '0) ncnt_q <= ncnt_q + 3'd1;
      if ((last_take && guard_p) || ncnt_q == 3'(tu_formats_pkg::EwaNormCycles - 1)) out_q <= 1'b1;
      else if (out_ready_i) out_q <= 1'b0;
    end
  end
  always_ff @(posedge clk_i) begin
    if (last_take) begin  // the pixel's output fields; the colour follows
      level_o  <= tri_level;
      texels_o <= guard_p ? tu_formats_pkg::EwaCountW'(1)
                          : tu_formats_pkg::EwaCountW'(n_p) << (single_p ? 2 : 3);
      probes_o <= guard_p ? '0 : n_p;
      flags_o  <= flags_p;
      if (guard_p) rgba_o <= tri_rgba;
    end
    if (ncnt_q == 3'(tu_formats_pkg::EwaNormCycles - 1)) rgba_o <= nrgba;
  end
  assign out_valid_o = out_q;

  logic unused;
  assign unused = ^{w_ready_unused, pu[UW], pv[UW], tt[2*TW-1], ou[OW-1:UW+1], ov[OW-1:UW+1]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, texels_o, probes_o, flags_o})
endmodule
