// POM refinement (docs/blocks/relief.md §8; C model pom::refine), II = 1, latency
// PomRefineLatency (7):
//   stage 0    : normalise den for the reciprocal (k = 0: den = 0, w forced to 0)
//   stages 1-4 : tu_recip_core (1/den)
//   stage 5    : w = min(round_half_up(a * 2^PomWF * R >> (p + RecipOutF)), 2^PomWF), as
//                w = sat ? 2^PomWF : (a' * R + 2^(DW+RecipOutF-PomWF-2)) >> (DW+RecipOutF-PomWF-1)
//                with a' = a << (DW - 1 - p) (stage 1) and sat = a >= den, a != 0 (stage 0): no
//                shifter and no compare after the product (identities below)
//   stage 6    : T'' = T_k + round_half_up(w * dT >> PomWF); wrap: fract(T''), else discard =
//                T'' outside [0, 1]^2
// side_i (the unit's back / clamped flags) is carried along unchanged.
`include "tu_assert.svh"
module tu_pom_refine #(
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomUvW-1:0]   u_i,     // T_k
  input  logic [tu_formats_pkg::PomUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   du_i,    // dT
  input  logic [tu_formats_pkg::PomUvW-1:0]   dv_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    steps_i, // k
  input  logic [tu_formats_pkg::PomDenW-1:0]  a_i,     // 255k - h_k N
  input  logic [tu_formats_pkg::PomDenW-1:0]  den_i,   // a + b
  input  logic                                wrap_i,
  input  logic [SideW-1:0]                    side_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PomUvW-1:0]   u_o,     // T''
  output logic [tu_formats_pkg::PomUvW-1:0]   v_o,
  output logic [tu_formats_pkg::PomNW-1:0]    steps_o,
  output logic [tu_formats_pkg::PomWW-1:0]    w_o,
  output logic                                discard_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int Lat = tu_formats_pkg::PomRefineLatency;
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int UvF = tu_formats_pkg::PomUvF;
  localparam int NW  = tu_formats_pkg::PomNW;
  localparam int DW  = tu_formats_pkg::PomDenW;
  localparam int WW  = tu_formats_pkg::PomWW;
  localparam int WF  = tu_formats_pkg::PomWF;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int PW  = tu_formats_pkg::RecipShiftW;
  localparam int RF  = tu_formats_pkg::RecipOutF;
  localparam int AwW = DW + RW;         // a' * R + rounding, unsigned (< 2^(DW+RW-1))
  localparam int ShW = UvW + WW + 1;    // w * dT, signed
  localparam int CoreLat = tu_formats_pkg::RecipCoreLatency;  // tu_recip_core

  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- Stage 0: normalise den ------------------------------------------------------------------
  logic [MW-1:0] m_d, m_q;
  logic [PW-1:0] p_d;
  tu_recip_norm #(.InW(DW)) u_norm (.q_i(den_i), .m_o(m_d), .p_o(p_d));
  logic sat_d;
  assign sat_d = a_i >= den_i && a_i != '0;

  // Operands delayed alongside the reciprocal core.
  logic [PW-1:0]      p_q;
  logic [DW-1:0]      a_q [CoreLat+1];
  logic               sat_q [CoreLat+1];
  logic [UvW-1:0]     u_q [Lat-1];
  logic [UvW-1:0]     v_q [Lat-1];
  logic [UvW-1:0]     du_q [Lat-1];
  logic [UvW-1:0]     dv_q [Lat-1];
  logic [NW-1:0]      steps_q [Lat];
  logic               wrap_q [Lat-1];
  logic [SideW-1:0]   side_q [Lat];
  always_ff @(posedge clk_i) begin
    if (en) begin
      m_q <= m_d;
      p_q <= p_d;
      // k = 0: w = 0 (a' = 0, no saturation); a >= den: w = 2^WF (a' unused, held at 0)
      a_q[0] <= (steps_i == '0 || sat_d) ? '0 : a_i;
      sat_q[0] <= steps_i != '0 && sat_d;
      // a' = a << (DW - 1 - p): a < den < 2^(p+1) makes a' < 2^DW (den < 2^DW: p <= DW - 1)
      a_q[1] <= DW'(a_q[0] << (PW'(DW - 1) - p_q));
      sat_q[1] <= sat_q[0];
      u_q[0] <= u_i;
      v_q[0] <= v_i;
      du_q[0] <= du_i;
      dv_q[0] <= dv_i;
      steps_q[0] <= steps_i;
      wrap_q[0] <= wrap_i;
      side_q[0] <= side_i;
      for (int i = 2; i <= CoreLat; i++) begin
        a_q[i] <= a_q[i-1];
        sat_q[i] <= sat_q[i-1];
      end
      for (int i = 1; i < Lat - 1; i++) begin
        u_q[i] <= u_q[i-1];
        v_q[i] <= v_q[i-1];
        du_q[i] <= du_q[i-1];
        dv_q[i] <= dv_q[i-1];
        wrap_q[i] <= wrap_q[i-1];
      end
      for (int i = 1; i < Lat; i++) begin
        steps_q[i] <= steps_q[i-1];
        side_q[i] <= side_q[i-1];
      end
    end
  end

  // ---- Stages 1-4: reciprocal --------------------------------------------------------------
  logic [RW-1:0] r;
  tu_recip_core u_core (.clk_i, .en_i(en), .m_i(m_q), .r_o(r));

  // ---- Stage 5: w ----------------------------------------------------------------------------
  // round_half_up(a 2^WF R / 2^(p+RF)) = floor((a' R + 2^(XSh-1)) / 2^XSh), XSh = DW - 1 + RF - WF:
  // multiply numerator and denominator by 2^(DW-1-p) (exact), then 2^WF divides both terms.
  // The clamp: with R = recip::eval(den) the unclamped w is >= 2^WF for a = den and <= 2^WF for
  // a = den - 1 for every den in 1 .. 2^DW - 1 (exhaustive, PomMarch.RefineClampIsTheCompareAGeDen),
  // and w grows with a, so min(w, 2^WF) = 2^WF exactly when a >= den; den = 0 (outside the march's
  // range) gives the C model's R = max, so w = 2^WF for a > 0 and 0 for a = 0: sat = a >= den, a != 0.
  localparam int XSh = DW - 1 + RF - WF;
  logic [AwW-1:0] aw;
  logic [WW-1:0]  w_d, w_q;
  always_comb begin
    aw = AwW'(a_q[CoreLat]) * AwW'(r) + (AwW'(1) << (XSh - 1));
    w_d = sat_q[CoreLat] ? WW'(1 << WF) : aw[XSh +: WW];
  end

  // ---- Stage 6: T'' ----------------------------------------------------------------------------
  logic signed [ShW-1:0] su, sv;
  logic signed [UvW-1:0] tu, tv;
  logic                  out_of_range;
  localparam logic signed [UvW-1:0] One = UvW'(1 << UvF);
  // T_k + round_half_up(w dT / 2^WF) = floor((w dT + T_k 2^WF + 2^(WF-1)) / 2^WF): one
  // multiply-add (T_k and the rounding term in the product's carry-save tree), wrapped to UvW
  // bits as the straight form T_k + (the rounded product) is.
  always_comb begin
    su = ($signed({1'b0, w_q}) * ShW'($signed(du_q[Lat-2])) + (ShW'($signed(u_q[Lat-2])) <<< WF)
          + (ShW'(1) <<< (WF - 1))) >>> WF;
    sv = ($signed({1'b0, w_q}) * ShW'($signed(dv_q[Lat-2])) + (ShW'($signed(v_q[Lat-2])) <<< WF)
          + (ShW'(1) <<< (WF - 1))) >>> WF;
    tu = UvW'(su);
    tv = UvW'(sv);
    out_of_range = tu < 0 || tv < 0 || tu > One || tv > One;
  end

  logic [UvW-1:0] u_o_q, v_o_q;
  logic [WW-1:0]  w_o_q;
  logic           discard_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      w_q <= w_d;
      w_o_q <= w_q;
      u_o_q <= wrap_q[Lat-2] ? {{(UvW-UvF){1'b0}}, tu[UvF-1:0]} : tu;
      v_o_q <= wrap_q[Lat-2] ? {{(UvW-UvF){1'b0}}, tv[UvF-1:0]} : tv;
      discard_q <= !wrap_q[Lat-2] && out_of_range;
    end
  end

  assign u_o       = u_o_q;
  assign v_o       = v_o_q;
  assign steps_o   = steps_q[Lat-1];
  assign w_o       = w_o_q;
  assign discard_o = discard_q;
  assign side_o    = side_q[Lat-1];

  // T'' wraps to UvW bits (as T_k + the rounded product does): the sum's top bits are unused.
  logic unused_bits;
  assign unused_bits = ^{stage_valid, su[ShW-1:UvW], sv[ShW-1:UvW], aw[AwW-1:XSh+WW], aw[XSh-1:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, steps_o, w_o, discard_o, side_o})
endmodule
