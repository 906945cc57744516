// Texel decode stage (docs/blocks/texture.md "Texel formats"): one stored texel-RAM word in its
// storage format (tu_formats_pkg::TexFmt* codes) -> the RGBA8 word r | g << 8 | b << 16 | a << 24
// every filter engine blends, exactly tex::decode_stored: n-bit fields expanded to 8 bits by bit
// replication, then with srgb_i the colour channels through the sRGB decode table (tu_srgb_rom,
// generated from tex::srgb_decode_table; alpha is linear). Combinational: it sits between the
// texel port (1-cycle read latency) and the engines, so their timing is unchanged.
// Formats (bit = TexFmt code) keeps a format's decode; a code whose format is left out decodes as
// rgba8 (the word as it is). HasSrgb = 0 leaves out the three tables (srgb_i is then ignored).
module tu_texel_decode #(
  parameter int            TexelW  = 32,     // stored bits per RAM word (the widest format kept, <= 32)
  parameter logic [6:0]    Formats = 7'h7f,  // bit = TexFmt code
  parameter int            HasSrgb = 1
) (
  input  logic [TexelW-1:0]                  word_i,
  input  logic [tu_formats_pkg::TexFmtW-1:0] fmt_i,
  input  logic                               srgb_i,
  output logic [31:0]                        rgba_o
);
  // The word zero-extended to 32 bits: every format's fields lie in its low bits.
  logic [31:0] w;
  assign w = 32'(word_i);

  logic [7:0] r, g, b, a;  // after bit replication
  always_comb begin
    {a, b, g, r} = w;  // rgba8, and every code left out
    unique case (fmt_i)
      tu_formats_pkg::TexFmtRgb565:
        if (Formats[1]) {a, b, g, r} = {8'hff, w[4:0], w[4:2], w[10:5], w[10:9], w[15:11], w[15:13]};
      tu_formats_pkg::TexFmtRgba5551:
        if (Formats[2]) {a, b, g, r} = {{8{w[0]}}, w[5:1], w[5:3], w[10:6], w[10:8], w[15:11], w[15:13]};
      tu_formats_pkg::TexFmtRgba4444:
        if (Formats[3]) {a, b, g, r} = {w[3:0], w[3:0], w[7:4], w[7:4], w[11:8], w[11:8], w[15:12], w[15:12]};
      tu_formats_pkg::TexFmtL8:
        if (Formats[4]) {a, b, g, r} = {8'hff, w[7:0], w[7:0], w[7:0]};
      tu_formats_pkg::TexFmtLa8:
        if (Formats[5]) {a, b, g, r} = {w[15:8], w[7:0], w[7:0], w[7:0]};
      tu_formats_pkg::TexFmtA8:
        if (Formats[6]) {a, b, g, r} = {w[7:0], 24'h0};
      default: ;
    endcase
  end

  if (HasSrgb != 0) begin : g_srgb
    logic [7:0] lr, lg, lb;
    tu_srgb_rom u_rom_r (.code_i(r), .lin_o(lr));
    tu_srgb_rom u_rom_g (.code_i(g), .lin_o(lg));
    tu_srgb_rom u_rom_b (.code_i(b), .lin_o(lb));
    assign rgba_o = srgb_i ? {a, lb, lg, lr} : {a, b, g, r};
  end else begin : g_no_srgb
    assign rgba_o = {a, b, g, r};
    logic unused_srgb;
    assign unused_srgb = srgb_i;
  end
endmodule
