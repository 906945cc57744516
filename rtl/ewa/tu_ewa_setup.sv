// EWA per-pixel set-up (B5 steps 1-3 of ewa::fx::setup, plus the walk's start values), a
// sequential FSM; bit-exact with cmodel/blocks/ewa/ewa_fx.cpp (docs/blocks/ewa.md "RTL").
//   ACCEPT  1 clock   register the pixel
//   PRE     1         level L0 = min(lod >> EllLodF, top) (the sampler's level, a unit disc too), d = Ae'-Ce', b = Be'
//                     block-normalised, pre-rotation into the right half-plane
//   VEC     I/U       CORDIC vectoring, U iterations per clock -> 2 phi; theta = phi + 1/4 turn
//   ROT     I/U       CORDIC rotation -> c, s (rounded half up to EwaCsF bits)
//   per level tried (the texel cap raises L and repeats):
//   AX      1         ea, eb clamped (axis-clamp flag)
//   EXP     1         exp2 ROM: a, b, 1/a, 1/b
//   MUL     1         k = (c/a, s/a, -s/b, c/b) rounded half up; a c, b s, a s, b c; centre cu, cv
//   SQ      1         radicands ceil(((a c)^2 + (b s)^2) / 2^2Sh) (Sh = E2F + CsF - PosF)
//   ROOT    RootW/S   two square roots, S bits per clock: h = ceil(sqrt(.)) = the C model's
//                     ceil(ceil(sqrt(x)) / 2^Sh)
//   BOX     1         hu = h + h/64 + 1 (margin) (+ 1/2 texel with border weights: clip_i),
//                     x0 = ceil(cu - hu), x1 = floor(cu + hu), y likewise
//   CAP     1         box = (x1-x0+1)(y1-y0+1); box > cap and L < top -> L+1, capped, AX again
//   START   2         walk start values (row y0, column x0; Align: the 2 x 2 walk's aligned corner
//                     (x0 & ~1, y0 & ~1)): xi, eta, Q and the first and second differences of Q
//                     along x and along y (exact integers)
//   HAND    >= 1      hand the record to the walker (rec_valid_o until rec_ready_i)
// Cycles from acceptance to rec_valid_o: 2 + 2 I/U + levels * (6 + RootW/S) + 2; a B1-guard
// pixel (no texture coordinates: the texture's mean, the top level's single texel, as
// render::render_cmodel) goes from ACCEPT straight to HAND: 1.
`include "tu_assert.svh"
module tu_ewa_setup #(
  parameter int CordUnroll = 2,  // CORDIC iterations per clock (divides EwaCordIter)
  parameter int SqrtStep   = 4,  // square-root bits per clock (divides RootW)
  parameter int Align      = 0   // 1: start values at the even-aligned corner (tu_ewa_walk_lanes)
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
  input  logic                                  guard_i,    // B1 guard: no coordinates
  input  logic [3:0]                            top_i,      // top mip level = max(lw, lh)
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic                                  clip_i,     // border weights: the box grows
  // record for the walker
  output logic                                  rec_valid_o,
  input  logic                                  rec_ready_i,
  output logic [3:0]                            level_o,
  output logic [4:0]                            flags_o,
  output logic                                  guard_o,    // record of a B1-guard pixel
  output logic signed [31:0]                    x0_o,
  output logic signed [31:0]                    x1_o,
  output logic signed [31:0]                    y0_o,
  output logic signed [31:0]                    y1_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  box_o,
  output logic signed [31:0]                    cu_o,
  output logic signed [31:0]                    cv_o,
  output logic signed [tu_formats_pkg::EwaXiW-1:0] xi0_o,
  output logic signed [tu_formats_pkg::EwaXiW-1:0] eta0_o,
  output logic signed [tu_formats_pkg::EwaXiW-1:0] dxi_o,    // kxu 2^PosF: xi step along x
  output logic signed [tu_formats_pkg::EwaXiW-1:0] deta_o,   // kyu 2^PosF
  output logic signed [tu_formats_pkg::EwaXiW-1:0] dxiy_o,   // kxv 2^PosF: xi step along y
  output logic signed [tu_formats_pkg::EwaXiW-1:0] detay_o,  // kyv 2^PosF
  output logic signed [63:0]                    q0_o,       // Q at (x0, y0)
  output logic signed [63:0]                    dq0_o,      // Q(x0+1, y0) - Q(x0, y0)
  output logic signed [63:0]                    ddq_o,      // second difference along x
  output logic signed [63:0]                    ey0_o,      // Q(x0, y0+1) - Q(x0, y0)
  output logic signed [63:0]                    ddqy_o,     // second difference along y
  output logic signed [63:0]                    dqy_o       // change of the x-difference per row
);
  localparam int Iter  = tu_formats_pkg::EwaCordIter;
  localparam int AngW  = tu_formats_pkg::EwaAngW;
  localparam int CW    = tu_formats_pkg::EwaCordW;
  localparam int XW    = CW + 2;
  localparam int ZW    = AngW + 2;
  localparam int RotF  = CW - 3;
  localparam int CsF   = tu_formats_pkg::EwaCsF;
  localparam int CsW   = tu_formats_pkg::EwaCsW;
  localparam int ExpF  = tu_formats_pkg::EwaExpF;
  localparam int E2F   = tu_formats_pkg::EwaE2F;
  localparam int E2W   = tu_formats_pkg::EwaE2W;
  localparam int AxW   = tu_formats_pkg::EwaAW;
  localparam int KW    = tu_formats_pkg::EwaKW;
  localparam int KF    = tu_formats_pkg::EwaKF;
  localparam int PosF  = tu_formats_pkg::EwaPosF;
  localparam int XiW   = tu_formats_pkg::EwaXiW;
  localparam int NW    = tu_formats_pkg::EwaCountW;
  localparam int LW    = tu_formats_pkg::EllLogW;
  localparam int UW    = tu_formats_pkg::PerspUvW;
  localparam int Sh    = E2F + CsF - PosF;        // half-extent radicand scale (2 Sh bits)
  localparam int PW    = AxW + CsW;               // a c etc. (signed)
  localparam int RadW  = 2 * PW;                  // (a c)^2 + (b s)^2
  localparam int RootW = 16;                      // radicand / 2^(2 Sh) < 2^32 (tested)
  localparam int Step  = 1 << PosF;
  localparam logic signed [31:0] StepS  = 32'(Step);
  localparam logic signed [31:0] StepSq = 32'(Step * Step);
  localparam logic signed [LW-1:0] LogNegInf = {1'b1, {(LW-1){1'b0}}};
  localparam logic signed [ZW-1:0] Quarter = ZW'(1) <<< (AngW - 2);
  localparam logic signed [ZW-1:0] Half    = ZW'(1) <<< (AngW - 1);

  typedef enum logic [3:0] {
    StIdle, StPre, StVec, StRot, StAx, StExp, StMul, StSq, StRoot, StBox, StCap, StSt1, StSt2, StHand
  } state_e;
  state_e st_q;
  logic [4:0] it_q;  // CORDIC iteration / square-root step counter

  // ---- pixel registers
  logic signed [UW-1:0] u_q, v_q;
  logic [63:0]          ae_q, ce_q, be_q;
  logic signed [LW-1:0] lmaj_q, lmin_q;
  logic [3:0]           lodi_q, top_q, lev_q;
  logic                 unit_q, guard_q;
  logic [NW-1:0]        cap_q;
  logic                 clip_q;
  logic [4:0] fl_q;

  assign in_ready_o  = st_q == StIdle;
  assign rec_valid_o = st_q == StHand;

  // ---- PRE: block normalisation of d = ae - ce, b = be (ae, ce < 2^62: d fits 64 bits)
  logic signed [63:0] d_pre, b_pre, ad, ab, mx;
  logic [6:0]         msb_pre, k_pre;
  logic signed [63:0] xn, yn;
  always_comb begin
    d_pre = $signed(ae_q) - $signed(ce_q);
    b_pre = $signed(be_q);
    ad = d_pre < 0 ? -d_pre : d_pre;
    ab = b_pre < 0 ? -b_pre : b_pre;
    mx = ad > ab ? ad : ab;
    msb_pre = '0;
    for (int i = 0; i < 64; i++) if (mx[i]) msb_pre = 7'(i);
    k_pre = (msb_pre + 7'd1 > 7'(CW - 3)) ? msb_pre + 7'd1 - 7'(CW - 3) : 7'd0;
    xn = d_pre >>> k_pre;
    yn = b_pre >>> k_pre;
  end

  // ---- CORDIC
  logic signed [XW-1:0] cx_q, cy_q, cx_d, cy_d;
  logic signed [ZW-1:0] cz_q, cz_d;
  logic                 circle_q;
  tu_ewa_cordic #(.Unroll(CordUnroll), .XW(XW), .ZW(ZW)) u_cordic (
    .rotate_i(st_q == StRot), .i0_i(it_q), .x_i(cx_q), .y_i(cy_q), .z_i(cz_q),
    .x_o(cx_d), .y_o(cy_d), .z_o(cz_d)
  );
  logic [CW-1:0]   gain;  // round(CORDIC gain 2^(EwaCordW-3)): the rotation's start x
  logic [AngW-1:0] atan_unused;
  tu_ewa_atan_rom u_gain (.i_i(4'd0), .atan_o(atan_unused), .gain_o(gain));
  // theta from 2 phi (wrapped to AngW bits): phi + 1/4 turn reduced to [-1/4, 1/4) turn
  logic signed [ZW-1:0] two_phi, theta;
  always_comb begin
    two_phi = ZW'($signed(cz_d[AngW-1:0]));
    theta = (two_phi >>> 1) + Quarter;
    if (theta >= Quarter) theta = theta - Half;
    if (unit_q || circle_q) theta = '0;
  end
  logic signed [CsW-1:0] c_q, s_q;
  function automatic logic signed [CsW-1:0] cs_round(input logic signed [XW-1:0] v);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [XW-1:0] t;  // high bits: sign copies
    /* verilator lint_on UNUSEDSIGNAL */
    t = (v + $signed(XW'(1) << (RotF - CsF - 1))) >>> (RotF - CsF);
    cs_round = CsW'(t);  // |cos|, |sin| <= 1: the dropped high bits are sign copies
  endfunction

  // ---- AX: log2 semi-axes at level L (EwaExpF fraction bits, floor)
  logic signed [LW+1:0] ra, rb, emax, lev_log;
  logic [3:0]           lim2, limc;
  logic [ExpF+3:0]      ea_q, eb_q;
  logic                 axclamp;
  logic [ExpF+3:0]      ea_d, eb_d;
  always_comb begin
    lim2 = top_q - lev_q;  // log2 of the longer side of level L
    limc = lim2 > 4'(tu_formats_pkg::EwaAxisMaxLog2) ? 4'(tu_formats_pkg::EwaAxisMaxLog2) : lim2;
    emax = (LW+2)'(limc) <<< ExpF;
    lev_log = $signed((LW+2)'(lev_q) << tu_formats_pkg::EllLogF);
    ra = ((LW+2)'(lmaj_q) - lev_log) >>> (tu_formats_pkg::EllLogF - ExpF);
    if (lmin_q == LogNegInf) rb = '0;  // (an unsigned '0 in a ?: would make >>> logical)
    else rb = ((LW+2)'(lmin_q) - lev_log) >>> (tu_formats_pkg::EllLogF - ExpF);
    axclamp = !unit_q && ra > emax;
    if (unit_q) begin
      ea_d = '0;
      eb_d = '0;
    end else begin
      ea_d = ra < 0 ? '0 : ra > emax ? (ExpF+4)'(emax) : (ExpF+4)'(ra);
      eb_d = rb < 0 ? '0 : rb > $signed((LW+2)'(ea_d)) ? ea_d : (ExpF+4)'(rb);
    end
  end

  // ---- EXP: exp2 ROM, 2^e and 2^-e (floor shifts)
  logic [E2W-1:0] e_pa, e_pb, e_na, e_nb;
  tu_ewa_exp2_rom u_exp_pa (.idx_i(ea_q[ExpF-1:0]), .e_o(e_pa));
  tu_ewa_exp2_rom u_exp_pb (.idx_i(eb_q[ExpF-1:0]), .e_o(e_pb));
  tu_ewa_exp2_rom u_exp_na (.idx_i(ExpF'(-ea_q[ExpF-1:0])), .e_o(e_na));
  tu_ewa_exp2_rom u_exp_nb (.idx_i(ExpF'(-eb_q[ExpF-1:0])), .e_o(e_nb));
  function automatic logic [E2W-1:0] exp2_neg(input logic [ExpF+3:0] e, input logic [E2W-1:0] rom);
    if (e[ExpF-1:0] == '0) exp2_neg = E2W'((E2W)'(1) << E2F) >> e[ExpF+3:ExpF];
    else exp2_neg = rom >> (e[ExpF+3:ExpF] + 4'd1);
  endfunction
  logic [AxW-1:0] a_q, b_q;
  logic [E2W-1:0] ia_q, ib_q;

  // ---- MUL: frame coefficients and the half-extent products; centre at level L
  function automatic logic signed [KW-1:0] kcoef(input logic signed [CsW-1:0] cs, input logic [E2W-1:0] inv);
    logic signed [CsW+E2W:0] p;
    p = $signed({{(E2W+1){cs[CsW-1]}}, cs}) * $signed({{CsW{1'b0}}, 1'b0, inv});
    p = (p + $signed((CsW+E2W+1)'(1) << (CsF + E2F - KF - 1))) >>> (CsF + E2F - KF);
    kcoef = KW'(p);
  endfunction
  function automatic logic signed [31:0] centre(input logic signed [UW-1:0] u, input logic [3:0] lev);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [UW:0] t;  // top bit: sign copy after the shift
    /* verilator lint_on UNUSEDSIGNAL */
    logic [5:0]         sh;
    sh = 6'(tu_formats_pkg::TexUvF - PosF) + 6'(lev);  // > 0: TexUvF >= PosF
    t = ($signed({u[UW-1], u}) + $signed((UW+1)'(1) << (sh - 6'd1))) >>> sh;
    centre = 32'(t) - 32'(Step / 2);
  endfunction
  logic signed [KW-1:0] kxu_q, kxv_q, kyu_q, kyv_q;
  logic signed [PW-1:0] pac_q, pbs_q, pas_q, pbc_q;
  logic signed [31:0]   cu_q, cv_q;

  // ---- SQ / ROOT
  logic [RadW-1:0]      radu, radv;
  logic [2*RootW-1:0]   xu_q, xv_q, xu_d, xv_d;
  logic [RootW+1:0]     remu_q, remv_q, remu_d, remv_d;
  logic [RootW-1:0]     rootu_q, rootv_q, rootu_d, rootv_d;
  always_comb begin
    radu = RadW'($signed(RadW'(pac_q)) * $signed(RadW'(pac_q))) + RadW'($signed(RadW'(pbs_q)) * $signed(RadW'(pbs_q)));
    radv = RadW'($signed(RadW'(pas_q)) * $signed(RadW'(pas_q))) + RadW'($signed(RadW'(pbc_q)) * $signed(RadW'(pbc_q)));
  end
  function automatic logic [2*RootW-1:0] ceil_scale(input logic [RadW-1:0] r);
    ceil_scale = (2*RootW)'((r + ((RadW)'(1) << (2 * Sh)) - RadW'(1)) >> (2 * Sh));
  endfunction
  tu_ewa_isqrt_step #(.RootW(RootW), .Step(SqrtStep)) u_sqrt_u (
    .x_i(xu_q), .rem_i(remu_q), .root_i(rootu_q), .x_o(xu_d), .rem_o(remu_d), .root_o(rootu_d));
  tu_ewa_isqrt_step #(.RootW(RootW), .Step(SqrtStep)) u_sqrt_v (
    .x_i(xv_q), .rem_i(remv_q), .root_i(rootv_q), .x_o(xv_d), .rem_o(remv_d), .root_o(rootv_d));

  // ---- BOX
  logic [RootW+1:0]   hu, hv, hhu, hhv;
  logic signed [31:0] x0_d, x1_d, y0_d, y1_d;
  always_comb begin
    hhu = (RootW+2)'(rootu_q) + (RootW+2)'(remu_q != '0);
    hhv = (RootW+2)'(rootv_q) + (RootW+2)'(remv_q != '0);
    // border texels up to 1/2 texel outside the ellipse (ewa::fx::kBorderGrow)
    hu = hhu + (hhu >> PosF) + (RootW+2)'(1) + (clip_q ? (RootW+2)'(Step / 2) : '0);
    hv = hhv + (hhv >> PosF) + (RootW+2)'(1) + (clip_q ? (RootW+2)'(Step / 2) : '0);
    x0_d = -(($signed(32'(hu)) - cu_q) >>> PosF);  // ceil((cu - hu) / 2^PosF)
    x1_d = (cu_q + $signed(32'(hu))) >>> PosF;
    y0_d = -(($signed(32'(hv)) - cv_q) >>> PosF);
    y1_d = (cv_q + $signed(32'(hv))) >>> PosF;
  end
  logic signed [31:0] bw, bh;
  logic [63:0]        box;
  assign bw  = x1_o - x0_o + 32'sd1;
  assign bh  = y1_o - y0_o + 32'sd1;
  assign box = 64'($signed(bw) * $signed(bh));

  // ---- START: walk start values at (x0, y0)
  logic signed [31:0] du0, dv0;
  logic signed [63:0] qa, qb, qc;  // Q = A du^2 + B du dv + C dv^2
  assign du0 = ((Align != 0 ? x0_o & ~32'sd1 : x0_o) <<< PosF) - cu_q;
  assign dv0 = ((Align != 0 ? y0_o & ~32'sd1 : y0_o) <<< PosF) - cv_q;
  logic signed [63:0] qa_q, qb_q, qc_q;
  logic signed [31:0] du0_q, dv0_q;
  always_comb begin
    qa = 64'(kxu_q) * 64'(kxu_q) + 64'(kyu_q) * 64'(kyu_q);
    qb = (64'(kxu_q) * 64'(kxv_q) + 64'(kyu_q) * 64'(kyv_q)) <<< 1;
    qc = 64'(kxv_q) * 64'(kxv_q) + 64'(kyv_q) * 64'(kyv_q);
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= StIdle;
    else begin
      unique case (st_q)
        StIdle: if (in_valid_i) st_q <= guard_i ? StHand : StPre;
        StPre:  st_q <= StVec;
        StVec:  if (32'(it_q) + CordUnroll >= Iter) st_q <= StRot;
        StRot:  if (32'(it_q) + CordUnroll >= Iter) st_q <= StAx;
        StAx:   st_q <= StExp;
        StExp:  st_q <= StMul;
        StMul:  st_q <= StSq;
        StSq:   st_q <= StRoot;
        StRoot: if (32'(it_q) + 1 >= RootW / SqrtStep) st_q <= StBox;
        StBox:  st_q <= StCap;
        StCap:  st_q <= (box > 64'(cap_q) && lev_q < top_q) ? StAx : StSt1;
        StSt1:  st_q <= StSt2;
        StSt2:  st_q <= StHand;
        StHand: if (rec_ready_i) st_q <= StIdle;
        default: st_q <= StIdle;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    unique case (st_q)
      StIdle: if (in_valid_i) begin
        u_q    <= $signed(u_i);
        v_q    <= $signed(v_i);
        ae_q   <= ae_i;
        ce_q   <= ce_i;
        be_q   <= be_i;
        lmaj_q <= $signed(lmaj_i);
        lmin_q <= $signed(lmin_i);
        lodi_q <= lod_i[tu_formats_pkg::EllLodW-1 -: 4];
        top_q  <= top_i;
        cap_q  <= cap_i;
        clip_q <= clip_i;
        unit_q <= eflags_i[tu_formats_pkg::EllFlagHorizon] || ($signed(lmaj_i) == LogNegInf);
        guard_q <= guard_i;
        // B1 guard: the 1x1 top level's texel (0, 0), no walk (render_cmodel)
        lev_q <= top_i;
        fl_q  <= '0;
        cu_q  <= '0;
        cv_q  <= '0;
        box_o <= NW'(1);
      end
      StPre: begin
        fl_q <= '0;
        if (unit_q) begin
          fl_q[tu_formats_pkg::EwaFlagUnitDisc] <= 1'b1;
          lev_q   <= lodi_q > top_q ? top_q : lodi_q;
        end else if (lodi_q > top_q) begin
          fl_q[tu_formats_pkg::EwaFlagLodSat] <= 1'b1;
          lev_q   <= top_q;
        end else begin
          lev_q <= lodi_q;
        end
        circle_q <= d_pre == 0 && b_pre == 0;
        if (xn < 0) begin
          cx_q <= XW'(-xn);
          cy_q <= XW'(-yn);
          cz_q <= Half;
        end else begin
          cx_q <= XW'(xn);
          cy_q <= XW'(yn);
          cz_q <= '0;
        end
        it_q <= '0;
      end
      StVec: begin
        if (32'(it_q) + CordUnroll >= Iter) begin
          cx_q <= XW'($signed({1'b0, gain}));
          cy_q <= '0;
          cz_q <= theta;
          it_q <= '0;
        end else begin
          cx_q <= cx_d;
          cy_q <= cy_d;
          cz_q <= cz_d;
          it_q <= it_q + 5'(CordUnroll);
        end
      end
      StRot: begin
        cx_q <= cx_d;
        cy_q <= cy_d;
        cz_q <= cz_d;
        it_q <= it_q + 5'(CordUnroll);
        c_q  <= cs_round(cx_d);
        s_q  <= cs_round(cy_d);
      end
      StAx: begin
        ea_q    <= ea_d;
        eb_q    <= eb_d;
        fl_q[tu_formats_pkg::EwaFlagAxisClamp] <= axclamp;
      end
      StExp: begin
        a_q  <= AxW'(e_pa) << ea_q[ExpF+3:ExpF];
        b_q  <= AxW'(e_pb) << eb_q[ExpF+3:ExpF];
        ia_q <= exp2_neg(ea_q, e_na);
        ib_q <= exp2_neg(eb_q, e_nb);
      end
      StMul: begin
        kxu_q <= kcoef(c_q, ia_q);
        kxv_q <= kcoef(s_q, ia_q);
        kyu_q <= kcoef(-s_q, ib_q);
        kyv_q <= kcoef(c_q, ib_q);
        pac_q <= $signed({1'b0, a_q}) * c_q;
        pbs_q <= $signed({1'b0, b_q}) * s_q;
        pas_q <= $signed({1'b0, a_q}) * s_q;
        pbc_q <= $signed({1'b0, b_q}) * c_q;
        cu_q  <= centre(u_q, lev_q);
        cv_q  <= centre(v_q, lev_q);
      end
      StSq: begin
        xu_q    <= ceil_scale(radu);
        xv_q    <= ceil_scale(radv);
        remu_q  <= '0;
        remv_q  <= '0;
        rootu_q <= '0;
        rootv_q <= '0;
        it_q    <= '0;
      end
      StRoot: begin
        xu_q    <= xu_d;
        xv_q    <= xv_d;
        remu_q  <= remu_d;
        remv_q  <= remv_d;
        rootu_q <= rootu_d;
        rootv_q <= rootv_d;
        it_q    <= it_q + 5'd1;
      end
      StBox: begin
        x0_o <= x0_d;
        x1_o <= x1_d;
        y0_o <= y0_d;
        y1_o <= y1_d;
      end
      StCap: begin
        if (box > 64'(cap_q) && lev_q < top_q) begin
          lev_q   <= lev_q + 4'd1;
          fl_q[tu_formats_pkg::EwaFlagCapped] <= 1'b1;
        end
        box_o <= NW'(box);
      end
      StSt1: begin
        qa_q   <= qa;
        qb_q   <= qb;
        qc_q   <= qc;
        du0_q  <= du0;
        dv0_q  <= dv0;
        xi0_o  <= XiW'(64'(kxu_q) * 64'(du0) + 64'(kxv_q) * 64'(dv0));
        eta0_o <= XiW'(64'(kyu_q) * 64'(du0) + 64'(kyv_q) * 64'(dv0));
        dxi_o  <= XiW'(kxu_q) <<< PosF;
        deta_o <= XiW'(kyu_q) <<< PosF;
        dxiy_o <= XiW'(kxv_q) <<< PosF;
        detay_o <= XiW'(kyv_q) <<< PosF;
      end
      StSt2: begin
        q0_o   <= 64'(xi0_o) * 64'(xi0_o) + 64'(eta0_o) * 64'(eta0_o);
        dq0_o  <= qa_q * ((64'(du0_q) <<< (PosF + 1)) + 64'(StepSq)) + qb_q * (64'(dv0_q) <<< PosF);
        ddq_o  <= (qa_q <<< (2 * PosF + 1));
        ey0_o  <= (qb_q * 64'(du0_q) + qc_q * ((64'(dv0_q) <<< 1) + 64'(StepS))) <<< PosF;
        ddqy_o <= (qc_q <<< (2 * PosF + 1));
        dqy_o  <= (qb_q <<< (2 * PosF));
      end
      default: ;
    endcase
  end
  assign level_o = lev_q;
  assign guard_o = guard_q;
  assign cu_o    = cu_q;
  assign cv_o    = cv_q;
  assign flags_o = fl_q;
  logic unused;
  assign unused = ^{lod_i[tu_formats_pkg::EllLodW-5:0], eflags_i[4:1], atan_unused};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(RecHandshake, rec_valid_o, rec_ready_i, {level_o, flags_o, guard_o, x0_o, x1_o, y0_o, y1_o, box_o, cu_o, cv_o, xi0_o, eta0_o, dxi_o, deta_o, dxiy_o, detay_o, q0_o, dq0_o, ddq_o, ey0_o, ddqy_o, dqy_o})
endmodule
