// BC1 block address (combinational, docs/blocks/texture.md "BC1 in the unit"): a texel word address
// as tu_texel_addr forms it for a BC1 texture (base + levelbase(L) + y * width_L + x, or base - 1
// for the border colour) -> the texel RAM word (64 bits: one BC1 block) holding that texel, and the
// texel's place in the block (4 (y & 3) + (x & 3), tu_bc1_decode's texel_i). The RAM holds a BC1
// texture as its border block at base - 1, then the blocks of each level one after another from
// level 0, row-major (tex::bc1_texel: max(1, width_L / 4) blocks per row; a level narrower or lower
// than 4 texels is one block), i.e. the C model's t.words two 32-bit words per block.
// The level of the address: the number of levels k >= 1 with offset >= levelbase(k) (the layout
// of tu_texel_addr); then x = offset_L & (width_L - 1), y = offset_L >> log2 width_L, and
// block = blockbase(L) + (y >> 2) * max(1, width_L / 4) + (x >> 2).
// No engine changes: the engines still address texels; the unit translates the address on its
// way to the RAM (one instance per texel port) and delays the texel's place with the read.
module tu_bc1_addr (
  input  logic [tu_formats_pkg::TexAddrW-1:0] addr_i,   // texel word address (tu_texel_addr)
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,   // the texture's base (level 0)
  input  logic [3:0]                          lw_i,     // log2 width of level 0
  input  logic [3:0]                          lh_i,     // log2 height of level 0
  output logic [tu_formats_pkg::TexAddrW-1:0] addr_o,   // block word address
  output logic [3:0]                          texel_o   // 4 (y & 3) + (x & 3)
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int NL = tu_formats_pkg::TexMaxLevels;

  logic [AW-1:0] off;
  assign off = addr_i - base_i;

  // Level L and the texel / block bases of levels 0..L.
  logic [AW-1:0] lbase, bbase;
  logic [3:0]    lvl;
  always_comb begin
    logic [AW-1:0] lb, bb;  // bases of level k
    lb    = '0;
    bb    = '0;
    lbase = '0;
    bbase = '0;
    lvl   = '0;
    for (int k = 0; k < NL; k++) begin
      logic [4:0] wk, hk;  // log2 size of level k
      wk = lw_i > 4'(k) ? 5'(lw_i) - 5'(k) : 5'd0;
      hk = lh_i > 4'(k) ? 5'(lh_i) - 5'(k) : 5'd0;
      if (k == 0 || off >= lb) begin
        lbase = lb;
        bbase = bb;
        lvl   = 4'(k);
      end
      lb = lb + (AW'(1) << (wk + hk));
      bb = bb + (AW'(1) << ((wk > 5'd2 ? wk - 5'd2 : 5'd0) + (hk > 5'd2 ? hk - 5'd2 : 5'd0)));
    end
  end

  logic [3:0]    wl;     // log2 width of level L
  logic [AW-1:0] o, x, y, blk;
  assign wl  = lw_i > lvl ? lw_i - lvl : 4'd0;
  assign o   = off - lbase;
  assign x   = o & ((AW'(1) << wl) - AW'(1));
  assign y   = o >> wl;
  assign blk = ((y >> 2) << (wl > 4'd2 ? wl - 4'd2 : 4'd0)) + (x >> 2);
  // the border colour (base - 1): its block, texel 0 (a block of one colour)
  logic border;
  assign border  = off == {AW{1'b1}};
  assign addr_o  = border ? addr_i : base_i + bbase + blk;
  assign texel_o = border ? 4'd0 : {y[1:0], x[1:0]};
endmodule
