// Texel address (combinational), the one addressing every engine uses: level-L texel (x, y), any
// integers, wrapped per axis like tex::wrap_index (wrap_i = {v, u} tu_formats_pkg::Wrap* codes):
//   repeat x & m, mirror x[wl] ? ~x & m : x & m, clamp to [0, m], border, mirror once
//   clamp(x < 0 ? ~x : x) to [0, m]   (m = 2^wl - 1, the level's size - 1)
// at base + levelbase(L) + y * width_L + x. Level L of a 2^lw x 2^lh texture is
// 2^max(0, lw-L) x 2^max(0, lh-L); levels are stored one after another from level 0, so
// levelbase(L) = sum_{k<L} 2^(max(0,lw-k) + max(0,lh-k)); the border colour is the word before
// level 0 (base - 1): a border texel (either axis outside the level in border mode) reads it, so
// no engine's data path changes (tex::texel_addr is the C model).
// Modes (default tu_unit_cfg_pkg::WrapModes; bit = Wrap code) leaves out the modes no texture uses;
// a code whose mode is left out is addressed as repeat (the plan's unit never receives one).
module tu_texel_addr #(
  parameter int         CoordW = 32,
  parameter logic [4:0] Modes  = tu_unit_cfg_pkg::WrapModes  // the engines keep the unit's
) (
  input  logic [tu_formats_pkg::TexAddrW-1:0]  base_i,     // texture base (word address)
  input  logic [3:0]                           lw_i,       // log2 width of level 0
  input  logic [3:0]                           lh_i,       // log2 height of level 0
  input  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_i,     // {v, u} wrap modes
  input  logic [3:0]                           level_i,
  input  logic signed [CoordW-1:0]             x_i,
  input  logic signed [CoordW-1:0]             y_i,
  output logic [tu_formats_pkg::TexAddrW-1:0]  addr_o
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int WW = tu_formats_pkg::WrapW;

  logic [3:0]    wl, hl;  // log2 size of level L
  logic [AW-1:0] lbase, xw, yw, wmask, hmask;
  logic          xo, yo;  // border texels
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_x (
    .x_i, .l_i(wl), .m_i(wmask), .mode_i(wrap_i[WW-1:0]), .idx_o(xw), .oob_o(xo));
  tu_wrap_axis #(.CoordW(CoordW), .Modes(Modes)) u_y (
    .x_i(y_i), .l_i(hl), .m_i(hmask), .mode_i(wrap_i[2*WW-1:WW]), .idx_o(yw), .oob_o(yo));
  assign wl    = (lw_i > level_i) ? lw_i - level_i : 4'd0;
  assign hl    = (lh_i > level_i) ? lh_i - level_i : 4'd0;
  assign wmask = (AW'(1) << wl) - AW'(1);
  assign hmask = (AW'(1) << hl) - AW'(1);
  always_comb begin
    lbase = '0;
    for (int k = 0; k < tu_formats_pkg::TexMaxLevels; k++) begin
      if (4'(k) < level_i) begin
        lbase = lbase + (AW'(1) << ((lw_i > 4'(k) ? 32'(lw_i) - 32'(k) : 0) +
                                    (lh_i > 4'(k) ? 32'(lh_i) - 32'(k) : 0)));
      end
    end
  end
  assign addr_o = (xo || yo) ? base_i - AW'(1) : base_i + lbase + (yw << wl) + xw;
endmodule
