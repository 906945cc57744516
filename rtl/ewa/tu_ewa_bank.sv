// Texel bank of a level-L texel (x, y) for the multi-texel EWA walk (combinational): the four
// banks hold the texels by the parity of their wrapped coordinates, bank = {y' & 1, x' & 1}
// (x', y' = tu_wrap_axis, the wrap tu_texel_addr applies); oob_o: a border texel (border wrap,
// outside the level), which reads the border word, not a bank texel.
// Two horizontally (or vertically) adjacent texels wrap to coordinates of different parity or to
// the same coordinate (repeat, mirror, clamp, mirror once; border inside the level), so the lanes
// of a 2 x 2 block never need two different texels of one bank (docs/blocks/ewa.md "Banks").
module tu_ewa_bank #(
  parameter int         CoordW = 32,
  parameter logic [4:0] Modes  = tu_unit_cfg_pkg::WrapModes
) (
  input  logic [3:0]                         lw_i,     // log2 width of level 0
  input  logic [3:0]                         lh_i,     // log2 height of level 0
  input  logic [2*tu_formats_pkg::WrapW-1:0] wrap_i,   // {v, u} wrap modes
  input  logic [3:0]                         level_i,
  input  logic signed [CoordW-1:0]           x_i,
  input  logic signed [CoordW-1:0]           y_i,
  output logic [1:0]                         bank_o,
  output logic                               oob_o
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int WW = tu_formats_pkg::WrapW;
  logic [3:0]    wl, hl;
  logic [AW-1:0] xw, yw, wmask, hmask;
  logic          xo, yo;
  assign wl    = (lw_i > level_i) ? lw_i - level_i : 4'd0;
  assign hl    = (lh_i > level_i) ? lh_i - level_i : 4'd0;
  assign wmask = (AW'(1) << wl) - AW'(1);
  assign hmask = (AW'(1) << hl) - AW'(1);
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_x (
    .x_i, .l_i(wl), .m_i(wmask), .mode_i(wrap_i[WW-1:0]), .idx_o(xw), .oob_o(xo));
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_y (
    .x_i(y_i), .l_i(hl), .m_i(hmask), .mode_i(wrap_i[2*WW-1:WW]), .idx_o(yw), .oob_o(yo));
  assign bank_o = {yw[0], xw[0]};
  assign oob_o  = xo || yo;
  logic unused;
  assign unused = ^{xw[AW-1:1], yw[AW-1:1]};
endmodule
