// Texel address (combinational), the one addressing every engine uses: level-L texel (x, y), any
// integers, wrapped per axis like tex::wrap_index (wrap_i = {v, u} tu_formats_pkg::Wrap* codes):
//   repeat x & m, mirror x[wl] ? ~x & m : x & m, clamp to [0, m], border, mirror once
//   clamp(x < 0 ? ~x : x) to [0, m]   (m = 2^wl - 1, the level's size - 1)
// at base + levelbase(L) + y * width_L + x. Level L of a 2^lw x 2^lh texture is
// 2^max(0, lw-L) x 2^max(0, lh-L); levels are stored one after another from level 0, so
// levelbase(L) = sum_{k<L} 2^(max(0,lw-k) + max(0,lh-k)); the border colour is the word before
// level 0 (base - 1): a border texel (either axis outside the level in border mode) reads it, so
// no engine's data path changes (tex::texel_addr is the C model).
// Two parts: tu_texel_level (per level: sizes, masks, base + levelbase(L), base - 1) and
// tu_texel_addr_xy (per texel: wraps, shift, one add). The streaming engines (tu_nearest,
// tu_bilinear, tu_ewa_walk, ...) register the first part when they latch a pixel and use the
// second directly; this module chains them for the engines whose level changes per texel and for
// the block's co-simulation (tu_texel_addr_sim).
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
  logic [3:0]    wl, hl;
  logic [14:0]   wmask, hmask;
  logic [AW-1:0] lbase, border;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i, .wl_o(wl), .hl_o(hl), .wmask_o(wmask), .hmask_o(hmask),
    .lbase_o(lbase), .border_o(border));
  tu_texel_addr_xy #(.CoordW(CoordW), .Modes(Modes)) u_xy (
    .wl_i(wl), .hl_i(hl), .wmask_i(wmask), .hmask_i(hmask), .lbase_i(lbase), .border_i(border),
    .wrap_i, .x_i, .y_i, .addr_o);
endmodule
