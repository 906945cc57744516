// One texel port of the texture unit (docs/blocks/texture.md "BC1 in the unit"): the engine's texel
// address on its way to the texel RAM (1-cycle read latency) and the stored word on its way back,
// decoded to RGBA8 for the format of the pixels in flight (fmt_i, srgb_i: tu_texture_unit fk_q).
//   HasBc1 = 0: the address passes unchanged, the word (TexelW bits) goes through tu_texel_decode.
//   HasBc1 = 1: the RAM word is 64 bits. A BC1 texture's address becomes its block's word
//     address (tu_bc1_addr, from the texture of the pixels in flight: base_i, lw_i, lh_i) and the
//     texel's place in the block is registered with the read (the RAM's enable, req_i), so that
//     tu_bc1_decode sees it with the block; the decoded RGBA8 then takes the sRGB table as an
//     rgba8 word would (tu_texel_decode, format rgba8). Other formats use the word's low TexelW
//     bits as before. No clock is added: both paths are combinational around the RAM's register.
module tu_texel_port #(
  // defaults: the full unit's (tu_unit_cfg_pkg)
  parameter int         TexelW  = tu_unit_cfg_pkg::TexelW,
  parameter logic [6:0] Formats = tu_unit_cfg_pkg::TexFormats,
  parameter int         HasSrgb = {31'b0, tu_unit_cfg_pkg::HasSrgb},
  parameter int         HasBc1  = {31'b0, tu_unit_cfg_pkg::HasBc1}  // RAM word 64 bits (a block), else TexelW
) (
  input  logic                                clk_i,
  input  logic                                req_i,    // the RAM's read enable
  input  logic [tu_formats_pkg::TexAddrW-1:0] addr_i,   // from the engine (tu_texel_addr)
  output logic [tu_formats_pkg::TexAddrW-1:0] addr_o,   // to the RAM
  input  logic [(HasBc1 != 0 ? 64 : TexelW)-1:0] word_i,   // from the RAM, the cycle after req_i
  input  logic [tu_formats_pkg::TexFmtW-1:0]  fmt_i,
  input  logic                                srgb_i,
  input  logic                                bc1_i,    // the pixels in flight's texture is BC1
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,   // ... its base and log2 sides (bc1_i)
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  output logic [31:0]                         rgba_o
);
  if (HasBc1 != 0) begin : g_bc1
    logic [tu_formats_pkg::TexAddrW-1:0] baddr;
    logic [3:0]  texel, texel_q;
    logic        bc1_q;
    logic [31:0] brgba, w;
    tu_bc1_addr u_addr (.addr_i, .base_i, .lw_i, .lh_i, .addr_o(baddr), .texel_o(texel));
    assign addr_o = bc1_i ? baddr : addr_i;
    always_ff @(posedge clk_i) begin  // with the RAM's read register: no reset (as its data)
      if (req_i) texel_q <= texel;
      if (req_i) bc1_q <= bc1_i;
    end
    tu_bc1_decode u_bc1 (.block_i(word_i), .texel_i(texel_q), .rgba_o(brgba));
    assign w = bc1_q ? brgba : 32'(word_i[TexelW-1:0]);
    tu_texel_decode #(.TexelW(32), .Formats(Formats), .HasSrgb(HasSrgb)) u_decode (
      .word_i(w), .fmt_i(bc1_q ? tu_formats_pkg::TexFmtRgba8 : fmt_i), .srgb_i, .rgba_o
    );
  end else begin : g_no_bc1
    assign addr_o = addr_i;
    tu_texel_decode #(.TexelW(TexelW), .Formats(Formats), .HasSrgb(HasSrgb)) u_decode (
      .word_i, .fmt_i, .srgb_i, .rgba_o
    );
    logic unused_bc1;
    assign unused_bc1 = ^{clk_i, req_i, bc1_i, base_i, lw_i, lh_i};
  end
endmodule
