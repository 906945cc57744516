// Per-level part of tu_texel_addr (combinational; an engine registers it when it accepts a pixel
// or selects a level, so that only tu_texel_addr_xy lies between its texel registers and the
// texel RAM address). Level L of a 2^lw x 2^lh texture is 2^wl x 2^hl, wl = max(0, lw - L),
// hl = max(0, lh - L); masks 2^wl - 1, 2^hl - 1; levels are stored one after another from
// level 0, so level L starts at base + levelbase(L),
//   levelbase(L) = sum_{k < min(L, TexMaxLevels)} 2^e_k,  e_k = max(0, lw - k) + max(0, lh - k),
// and the border colour is the word before level 0 (base - 1).
// e_k falls by 2 per level while both sides are > 1, then by 1, and is 0 from k = max(lw, lh) on:
// the terms with e_k > 0 are distinct powers of two (their sum is their OR, no carries) and the
// others are 1 each, so levelbase(L) = OR_{k < L, e_k > 0} 2^e_k + max(0, min(L, TexMaxLevels) -
// max(lw, lh)) (bits >= TexAddrW dropped, as the sum modulo 2^TexAddrW).
module tu_texel_level (
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,    // texture base (word address)
  input  logic [3:0]                          lw_i,      // log2 width of level 0
  input  logic [3:0]                          lh_i,      // log2 height of level 0
  input  logic [3:0]                          level_i,   // L
  output logic [3:0]                          wl_o,      // log2 width of level L
  output logic [3:0]                          hl_o,      // log2 height of level L
  output logic [14:0]                         wmask_o,   // 2^wl - 1 (wl <= 15: 15 bits)
  output logic [14:0]                         hmask_o,   // 2^hl - 1
  output logic [tu_formats_pkg::TexAddrW-1:0] lbase_o,   // base + levelbase(L)
  output logic [tu_formats_pkg::TexAddrW-1:0] border_o   // base - 1: the border colour's word
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int NL = tu_formats_pkg::TexMaxLevels;
  logic [AW-1:0] ones;  // OR of the distinct powers 2^e_k, e_k > 0
  logic [3:0]    top, lc, cnt;  // max(lw, lh); min(L, NL); the levels k in [top, lc)
  assign wl_o    = (lw_i > level_i) ? lw_i - level_i : 4'd0;
  assign hl_o    = (lh_i > level_i) ? lh_i - level_i : 4'd0;
  always_comb begin  // bit j of 2^wl - 1 is j < wl
    for (int j = 0; j < 15; j++) begin
      wmask_o[j] = 4'(j) < wl_o;
      hmask_o[j] = 4'(j) < hl_o;
    end
  end
  assign top     = lw_i > lh_i ? lw_i : lh_i;
  assign lc      = level_i > 4'(NL) ? 4'(NL) : level_i;
  assign cnt     = lc > top ? lc - top : 4'd0;
  always_comb begin
    ones = '0;
    for (int k = 0; k < NL; k++) begin
      logic [3:0] dw, dh;
      logic [4:0] e;
      dw = lw_i > 4'(k) ? lw_i - 4'(k) : 4'd0;
      dh = lh_i > 4'(k) ? lh_i - 4'(k) : 4'd0;
      e  = {1'b0, dw} + {1'b0, dh};
      if (4'(k) < level_i && e != 5'd0) ones = ones | (AW'(1) << e);
    end
  end
  assign lbase_o  = base_i + ones + AW'(cnt);
  assign border_o = base_i - AW'(1);
endmodule
