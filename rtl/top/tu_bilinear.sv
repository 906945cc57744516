// Bilinear filter at level L through the texel port (the bilinear engine of tu_texture_unit, L = 0;
// tu_trilinear runs it at two levels; a B1-guard pixel: the texture's mean, texel (0, 0) of the
// 1x1 top level, as render_cmodel), exactly tex::bilinear(t, L, u, v): level-L position
// u / 2^L - 1/2 = u - 2^(TexUvF + L - 1) with TexUvF + L fraction bits, x0 = floor, weight fx = the
// top TexWeightF (= TexUvF) bits of its fraction (truncated), per channel
// round_half_up(((c00 (1-fx) + c10 fx)(1-fy) + (c01 (1-fx) + c11 fx) fy)). Four reads, one per
// clock (1-cycle read latency): 6 cycles from acceptance to out_valid, then held until taken.
`include "tu_assert.svh"
module tu_bilinear (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0] u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0] v_i,
  input  logic                                guard_i,  // B1 guard: texel (0, 0) of the 1x1 top level
  input  logic [3:0]                          level_i,  // L (TexUvF + L < 32: the shifts stay in range)
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_i,   // {v, u} Wrap* codes (tu_texel_addr)
  output logic                                tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] tex_addr_o,
  input  logic [31:0]                         tex_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [31:0]                         rgba_o
);
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int F  = tu_formats_pkg::TexUvF;
  localparam int One = 1 << F;
  localparam logic [F:0]   OneF = (F+1)'(One);
  logic [2:0]                          st_q;   // 0 idle, 1..4 read k-1, 5 last data, 6 output
  logic signed [UW-1:0]                x0_q, y0_q;
  logic [F:0]                          fx_q, fy_q;
  logic [tu_formats_pkg::TexAddrW-1:0] base_q;
  logic [3:0]                          lw_q, lh_q, lev_q;
  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_q;
  logic [31:0]                         c_q [3];
  logic signed [UW-1:0]                su, sv;
  logic [4:0]                          sh;  // TexUvF + L: fraction bits of the level-L position
  assign sh = 5'(F) + {1'b0, level_i};
  assign su = $signed(u_i) - $signed(UW'(One / 2) << level_i);
  assign sv = $signed(v_i) - $signed(UW'(One / 2) << level_i);
  assign in_ready_o  = st_q == 3'd0;
  assign out_valid_o = st_q == 3'd6;
  assign tex_req_o   = st_q >= 3'd1 && st_q <= 3'd4;

  logic signed [UW-1:0] rx, ry;
  assign rx = x0_q + ((st_q == 3'd2 || st_q == 3'd4) ? UW'(1) : UW'(0));
  assign ry = y0_q + ((st_q == 3'd3 || st_q == 3'd4) ? UW'(1) : UW'(0));
  tu_texel_addr #(.CoordW(UW)) u_addr (
    .base_i(base_q), .lw_i(lw_q), .lh_i(lh_q), .wrap_i(wrap_q), .level_i(lev_q),
    .x_i(rx), .y_i(ry), .addr_o(tex_addr_o)
  );

  // Blend (combinational, registered into rgba_o when the last texel arrives).
  logic [31:0] blend;
  logic [F:0]  gx, gy;  // 1 - fx, 1 - fy
  assign gx = OneF - fx_q;
  assign gy = OneF - fy_q;
  always_comb begin
    for (int c = 0; c < 4; c++) begin
      logic [8+F:0]     top, bot;
      /* verilator lint_off UNUSEDSIGNAL */
      logic [8+2*F+1:0] s;  // < 2^(8+2F): bits above the rounded channel are 0
      /* verilator lint_on UNUSEDSIGNAL */
      top = (8+F+1)'(c_q[0][8*c +: 8]) * (8+F+1)'(gx) + (8+F+1)'(c_q[1][8*c +: 8]) * (8+F+1)'(fx_q);
      bot = (8+F+1)'(c_q[2][8*c +: 8]) * (8+F+1)'(gx) + (8+F+1)'(tex_data_i[8*c +: 8]) * (8+F+1)'(fx_q);
      s = (8+2*F+2)'(top) * (8+2*F+2)'(gy) + (8+2*F+2)'(bot) * (8+2*F+2)'(fy_q) +
          (8+2*F+2)'(1 << (2*F - 1));
      blend[8*c +: 8] = s[2*F +: 8];
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= 3'd0;
    else if (st_q == 3'd0) st_q <= in_valid_i ? 3'd1 : 3'd0;
    else if (st_q == 3'd6) st_q <= out_ready_i ? 3'd0 : 3'd6;
    else st_q <= st_q + 3'd1;
  end
  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) begin
      // guard: weights (1, 0) on texel (0, 0) of the top level reproduce that texel exactly
      if (guard_i) begin  // (if/else: an unsigned '0 in a ?: would make >>> logical)
        x0_q <= '0;
        y0_q <= '0;
      end else begin
        x0_q <= su >>> sh;
        y0_q <= sv >>> sh;
      end
      fx_q    <= guard_i ? '0 : {1'b0, su[{1'b0, level_i} +: F]};
      fy_q    <= guard_i ? '0 : {1'b0, sv[{1'b0, level_i} +: F]};
      lev_q   <= guard_i ? (lw_i > lh_i ? lw_i : lh_i) : level_i;
      base_q  <= base_i;
      lw_q    <= lw_i;
      lh_q    <= lh_i;
      wrap_q  <= wrap_i;
    end
    if (st_q >= 3'd2 && st_q <= 3'd4) c_q[2'(st_q - 3'd2)] <= tex_data_i;
    if (st_q == 3'd5) rgba_o <= blend;
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o})
endmodule
