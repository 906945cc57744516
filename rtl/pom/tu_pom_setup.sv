// POM per-pixel set-up (docs/blocks/relief.md §8; C model pom::setup), II = 1, latency
// PomSetupLatency (7):
//   stage 0    : a = max(|Vz|, PomVzMin) (clamped, back = Vz < 0); normalise a and N for the
//                reciprocal; S*Vx, S*Vy (exact)
//   stages 1-4 : two tu_recip_core (1/a and 1/N)
//   stage 5    : P  = round_half_up(S*Vxy * R_a >> (p_a + RecipOutF))
//   stage 6    : dT = round_half_up(P * R_n >> (p_n + RecipOutF)); P itself on pu_o, pv_o (the
//                iterative parallax's direction (P, 1), pom::ipx_dir_normalised)
// Neither product is followed by a variable shift: S*Vxy is shifted left by AMax - p_a in stage 1
// and R_n by NMax - p_n into its stage-5 register, so stages 5 and 6 shift by a constant (the
// same integers: numerator and divisor multiplied by the same power of two).
// side_i is carried along unchanged (the unit passes the pixel's T and wrap through it).
`include "tu_assert.svh"
module tu_pom_setup #(
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vz_i,
  input  logic [tu_formats_pkg::PomSW-1:0]    s_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    n_i,
  input  logic [SideW-1:0]                    side_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PomUvW-1:0]   du_o,
  output logic [tu_formats_pkg::PomUvW-1:0]   dv_o,
  output logic [tu_formats_pkg::PomUvW-1:0]   pu_o,
  output logic [tu_formats_pkg::PomUvW-1:0]   pv_o,
  output logic [tu_formats_pkg::PomNW-1:0]    n_o,
  output logic                                back_o,
  output logic                                clamped_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int Lat = tu_formats_pkg::PomSetupLatency;
  localparam int VzW = tu_formats_pkg::PomVzW;
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int NW  = tu_formats_pkg::PomNW;
  localparam int SW  = tu_formats_pkg::PomSW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int PW  = tu_formats_pkg::RecipShiftW;
  localparam int RF  = tu_formats_pkg::RecipOutF;
  localparam int XsW = VzW + SW + 1;   // S*Vx: signed
  localparam int AMax = VzW - 1;       // p_a = msb of a in [PomVzMin, 2^(VzW-1)]: 9 .. AMax
  localparam int ASh = AMax - 9;       // largest left shift of S*Vxy (a >= PomVzMin = 2^9)
  localparam int NMax = NW - 1;        // p_n = msb of N in 1 .. 63: 0 .. NMax
  localparam int XaW = XsW + ASh;      // S*Vxy << (AMax - p_a): signed
  localparam int RnW = RW + NMax;      // R_n << (NMax - p_n): unsigned
  localparam int PaW = XaW + RW + 1;   // S*Vxy' * R_a
  localparam int PnW = XsW + RnW + 1;  // P * R_n'
  localparam int ShA = AMax + RF;      // the constant shifts
  localparam int ShN = NMax + RF;
  localparam int CoreLat = tu_formats_pkg::RecipCoreLatency;  // tu_recip_core

  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- Stage 0 -----------------------------------------------------------------------------
  logic [VzW:0]  vz_abs, a;  // one extra bit: |-2^15| = 2^15
  logic          clamped_d;
  logic [MW-1:0] ma_d, mn_d;
  logic [PW-1:0] pa_d, pn_d;
  logic signed [XsW-1:0] xs_d, ys_d;
  always_comb begin
    vz_abs    = vz_i[VzW-1] ? (VzW+1)'(-$signed(vz_i)) : (VzW+1)'(vz_i);
    clamped_d = vz_abs < (VzW+1)'(tu_formats_pkg::PomVzMin);
    a         = clamped_d ? (VzW+1)'(tu_formats_pkg::PomVzMin) : vz_abs;
    xs_d      = XsW'($signed(vx_i) * $signed({1'b0, s_i}));
    ys_d      = XsW'($signed(vy_i) * $signed({1'b0, s_i}));
  end
  tu_recip_norm #(.InW(VzW + 1)) u_norm_a (.q_i(a),   .m_o(ma_d), .p_o(pa_d));
  tu_recip_norm #(.InW(NW))      u_norm_n (.q_i(n_i), .m_o(mn_d), .p_o(pn_d));

  // Operands delayed alongside the reciprocal cores (stages 0 .. CoreLat).
  logic [MW-1:0]         ma_q, mn_q;
  logic [PW-1:0]         pa_q;
  logic [PW-1:0]         pn_q [CoreLat+1];
  logic signed [XsW-1:0] xs_q0, ys_q0;
  logic signed [XaW-1:0] xs_q [CoreLat];  // xs_q[i]: stage i + 1, shifted
  logic signed [XaW-1:0] ys_q [CoreLat];
  logic [NW-1:0]         n_q [Lat];
  logic                  back_q [Lat];
  logic                  clamped_q [Lat];
  logic [SideW-1:0]      side_q [Lat];
  always_ff @(posedge clk_i) begin
    if (en) begin
      ma_q <= ma_d;
      mn_q <= mn_d;
      pa_q <= pa_d;
      pn_q[0] <= pn_d;
      xs_q0 <= xs_d;
      ys_q0 <= ys_d;
      // p_a in 9 .. AMax (a = max(|Vz|, 2^9) <= 2^15): the shift is 0 .. ASh
      xs_q[0] <= XaW'(xs_q0) <<< (PW'(AMax) - pa_q);
      ys_q[0] <= XaW'(ys_q0) <<< (PW'(AMax) - pa_q);
      n_q[0] <= n_i;
      back_q[0] <= vz_i[VzW-1];
      clamped_q[0] <= clamped_d;
      side_q[0] <= side_i;
      for (int i = 1; i < CoreLat; i++) begin
        xs_q[i] <= xs_q[i-1];
        ys_q[i] <= ys_q[i-1];
      end
      for (int i = 1; i <= CoreLat; i++) pn_q[i] <= pn_q[i-1];
      for (int i = 1; i < Lat; i++) begin
        n_q[i] <= n_q[i-1];
        back_q[i] <= back_q[i-1];
        clamped_q[i] <= clamped_q[i-1];
        side_q[i] <= side_q[i-1];
      end
    end
  end

  // ---- Stages 1-4: reciprocals (outputs line up with stage CoreLat) ------------------------
  logic [RW-1:0]  ra, rn;
  logic [RnW-1:0] rn_q5;
  tu_recip_core u_core_a (.clk_i, .en_i(en), .m_i(ma_q), .r_o(ra));
  tu_recip_core u_core_n (.clk_i, .en_i(en), .m_i(mn_q), .r_o(rn));

  // round_half_up(x * R / 2^p+RF), the C model's mul_recip (x signed, R unsigned), as
  // floor((x 2^(Max-p) * R + 2^(Max+RF-1)) / 2^(Max+RF)): the operand shifted before, one
  // multiply-add with a constant rounding term and a constant shift after.
  function automatic logic [UvW-1:0] mul_ra(input logic signed [XaW-1:0] x, input logic [RW-1:0] r);
    logic signed [PaW-1:0] p;
    p = PaW'(x) * $signed({1'b0, r}) + (PaW'(1) <<< (ShA - 1));
    p = p >>> ShA;  // |P| < 2^(UvW-1): the top bits are copies of the sign
    mul_ra = UvW'(p);
  endfunction
  function automatic logic [UvW-1:0] mul_rn(input logic signed [XsW-1:0] x, input logic [RnW-1:0] r);
    logic signed [PnW-1:0] p;
    p = PnW'(x) * $signed({1'b0, r}) + (PnW'(1) <<< (ShN - 1));
    p = p >>> ShN;  // |P| < 2^(UvW-1): the top bits are copies of the sign
    mul_rn = UvW'(p);
  endfunction

  // ---- Stage 5: P = S*Vxy / a;  stage 6: dT = P / N ------------------------------------------
  logic signed [UvW-1:0] pu_q, pv_q;
  logic [UvW-1:0]        du_q, dv_q, pu6_q, pv6_q;

  always_ff @(posedge clk_i) begin
    if (en) begin
      pu_q  <= mul_ra(xs_q[CoreLat-1], ra);
      pv_q  <= mul_ra(ys_q[CoreLat-1], ra);
      // p_n in 0 .. NMax (N in 1 .. 63; N = 0 gives p_n = 0 as before)
      rn_q5 <= RnW'(rn) << (PW'(NMax) - pn_q[CoreLat]);
      du_q  <= mul_rn(XsW'(pu_q), rn_q5);
      dv_q  <= mul_rn(XsW'(pv_q), rn_q5);
      pu6_q <= pu_q;
      pv6_q <= pv_q;
    end
  end

  assign du_o      = du_q;
  assign dv_o      = dv_q;
  assign pu_o      = pu6_q;
  assign pv_o      = pv6_q;
  assign n_o       = n_q[Lat-1];
  assign back_o    = back_q[Lat-1];
  assign clamped_o = clamped_q[Lat-1];
  assign side_o    = side_q[Lat-1];

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {du_o, dv_o, pu_o, pv_o, n_o, back_o, clamped_o, side_o})
endmodule
