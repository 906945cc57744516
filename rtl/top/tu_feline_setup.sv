// Feline per-pixel set-up (docs/blocks/feline.md steps 1-4), bit-exact with feline::fx::setup
// (cmodel/blocks/feline/feline_fx.cpp), a sequential FSM:
//   ACCEPT 1 clock   register the pixel (a B1-guard pixel goes to HAND: one probe, the top level)
//   PRE    1         e = max(0, lmaj - lmin); N = 1 + #{n in [1, Nmax) : e > Lg[n] + kRatioTol}
//                    (the Lg ROM, every entry compared at once), clamped flag; probe log2 rho
//                    lam = max(lmin, lmaj - Lg[Nmax]) (no axes: B2's lrho) through the sampler rule
//                    tu_lod_rule -> lod; the exponents of s1 (clamped, flag) and of r = m / s1;
//                    N = 1: HAND (no line: every probe offset and distance is 0)
//   DIR    1 + 2 I/U the major axis (tu_ewa_dir, the EWA's CORDIC) -> c, s; beside it
//                    s1 = exp2(lmaj) and rho = 1 - r (exp2 ROM), then D = s1 rho and tq = rho R,
//                    then D R (R = 1/(N-1), ROM), each rounded half up; in the last clock the
//                    half step h = (D R)(c, s) rounded half up to FelSigF bits
//   HAND   >= 1      record for the prober (rec_valid_o until rec_ready_i)
// Cycles from acceptance to rec_valid_o: 1 (guard), 2 (N = 1), 3 + 2 I/U (N >= 2)
// (feline::setup_cycles, cmodel/blocks/feline/feline_cycles.hpp).
`include "tu_assert.svh"
module tu_feline_setup #(
  parameter int CordUnroll = 2  // CORDIC iterations per clock (divides EwaCordIter, <= EwaCordIter / 2)
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  in_valid_i,
  output logic                                  in_ready_o,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ae_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ce_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   be_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmaj_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmin_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lrho_i,
  input  logic [4:0]                            eflags_i,
  input  logic                                  guard_i,   // B1 guard: the texture's mean
  input  logic [tu_formats_pkg::FelProbeW-1:0]  nmax_i,    // probe cap (1..FelNMax; 0 reads as 1, more as FelNMax)
  // the sampler's lod rule (tex::trilinear_lod): bias, min / max lod, the material's levels
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] bias_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    minlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    maxlod_i,
  input  logic [3:0]                            lbase_i,
  input  logic [3:0]                            ltop_i,
  input  logic [3:0]                            top_i,     // the pyramid's top level max(lw, lh)
  output logic                                  rec_valid_o,
  input  logic                                  rec_ready_i,
  output logic [tu_formats_pkg::FelProbeW-1:0]  n_o,       // probes
  output logic [tu_formats_pkg::EllLodW-1:0]    lod_o,     // probe lod, TexLodF fraction bits
  output logic                                  single_o,  // one level per probe (lod at the top, or guard)
  output logic                                  guard_o,
  output logic signed [tu_formats_pkg::FelStepW-1:0] hu_o,  // half step along u, v: s.FelSigF
  output logic signed [tu_formats_pkg::FelStepW-1:0] hv_o,
  output logic [tu_formats_pkg::FelTF-1:0]      tq_o,      // probe distance step, u0.FelTF
  output logic [2:0]                            flags_o    // feline::fx::Flag {axis clamp, clamped, unit}
);
  localparam int LW    = tu_formats_pkg::EllLogW;
  localparam int LF    = tu_formats_pkg::EllLogF;
  localparam int PW    = tu_formats_pkg::FelProbeW;
  localparam int NMax  = tu_formats_pkg::FelNMax;
  localparam int ExpF  = tu_formats_pkg::EwaExpF;
  localparam int E2F   = tu_formats_pkg::EwaE2F;
  localparam int E2W   = tu_formats_pkg::EwaE2W;
  localparam int SigW  = tu_formats_pkg::FelSigW;
  localparam int SigF  = tu_formats_pkg::FelSigF;
  localparam int TF    = tu_formats_pkg::FelTF;
  localparam int RF    = tu_formats_pkg::FelRecipF;
  localparam int StW   = tu_formats_pkg::FelStepW;
  localparam int CsW   = tu_formats_pkg::EwaCsW;
  localparam int CsF   = tu_formats_pkg::EwaCsF;
  localparam int Drop  = LF - ExpF;  // log codes to the exp2 ROM's EwaExpF bits
  localparam int RatioTol = 8;       // feline::kRatioTol (log codes)
  localparam int EW    = LW + 2;     // exponents in EwaExpF bits, signed
  localparam logic signed [LW-1:0] LogNegInf = {1'b1, {(LW-1){1'b0}}};
  localparam logic signed [EW-1:0] SigLo = -($signed(EW'(SigF)) <<< ExpF);
  localparam logic signed [EW-1:0] SigHi = $signed(EW'(tu_formats_pkg::FelAxisMaxLog2)) <<< ExpF;
  localparam logic signed [EW-1:0] RMax  = $signed(EW'(TF)) <<< ExpF;
  `TU_ASSERT_PARAM(g_unroll, CordUnroll >= 1 && CordUnroll <= tu_formats_pkg::EwaCordIter / 2,
                   "the line's arithmetic needs 3 clocks beside the CORDIC: CordUnroll <= EwaCordIter / 2")

  typedef enum logic [1:0] {SIdle, SPre, SDir, SHand} state_e;
  state_e st_q;
  assign in_ready_o  = st_q == SIdle;
  assign rec_valid_o = st_q == SHand;

  // ---- pixel registers
  logic [63:0]          ae_q, ce_q, be_q;
  logic signed [LW-1:0] lmaj_q, lmin_q, lrho_q;
  logic                 unit_q;
  logic [PW-1:0]        nmax_q;
  logic [tu_formats_pkg::TexLodBiasW-1:0] bias_q;
  logic [tu_formats_pkg::EllLodW-1:0]     minlod_q, maxlod_q;
  logic [3:0]           lbase_q, ltop_q, top_q;

  // ---- PRE: probe count, probe lod, exponents
  logic [(NMax+1)*LW-1:0] lg;
  logic [RF:0]            recip;
  logic [PW-1:0]          n_q;
  tu_feline_rom u_rom (.m_i(n_q - PW'(1)), .recip_o(recip), .lg_o(lg));
  logic signed [LW+1:0] e, lgmax, lam, el;
  logic [PW-1:0]        n_d;
  logic                 clamped;
  always_comb begin
    e = (LW+2)'(lmaj_q) - (LW+2)'(lmin_q);
    if (e < 0) e = '0;
    lgmax = (LW+2)'(lg[nmax_q * LW +: LW]);
    n_d = PW'(1);
    for (int n = 1; n < NMax; n++)
      if (PW'(n) < nmax_q && e > (LW+2)'(lg[n * LW +: LW]) + (LW+2)'(RatioTol)) n_d = n_d + PW'(1);
    clamped = e > lgmax + (LW+2)'(RatioTol);
    lam = (LW+2)'(lmaj_q) - lgmax;
    if ((LW+2)'(lmin_q) > lam) lam = (LW+2)'(lmin_q);
    if (unit_q) begin
      n_d = PW'(1);
      clamped = 1'b0;
      lam = (LW+2)'(lrho_q);
    end
    el = (LW+2)'(lmaj_q) - lam;  // B2 may floor lmin a code above lmaj
    if (el < 0) el = '0;
  end
  logic [tu_formats_pkg::EllLodW-1:0] lod_d;
  logic [2:0]                         lflags_unused;
  logic signed [31:0]                 lam32;
  assign lam32 = 32'(lam);
  tu_lod_rule u_rule (
    .l_i(lam32), .bias_i(bias_q), .minlod_i(minlod_q), .maxlod_i(maxlod_q),
    .base_i(lbase_q), .top_i(ltop_q), .lod_o(lod_d), .flags_o(lflags_unused)
  );
  // exponent of s1 (lmaj truncated to EwaExpF bits, clamped) and of r (the ratio, at most FelTF)
  logic signed [EW-1:0] es_d, es_q, er_d, er_q;
  logic                 axclamp;
  always_comb begin
    es_d = EW'(lmaj_q) >>> Drop;
    axclamp = es_d < SigLo || es_d > SigHi;
    if (es_d < SigLo) es_d = SigLo;
    if (es_d > SigHi) es_d = SigHi;
    er_d = EW'(el >>> Drop);
    if (er_d > RMax) er_d = RMax;
  end

  // ---- DIR: the major axis and the line
  logic                  dir_done, dir_finish_unused;
  logic signed [CsW-1:0] c, s;
  logic signed [63:0]    dd, bd;
  assign dd = $signed(ae_q) - $signed(ce_q);
  assign bd = $signed(be_q);
  tu_ewa_dir #(.CordUnroll(CordUnroll)) u_dir (
    .clk_i, .rst_ni, .start_i(st_q == SPre && !unit_q && n_d != PW'(1)),
    .d_i(dd), .b_i(bd), .unit_i(1'b0),
    .finish_o(dir_finish_unused), .done_o(dir_done), .c_o(c), .s_o(s)
  );
  // 2^e (e >= 0: T[e mod 2^ExpF] << e / 2^ExpF) and 2^-m (m = -e: T[-m mod 2^ExpF] >> (m / 2^ExpF + 1),
  // 2^E2F >> m / 2^ExpF for a whole m): the ROM index is e's low ExpF bits either way
  logic [E2W-1:0] t_s, t_r;
  tu_ewa_exp2_rom u_exp_s (.idx_i(es_q[ExpF-1:0]), .e_o(t_s));
  tu_ewa_exp2_rom u_exp_r (.idx_i(ExpF'(-er_q[ExpF-1:0])), .e_o(t_r));
  function automatic logic [E2W-1:0] exp2_neg(input logic [EW-1:0] m, input logic [E2W-1:0] rom);
    if (m[ExpF-1:0] == '0) exp2_neg = E2W'((E2W)'(1) << E2F) >> m[EW-1:ExpF];
    else exp2_neg = rom >> (m[EW-1:ExpF] + (EW-ExpF)'(1));
  endfunction
  logic [EW-1:0]  mneg;
  logic [SigW-1:0] sig_d;
  always_comb begin
    mneg = EW'(-es_q);
    if (es_q >= 0) sig_d = SigW'(SigW'(t_s) << es_q[EW-1:ExpF]);
    else sig_d = SigW'(exp2_neg(mneg, t_s));
  end
  logic [SigW-1:0]  sig_q, delta_q, dr_q;
  logic [TF-1:0]    rho_q, tq_q;
  logic [SigW+TF-1:0]   pd;
  logic [SigW+RF:0]     pr;
  logic [TF+RF:0]       pt;
  assign pd = (SigW+TF)'(sig_q) * (SigW+TF)'(rho_q);
  assign pr = (SigW+RF+1)'(delta_q) * (SigW+RF+1)'(recip);
  assign pt = (TF+RF+1)'(rho_q) * (TF+RF+1)'(recip);
  // h = round_half_up(D R c / 2^CsF), signed
  function automatic logic signed [StW-1:0] half_step(input logic [SigW-1:0] dr, input logic signed [CsW-1:0] cs);
    logic signed [SigW+CsW:0] p;
    p = $signed({1'b0, dr}) * cs;
    p = (p + $signed((SigW+CsW+1)'(1) << (CsF - 1))) >>> CsF;
    half_step = StW'(p);
  endfunction

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= SIdle;
    else begin
      unique case (st_q)
        SIdle: if (in_valid_i) st_q <= guard_i ? SHand : SPre;
        SPre:  st_q <= n_d == PW'(1) ? SHand : SDir;
        SDir:  if (dir_done) st_q <= SHand;
        SHand: if (rec_ready_i) st_q <= SIdle;
        default: st_q <= SIdle;
      endcase
    end
  end
  always_ff @(posedge clk_i) begin
    unique case (st_q)
      SIdle: if (in_valid_i) begin
        ae_q     <= ae_i;
        ce_q     <= ce_i;
        be_q     <= be_i;
        lmaj_q   <= $signed(lmaj_i);
        lmin_q   <= $signed(lmin_i);
        lrho_q   <= $signed(lrho_i);
        unit_q   <= eflags_i[tu_formats_pkg::EllFlagHorizon] || $signed(lmaj_i) == LogNegInf ||
                    $signed(lmin_i) == LogNegInf;
        nmax_q   <= nmax_i == '0 ? PW'(1) : nmax_i > PW'(NMax) ? PW'(NMax) : nmax_i;
        bias_q   <= bias_i;
        minlod_q <= minlod_i;
        maxlod_q <= maxlod_i;
        lbase_q  <= lbase_i;
        ltop_q   <= ltop_i;
        top_q    <= top_i;
        // B1 guard: one probe on the top level's texel (tu_bilinear's guard)
        guard_o  <= guard_i;
        n_q      <= PW'(1);
        lod_o    <= {top_i, tu_formats_pkg::TexLodF'(0)};
        single_o <= 1'b1;
        flags_o  <= '0;
        hu_o     <= '0;
        hv_o     <= '0;
        tq_o     <= '0;
      end
      SPre: begin
        n_q      <= n_d;
        lod_o    <= lod_d;
        single_o <= lod_d[tu_formats_pkg::TexLodF +: 4] >= top_q;
        flags_o  <= {!unit_q && axclamp, clamped, unit_q};
        es_q     <= es_d;
        er_q     <= er_d;
      end
      SDir: begin
        sig_q   <= sig_d;
        rho_q   <= TF'((SigW+1)'(1 << E2F) - (SigW+1)'(exp2_neg(er_q, t_r)));
        delta_q <= SigW'((pd + (SigW+TF)'(1 << (TF - 1))) >> TF);
        tq_q    <= TF'((pt + (TF+RF+1)'(1 << (RF - 1))) >> RF);
        dr_q    <= SigW'((pr + (SigW+RF+1)'(1 << (RF - 1))) >> RF);
        if (dir_done) begin
          hu_o <= half_step(dr_q, c);
          hv_o <= half_step(dr_q, s);
          tq_o <= tq_q;
        end
      end
      default: ;
    endcase
  end
  assign n_o = n_q;
  logic unused;
  assign unused = ^{dir_finish_unused, lflags_unused, eflags_i[4:1], lg[LW-1:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(RecHandshake, rec_valid_o, rec_ready_i, {n_o, lod_o, single_o, guard_o, hu_o, hv_o, tq_o, flags_o})
endmodule
