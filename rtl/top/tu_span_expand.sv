// Span -> pixel stream: holds one span [x0, x1] of row y and emits one pixel per clock (valid/
// ready), x0 first. Per pixel it provides the tu_persp inputs (seeds, increments, offset n; the
// unit accumulates itself), the B1 accumulator q of the pixel (q0 + n G, exact, for tu_ellipse),
// and the B2 numerators: nux, nvx constant along the row, nuy -= m, nvy -= nn per pixel (exact),
// each rounded half up to s(EllNumW).EllNumF and saturated (ellipse::fx::round_num); and for the
// recurrence ellipse (tu_ellipse_rec) the seed's other denominator factors q(x+1) = q + G and
// q(y+1) = q + H (s(EllRecQW).PerspF), seeded per span (per scanline) at q0 + G, q0 + H and
// advancing by + G per pixel (exact; unused, and removed by synthesis, with the analytic ellipse).
`include "tu_assert.svh"
module tu_span_expand #(
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]  pu0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  pv0_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  q0_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]  d_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  g_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]  h_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nux_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nvx_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nuy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nvy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   m_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]   nn_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] x0_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0] x1_i,
  input  logic [SideW-1:0]                    side_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PerspPW-1:0]  pu0_o,
  output logic [tu_formats_pkg::PerspPW-1:0]  pv0_o,
  output logic [tu_formats_pkg::PerspQW-1:0]  q0_o,
  output logic [tu_formats_pkg::PerspPW-1:0]  a_o,
  output logic [tu_formats_pkg::PerspPW-1:0]  d_o,
  output logic [tu_formats_pkg::PerspQW-1:0]  g_o,
  output logic [tu_formats_pkg::PerspXyW-1:0] n_o,
  output logic [tu_formats_pkg::PerspXyW-1:0] x_o,
  output logic [tu_formats_pkg::PerspQW-1:0]  q_o,
  output logic [tu_formats_pkg::EllRecQW-1:0] qg_o,
  output logic [tu_formats_pkg::EllRecQW-1:0] qh_o,
  output logic [tu_formats_pkg::EllNumW-1:0]  nux_o,
  output logic [tu_formats_pkg::EllNumW-1:0]  nvx_o,
  output logic [tu_formats_pkg::EllNumW-1:0]  nuy_o,
  output logic [tu_formats_pkg::EllNumW-1:0]  nvy_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int NW  = tu_formats_pkg::EllNxW;
  localparam int OW  = tu_formats_pkg::EllNumW;
  localparam int Sh  = 2 * tu_formats_pkg::PerspF - tu_formats_pkg::EllNumF;
  localparam int RsW = NW - Sh + 1;
  localparam int GW  = tu_formats_pkg::EllRecQW;
  localparam logic signed [RsW-1:0] OMax = (RsW'(1) <<< (OW - 1)) - RsW'(1);
  localparam logic signed [RsW-1:0] OMin = -(RsW'(1) <<< (OW - 1));

  // round half up by Sh bits, saturate to s(EllNumW)
  function automatic logic [OW-1:0] round_num(input logic [NW-1:0] v);
    logic signed [NW:0]    t;
    logic signed [RsW-1:0] r;
    t = $signed({v[NW-1], v}) + $signed((NW+1)'(1) << (Sh - 1));
    r = RsW'(t >>> Sh);
    if (r > OMax) round_num = OW'(OMax);
    else if (r < OMin) round_num = OW'(OMin);
    else round_num = OW'(r);
  endfunction

  logic                                busy_q, fire, last;
  logic [tu_formats_pkg::PerspXyW-1:0] x_q, x0_q, x1_q;
  logic [tu_formats_pkg::PerspQW-1:0]  q_q;
  logic [GW-1:0]                       qg_q, qh_q;
  logic [GW-1:0]                       g_s, g_in_s, h_in_s, q0_s;
  assign g_s    = GW'($signed(g_o));
  assign g_in_s = GW'($signed(g_i));
  assign h_in_s = GW'($signed(h_i));
  assign q0_s   = GW'($signed(q0_i));
  logic [NW-1:0]                       nux_q, nvx_q, nuy_q, nvy_q, m_q, nn_q;
  assign fire        = busy_q && out_ready_i;
  assign last        = x_q == x1_q;
  assign in_ready_o  = !busy_q || (fire && last);
  assign out_valid_o = busy_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) busy_q <= 1'b0;
    else if (in_valid_i && in_ready_o) busy_q <= 1'b1;
    else if (fire && last) busy_q <= 1'b0;
  end
  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) begin
      pu0_o  <= pu0_i;
      pv0_o  <= pv0_i;
      q0_o   <= q0_i;
      a_o    <= a_i;
      d_o    <= d_i;
      g_o    <= g_i;
      x_q    <= x0_i;
      x0_q   <= x0_i;
      x1_q   <= x1_i;
      q_q    <= q0_i;
      qg_q   <= q0_s + g_in_s;
      qh_q   <= q0_s + h_in_s;
      nux_q  <= nux_i;
      nvx_q  <= nvx_i;
      nuy_q  <= nuy_i;
      nvy_q  <= nvy_i;
      m_q    <= m_i;
      nn_q   <= nn_i;
      side_o <= side_i;
    end else if (fire) begin
      x_q   <= x_q + 1'b1;
      q_q   <= q_q + g_o;
      qg_q  <= qg_q + g_s;
      qh_q  <= qh_q + g_s;
      nuy_q <= nuy_q - m_q;
      nvy_q <= nvy_q - nn_q;
    end
  end
  assign n_o   = x_q - x0_q;
  assign x_o   = x_q;
  assign q_o   = q_q;
  assign qg_o  = qg_q;
  assign qh_o  = qh_q;
  assign nux_o = round_num(nux_q);
  assign nvx_o = round_num(nvx_q);
  assign nuy_o = round_num(nuy_q);
  assign nvy_o = round_num(nvy_q);

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  // Two groups: Verilator 5.006 emits broken C++ for the sampled copy of one 1,300-bit value.
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {pu0_o, pv0_o, q0_o, a_o, d_o, g_o, n_o, x_o, q_o, qg_o, qh_o, nux_o, nvx_o, nuy_o, nvy_o})
  `TU_ASSERT_HANDSHAKE(OutHandshakeSide, out_valid_o, out_ready_i, side_o)
endmodule
