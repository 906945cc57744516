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
  // the texel read now (rx, ry) and the other column / row (ax, ay): x0 and x1 = x0 + 1 swap after
  // each read (x0, x1, x0, x1), y0 and y1 = y0 + 1 after the second (y0, y0, y1, y1); both hold x0
  // (y0) from acceptance, the + 1 is added in the first read's clock (off the acceptance path)
  logic signed [UW-1:0]                rx_q, ax_q, ry_q, ay_q;
  logic [F:0]                          fx_q, fy_q;
  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_q;
  // Level-L position s = u - 2^(F+L-1) (F + L fraction bits, exact as the C model's int64):
  // floor(s / 2^L) = floor(u / 2^L) - 2^(F-1) (the subtrahend is a multiple of 2^L), so
  //   x0 = (floor(u / 2^L) - 2^(F-1)) >> F,  fx = (floor(u / 2^L) - 2^(F-1)) mod 2^F
  // = the shifted u with its bit F-1 inverted: one shift, then a UW+1-bit decrement of the
  // bits from F-1 up (no wrap at u near -2^31).
  logic signed [UW-1:0] ul, vl;  // floor(u / 2^L), floor(v / 2^L)
  logic signed [UW:0]   sul, svl;  // floor(s / 2^L)
  assign ul  = $signed(u_i) >>> level_i;
  assign vl  = $signed(v_i) >>> level_i;
  assign sul = (UW+1)'(ul) - ((UW+1)'(1) << (F - 1));
  assign svl = (UW+1)'(vl) - ((UW+1)'(1) << (F - 1));
  assign in_ready_o  = st_q == 3'd0;
  assign out_valid_o = st_q == 3'd6;
  assign tex_req_o   = st_q >= 3'd1 && st_q <= 3'd4;

  logic signed [UW-1:0] x0_d, y0_d;  // the level-L texel of the pixel (guard: (0, 0))
  always_comb begin
    if (guard_i) begin  // (if/else: an unsigned '0 in a ?: would make >>> logical)
      x0_d = '0;
      y0_d = '0;
    end else begin
      x0_d = UW'(sul >>> F);
      y0_d = UW'(svl >>> F);
    end
  end

  // Texel address: the level part (tu_texel_level) from the pixel's ports, registered at
  // acceptance with x0, y0; per read only the wraps, the shift and one add
  // (tu_texel_addr_xy) lie between registers and tex_addr_o (no state decode: rx_q, ry_q).
  logic [3:0]                          wl_d, hl_d, wl_q, hl_q;
  logic [14:0]                         wm_d, hm_d, wm_q, hm_q;
  logic [tu_formats_pkg::TexAddrW-1:0] lb_d, bd_d, lb_q, bd_q;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i(guard_i ? (lw_i > lh_i ? lw_i : lh_i) : level_i),
    .wl_o(wl_d), .hl_o(hl_d), .wmask_o(wm_d), .hmask_o(hm_d), .lbase_o(lb_d), .border_o(bd_d));
  tu_texel_addr_xy #(.CoordW(UW)) u_addr (
    .wl_i(wl_q), .hl_i(hl_q), .wmask_i(wm_q), .hmask_i(hm_q), .lbase_i(lb_q), .border_i(bd_q),
    .wrap_i(wrap_q), .x_i(rx_q), .y_i(ry_q), .addr_o(tex_addr_o)
  );

  // Blend, one texel per read as it arrives: the same integers as
  //   (c00 (1-fx) + c10 fx)(1-fy) + (c01 (1-fx) + c11 fx) fy + 2^(2F-1)
  //   = c00 w00 + c10 w10 + c01 w01 + c11 w11 + 2^(2F-1),  w00 = gx gy, w10 = fx gy, w01 = gx fy,
  // w11 = fx fy (gx = 1 - fx, gy = 1 - fy; nothing is rounded before the sum). State 1 forms the
  // four weights and sets each channel's sum to the rounding term; states 2..4 add c w of the
  // texel that arrives (its weight in w_q[0], the next ones move down); state 5 adds the last and
  // registers the rounded channels: each clock one 8 x (2F+1)-bit multiply-add per channel.
  localparam int WtW = 2*F + 1;      // a weight <= 2^(2F)
  localparam int SW  = 8 + 2*F + 1;  // a sum < 2^(8+2F) + 2^(2F-1)
  logic [F:0]     gx, gy;  // 1 - fx, 1 - fy
  logic [WtW-1:0] w_q [4];
  logic [SW-1:0]  acc_q [4], acc_d [4];
  logic [31:0]    blend;
  assign gx = OneF - fx_q;
  assign gy = OneF - fy_q;
  always_comb begin
    for (int c = 0; c < 4; c++) begin
      acc_d[c] = acc_q[c] + SW'(tex_data_i[8*c +: 8]) * SW'(w_q[0]);
      blend[8*c +: 8] = acc_d[c][2*F +: 8];  // acc_d < 2^(8+2F): the bits above are 0
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
      rx_q    <= x0_d;
      ax_q    <= x0_d;
      ry_q    <= y0_d;
      ay_q    <= y0_d;
      fx_q    <= guard_i ? '0 : {1'b0, sul[F-1:0]};
      fy_q    <= guard_i ? '0 : {1'b0, svl[F-1:0]};
      wl_q    <= wl_d;
      hl_q    <= hl_d;
      wm_q    <= wm_d;
      hm_q    <= hm_d;
      lb_q    <= lb_d;
      bd_q    <= bd_d;
      wrap_q  <= wrap_i;
    end
    if (st_q == 3'd1) begin  // read 2 at (x0 + 1, y0); ay becomes y0 + 1
      rx_q <= ax_q + UW'(1);
      ax_q <= rx_q;
      ay_q <= ay_q + UW'(1);
    end
    if (st_q == 3'd2 || st_q == 3'd3) begin  // reads 3, 4: x swaps each time, y after the second
      rx_q <= ax_q;
      ax_q <= rx_q;
      if (st_q == 3'd2) begin
        ry_q <= ay_q;
        ay_q <= ry_q;
      end
    end
    if (st_q == 3'd1) begin
      w_q[0] <= WtW'(gx) * WtW'(gy);
      w_q[1] <= WtW'(fx_q) * WtW'(gy);
      w_q[2] <= WtW'(gx) * WtW'(fy_q);
      w_q[3] <= WtW'(fx_q) * WtW'(fy_q);
      for (int c = 0; c < 4; c++) acc_q[c] <= SW'(1 << (2*F - 1));
    end
    if (st_q >= 3'd2 && st_q <= 3'd4) begin
      for (int c = 0; c < 4; c++) acc_q[c] <= acc_d[c];
      for (int k = 0; k < 3; k++) w_q[k] <= w_q[k+1];
    end
    if (st_q == 3'd5) rgba_o <= blend;
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o})
endmodule
