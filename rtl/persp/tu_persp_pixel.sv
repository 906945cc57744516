// Perspective divide, per-pixel back end (stages S2..S8 of tu_persp, latency 7, II = 1): guard,
// normalise, reciprocal (tu_recip_core), two multiply-adds in carry-save form (S7), their carry
// chains and shift/round/saturate (S8). Shared by the single-pixel unit tu_persp, the k-lane unit
// tu_persp_klane and tu_objspace_sample. Formats: cmodel/blocks/persp.
module tu_persp_pixel (
  input  logic                                clk_i,
  input  logic                                en_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  pu_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  pv_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  q_i,
  output logic [tu_formats_pkg::PerspUvW-1:0] u_o,
  output logic [tu_formats_pkg::PerspUvW-1:0] v_o,
  output logic                                flag_o
);
  localparam int PW = tu_formats_pkg::PerspPW;
  localparam int QW = tu_formats_pkg::PerspQW;
  localparam int MW = tu_formats_pkg::RecipMantW;
  localparam int RW = tu_formats_pkg::RecipOutW;
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int EW = 6;                 // msb position of q, 0..QW-2
  localparam int ProdW = PW + RW + 1;    // signed p * unsigned R
  localparam int CoreLat = tu_formats_pkg::RecipCoreLatency;  // tu_recip_core
  localparam logic [QW-1:0] GuardVal = QW'(1) << (tu_formats_pkg::PerspF - tu_formats_pkg::PerspGuardLog2);
  logic en;
  logic [PW-1:0] pu_q1, pv_q1;
  logic [QW-1:0] q_q1;
  assign en = en_i;
  assign pu_q1 = pu_i;
  assign pv_q1 = pv_i;
  assign q_q1 = q_i;

  // ---- S2: guard, leading-one detect, normalise (truncate to MW bits)
  logic          guard;
  logic [EW-1:0] msb;
  logic [QW-1:0] nrm;
  always_comb begin
    guard = q_q1[QW-1] || (q_q1 < GuardVal);
    msb = '0;
    for (int i = 0; i < QW - 1; i++) begin
      if (q_q1[i]) msb = EW'(i);
    end
    nrm = q_q1 << (QW - 1 - 32'(msb));
  end

  logic [MW-1:0] m_q2;
  logic [EW-1:0] e_q [CoreLat+2];
  logic          g_q [CoreLat+2];
  logic [PW-1:0] pu_q [CoreLat+1];
  logic [PW-1:0] pv_q [CoreLat+1];
  always_ff @(posedge clk_i) begin
    if (en) begin
      m_q2    <= nrm[QW-1 -: MW];
      e_q[0]  <= msb;
      g_q[0]  <= guard;
      pu_q[0] <= pu_q1;
      pv_q[0] <= pv_q1;
      for (int i = 1; i <= CoreLat; i++) begin
        e_q[i]  <= e_q[i-1];
        g_q[i]  <= g_q[i-1];
        pu_q[i] <= pu_q[i-1];
        pv_q[i] <= pv_q[i-1];
      end
      e_q[CoreLat+1] <= e_q[CoreLat];
      g_q[CoreLat+1] <= g_q[CoreLat];
    end
  end
  // pu_q[CoreLat] lines up with the core output (S6); e_q/g_q[CoreLat+1] with the products (S7).

  // ---- S3..S6: reciprocal core
  logic [RW-1:0] r;
  tu_recip_core u_core (.clk_i, .en_i(en), .m_i(m_q2), .r_o(r));

  // ---- S7: two multiply-adds x = p * R + 2^(sh-1) (the rounding term of S8 inside the product),
  // each left in carry-save form: S7 holds the partial-product rows and their 3:2 compressor tree
  // only; the carry-propagate add moved to S8 (S7 used to end in the 80-bit carry chain: 7.56 ns
  // in osu018, R's register fan-out 1.5 ns + tree 2.1 ns + carry chain 3.0 ns; now the chain runs
  // in S8, whose shift and saturation were short). Rows: p * R[j] * 2^j (p sign-extended) for
  // j < RW, and the rounding term; every 3 rows become 2 (sum, carry << 1) per level, all
  // modulo 2^ProdW, so s + c = x (mod 2^ProdW), and x itself fits ProdW bits:
  // |p * R| < 2^(PW-1+RW) and sh - 1 < PW - 1 + RW. The low Sh0 bits of x are dropped by S8's
  // floor; only their carry into bit Sh0 is kept (cy).
  localparam int Sh0 = tu_formats_pkg::RecipOutF - tu_formats_pkg::PerspUvF;  // sh = Sh0 + e
  localparam int TW = ProdW - Sh0;
  // tu_csa.svh: the rows and the compressor tree, shared with tu_ewa_norm_tail.
  localparam int CsaW = ProdW;
  localparam int CsaM = RW;
  localparam int CsaB = 0;
`include "tu_csa.svh"

  logic [ProdW-1:0] half, su, cu, sv, cv;
  logic [Sh0:0]     lo_u, lo_v;
  logic [TW-1:0]    su_q, cu_q, sv_q, cv_q;
  logic             cyu_q, cyv_q;
  assign half = ProdW'(1) << (Sh0 - 1 + 32'(e_q[CoreLat]));
  assign {cu, su} = csa_mul(ProdW'($signed(pu_q[CoreLat])), r, 1'b0, half);
  assign {cv, sv} = csa_mul(ProdW'($signed(pv_q[CoreLat])), r, 1'b0, half);
  assign lo_u = (Sh0+1)'(su[Sh0-1:0]) + (Sh0+1)'(cu[Sh0-1:0]);
  assign lo_v = (Sh0+1)'(sv[Sh0-1:0]) + (Sh0+1)'(cv[Sh0-1:0]);
  always_ff @(posedge clk_i) begin
    if (en) begin
      su_q  <= su[ProdW-1:Sh0];
      cu_q  <= cu[ProdW-1:Sh0];
      cyu_q <= lo_u[Sh0];
      sv_q  <= sv[ProdW-1:Sh0];
      cv_q  <= cv[ProdW-1:Sh0];
      cyv_q <= lo_v[Sh0];
    end
  end

  // ---- S8: x[ProdW-1:Sh0] = s + c + cy (the carry chain), round half up = floor(x / 2^sh):
  // a shift by the exponent; saturate
  localparam logic [UW-1:0] CodeMax = {1'b0, {(UW-1){1'b1}}};
  localparam logic [UW-1:0] CodeMin = {1'b1, {(UW-1){1'b0}}};
  // floor(x / 2^e) saturated to UW bits. Out of range <=> x >= 2^(UW-1+e) or x < -2^(UW-1+e)
  // <=> bits x[TW-1 : UW-1+e] not all equal to the sign: tested on x itself, beside the shift
  // (it was a compare after the shift).
  function automatic logic [UW-1:0] shift_sat(input logic [TW-1:0] x, input logic [EW-1:0] ee,
                                               input logic guard_f);
    logic [TW-1:0] mask;
    logic [UW-1:0] rnd;
    logic          ovf;
    for (int i = 0; i < TW; i++) mask[i] = (i >= UW - 1 + 32'(ee));
    ovf = |((x ^ {TW{x[TW-1]}}) & mask);
    rnd = UW'($signed(x) >>> ee);
    if (guard_f || (ovf && !x[TW-1])) shift_sat = CodeMax;
    else if (ovf)                     shift_sat = CodeMin;
    else                              shift_sat = rnd;
  endfunction
  logic [UW-1:0]           u_d, v_d, u_q8, v_q8;
  logic                    flag_q8;
  logic [TW-1:0]           xu, xv;
  always_comb begin
    // one adder with cy as its carry-in: (2s + cy) + (2c + cy) = 2 (s + c + cy)
    xu = TW'(({su_q, cyu_q} + {cu_q, cyu_q}) >> 1);
    xv = TW'(({sv_q, cyv_q} + {cv_q, cyv_q}) >> 1);
    u_d = shift_sat(xu, e_q[CoreLat+1], g_q[CoreLat+1]);
    v_d = shift_sat(xv, e_q[CoreLat+1], g_q[CoreLat+1]);
  end
  always_ff @(posedge clk_i) begin
    if (en) begin
      u_q8    <= u_d;
      v_q8    <= v_d;
      flag_q8 <= g_q[CoreLat+1];
    end
  end
  assign u_o    = u_q8;
  assign v_o    = v_q8;
  assign flag_o = flag_q8;

  // truncated mantissa bits; the low sums' bits below 2^Sh0 (the floor drops them, their carry stays)
  logic unused;
  assign unused = ^{nrm[QW-MW-1:0], lo_u[Sh0-1:0], lo_v[Sh0-1:0]};

endmodule
