// Perspective divide, per-pixel back end (stages S2..S8 of tu_persp, latency 7, II = 1): guard,
// normalise, reciprocal (tu_recip_core), two multiplies, shift/round/saturate. Shared by the
// single-pixel unit tu_persp and the k-lane unit tu_persp_klane. Formats: cmodel/blocks/persp.
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
  localparam logic signed [ProdW-1:0] UMax = ProdW'({1'b0, {(UW-1){1'b1}}});
  // -2^(UW-1) written bit by bit: Yosys 0.23 drops the minus of -ProdW'(...) in a localparam.
  localparam logic signed [ProdW-1:0] UMin = {{(ProdW-UW+1){1'b1}}, {(UW-1){1'b0}}};
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

  // ---- S7: two multiply-adds: x = p * R + 2^(sh-1), the rounding term of S8 added here, in the
  // products' carry-save trees (S8 used to add it to the 80-bit products and then shift: an
  // adder and a shifter in one stage, tu_persp's critical path, 14.3 ns in osu018).
  // |p * R| < 2^(PW-1+RW) and sh - 1 < PW - 1 + RW, so x fits ProdW bits.
  localparam int Sh0 = tu_formats_pkg::RecipOutF - tu_formats_pkg::PerspUvF;  // sh = Sh0 + e
  logic signed [ProdW-1:0] r_ext, pu_ext, pv_ext, half, prod_u_q, prod_v_q;
  assign r_ext  = ProdW'({1'b0, r});
  assign pu_ext = ProdW'($signed(pu_q[CoreLat]));
  assign pv_ext = ProdW'($signed(pv_q[CoreLat]));
  assign half   = ProdW'(1) << (Sh0 - 1 + 32'(e_q[CoreLat]));
  always_ff @(posedge clk_i) begin
    if (en) begin
      prod_u_q <= pu_ext * r_ext + half;
      prod_v_q <= pv_ext * r_ext + half;
    end
  end

  // ---- S8: round half up = floor(x / 2^sh): a shift by the exponent; saturate
  localparam int TW = ProdW - Sh0;
  localparam logic signed [TW-1:0] SatMax = TW'(UMax);
  localparam logic signed [TW-1:0] SatMin = TW'(UMin);
  localparam logic [UW-1:0] CodeMax = {1'b0, {(UW-1){1'b1}}};
  localparam logic [UW-1:0] CodeMin = {1'b1, {(UW-1){1'b0}}};
  logic [UW-1:0]           u_d, v_d, u_q8, v_q8;
  logic                    flag_q8;
  logic signed [TW-1:0]    rnd_u, rnd_v;
  always_comb begin
    rnd_u = $signed(prod_u_q[ProdW-1:Sh0]) >>> e_q[CoreLat+1];
    rnd_v = $signed(prod_v_q[ProdW-1:Sh0]) >>> e_q[CoreLat+1];
    if (g_q[CoreLat+1] || rnd_u > SatMax) u_d = CodeMax;
    else if (rnd_u < SatMin)              u_d = CodeMin;
    else                                  u_d = rnd_u[UW-1:0];
    if (g_q[CoreLat+1] || rnd_v > SatMax) v_d = CodeMax;
    else if (rnd_v < SatMin)              v_d = CodeMin;
    else                                  v_d = rnd_v[UW-1:0];
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

  // truncated mantissa bits; the products' bits below 2^Sh0 (the floor drops them)
  logic unused;
  assign unused = ^{nrm[QW-MW-1:0], prod_u_q[Sh0-1:0], prod_v_q[Sh0-1:0]};

endmodule
