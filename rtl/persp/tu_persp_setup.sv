// Perspective divide unit (B1), per-scanline set-up, II = 1, latency 2 (persp::kSetupLatency).
// One input = one span [x0, x1] on row y with the quantised coefficients A..I (s54.40 / s44.40);
// outputs the accumulator seeds at x0 (the inputs pu0, pv0, q0 of tu_persp) and an overflow
// flag, exactly as persp::Model::setup_span (docs/blocks/persp.md):
//   S1 multiply : A x0, A x1, B y, D x0, D x1, E y, G x0, G x1, H y   (nine exact products,
//                 signed coefficient x unsigned 12-bit index)
//   S2 add      : p(x) = A x + B y + C (exact, PW + XyW + 2 bits) at x0 and x1 for p_u, p_v, q;
//                 ovf = some value does not fit its accumulator format (s54.40 / s44.40);
//                 outputs are the values at x0 modulo 2^W (exact whenever ovf = 0)
`include "tu_assert.svh"
module tu_persp_setup (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]  a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  b_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  c_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  d_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  e_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  f_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  g_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  h_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  i_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] x0_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] x1_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] y_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PerspPW-1:0]  pu_o,
  output logic [tu_formats_pkg::PerspPW-1:0]  pv_o,
  output logic [tu_formats_pkg::PerspQW-1:0]  q_o,
  output logic                                ovf_o
);
  localparam int PW  = tu_formats_pkg::PerspPW;
  localparam int QW  = tu_formats_pkg::PerspQW;
  localparam int XW  = tu_formats_pkg::PerspXyW;
  localparam int PMW = PW + XW + 1;  // signed coefficient x unsigned index, exact
  localparam int QMW = QW + XW + 1;
  localparam int PSW = PMW + 1;      // A x + B y + C: |.| < 2^(PW+XW) + 2^(PW-1)
  localparam int QSW = QMW + 1;
  localparam int Depth = tu_formats_pkg::PerspSetupLatency;

  logic             en;
  logic [Depth-1:0] stage_valid;

  tu_pipe_valid #(.Depth(Depth)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- S1: nine exact products; C, F, I carried along
  logic signed [XW:0] x0_s, x1_s, y_s;
  assign x0_s = $signed({1'b0, x0_i});
  assign x1_s = $signed({1'b0, x1_i});
  assign y_s  = $signed({1'b0, y_i});

  logic signed [PMW-1:0] ax0_q, ax1_q, by_q, dx0_q, dx1_q, ey_q;
  logic signed [QMW-1:0] gx0_q, gx1_q, hy_q;
  logic signed [PW-1:0]  c_q, f_q;
  logic signed [QW-1:0]  i_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      ax0_q <= $signed(a_i) * x0_s;
      ax1_q <= $signed(a_i) * x1_s;
      by_q  <= $signed(b_i) * y_s;
      dx0_q <= $signed(d_i) * x0_s;
      dx1_q <= $signed(d_i) * x1_s;
      ey_q  <= $signed(e_i) * y_s;
      gx0_q <= $signed(g_i) * x0_s;
      gx1_q <= $signed(g_i) * x1_s;
      hy_q  <= $signed(h_i) * y_s;
      c_q   <= $signed(c_i);
      f_q   <= $signed(f_i);
      i_q   <= $signed(i_i);
    end
  end

  // ---- S2: exact sums at both span ends, range check against the accumulator formats
  logic signed [PSW-1:0] pu0, pu1, pv0, pv1;
  logic signed [QSW-1:0] q0, q1;
  assign pu0 = PSW'(ax0_q) + PSW'(by_q) + PSW'(c_q);
  assign pu1 = PSW'(ax1_q) + PSW'(by_q) + PSW'(c_q);
  assign pv0 = PSW'(dx0_q) + PSW'(ey_q) + PSW'(f_q);
  assign pv1 = PSW'(dx1_q) + PSW'(ey_q) + PSW'(f_q);
  assign q0  = QSW'(gx0_q) + QSW'(hy_q) + QSW'(i_q);
  assign q1  = QSW'(gx1_q) + QSW'(hy_q) + QSW'(i_q);

  // A value fits s(W) iff its bits [SW-1 : W-1] are all equal (sign extension of bit W-1).
  logic [5:0] fits;
  assign fits[0] = (pu0[PSW-1:PW-1] == '0) || (pu0[PSW-1:PW-1] == '1);
  assign fits[1] = (pv0[PSW-1:PW-1] == '0) || (pv0[PSW-1:PW-1] == '1);
  assign fits[2] = (q0[QSW-1:QW-1] == '0)  || (q0[QSW-1:QW-1] == '1);
  assign fits[3] = (pu1[PSW-1:PW-1] == '0) || (pu1[PSW-1:PW-1] == '1);
  assign fits[4] = (pv1[PSW-1:PW-1] == '0) || (pv1[PSW-1:PW-1] == '1);
  assign fits[5] = (q1[QSW-1:QW-1] == '0)  || (q1[QSW-1:QW-1] == '1);

  always_ff @(posedge clk_i) begin
    if (en) begin
      pu_o  <= pu0[PW-1:0];
      pv_o  <= pv0[PW-1:0];
      q_o   <= q0[QW-1:0];
      ovf_o <= ~&fits;
    end
  end

  logic unused;
  assign unused = ^{stage_valid, pu1[PW-2:0], pv1[PW-2:0], q1[QW-2:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {pu_o, pv_o, q_o, ovf_o})
endmodule
