// Per-texel part of tu_texel_addr (combinational): level-L texel (x, y), any integers, wrapped per
// axis (tu_wrap_axis, wrap_i = {v, u} tu_formats_pkg::Wrap* codes) into the level given by
// tu_texel_level's outputs, at lbase + y * 2^wl + x = lbase + ((y << wl) | x) (the wrapped
// x < 2^wl: the OR is the sum); a border texel (either axis outside the level in border mode)
// reads border_i (base - 1). What remains between an engine's texel registers and the texel RAM
// address: the wraps (masks, no carry chains), the shift by wl, one TexAddrW-bit add.
module tu_texel_addr_xy #(
  parameter int         CoordW = 32,
  parameter logic [4:0] Modes  = tu_unit_cfg_pkg::WrapModes
) (
  input  logic [3:0]                           wl_i,      // tu_texel_level outputs
  input  logic [3:0]                           hl_i,
  input  logic [14:0]                          wmask_i,   // 2^wl - 1
  input  logic [14:0]                          hmask_i,   // 2^hl - 1
  input  logic [tu_formats_pkg::TexAddrW-1:0]  lbase_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  border_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_i,    // {v, u} wrap modes
  input  logic signed [CoordW-1:0]             x_i,
  input  logic signed [CoordW-1:0]             y_i,
  output logic [tu_formats_pkg::TexAddrW-1:0]  addr_o
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int WW = tu_formats_pkg::WrapW;
  logic [AW-1:0] xw, yw;
  logic          xo, yo;  // border texels
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_x (
    .x_i, .l_i(wl_i), .m_i(AW'(wmask_i)), .mode_i(wrap_i[WW-1:0]), .idx_o(xw), .oob_o(xo));
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_y (
    .x_i(y_i), .l_i(hl_i), .m_i(AW'(hmask_i)), .mode_i(wrap_i[2*WW-1:WW]), .idx_o(yw), .oob_o(yo));
  assign addr_o = (xo || yo) ? border_i : lbase_i + ((yw << wl_i) | xw);
endmodule
