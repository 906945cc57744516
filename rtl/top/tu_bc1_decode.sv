// BC1 (DXT1) texel decode (docs/blocks/texture.md "BC1"): one 64-bit block and a texel's place
// in it (4 y + x) -> RGBA8 r | g << 8 | b << 16 | a << 24, exactly tex::bc1_decode: endpoints
// c0 = block[15:0], c1 = block[31:16] (RGB565) expanded by bit replication; the texel's 2-bit
// index at block[32 + 2 texel +: 2] picks c0, c1 or an interpolant:
//   c0 > c1: (2 c0 + c1 + 1) / 3, (c0 + 2 c1 + 1) / 3 (nearest integer), alpha 255
//   else:    (c0 + c1 + 1) >> 1, and transparent black (0, 0, 0, 0)
// Combinational; the divisions by 3 are n * 683 >> 11 (exact for n < 2048, here n <= 766).
module tu_bc1_decode (
  input  logic [63:0] block_i,
  input  logic [3:0]  texel_i,
  output logic [31:0] rgba_o
);
  logic [15:0] w0, w1;
  logic [23:0] e0, e1;  // {b, g, r} expanded endpoints
  assign w0 = block_i[15:0];
  assign w1 = block_i[31:16];
  assign e0 = {w0[4:0], w0[4:2], w0[10:5], w0[10:9], w0[15:11], w0[15:13]};
  assign e1 = {w1[4:0], w1[4:2], w1[10:5], w1[10:9], w1[15:11], w1[15:13]};

  logic [1:0] idx;
  assign idx = block_i[32 + {texel_i, 1'b0} +: 2];

  logic        four;  // 4-colour mode
  logic [23:0] p2, p3;
  assign four = w0 > w1;
  always_comb begin
    for (int c = 0; c < 3; c++) begin
      /* verilator lint_off UNUSEDSIGNAL */
      logic [9:0]  n2, n3, h;  // h[0]: the dropped half; n < 768
      logic [20:0] q2, q3;     // q[18:11] = floor(n / 3)
      /* verilator lint_on UNUSEDSIGNAL */
      n2 = {1'b0, e0[8*c +: 8], 1'b0} + {2'b0, e1[8*c +: 8]} + 10'd1;  // 2 c0 + c1 + 1
      n3 = {2'b0, e0[8*c +: 8]} + {1'b0, e1[8*c +: 8], 1'b0} + 10'd1;  // c0 + 2 c1 + 1
      h  = {2'b0, e0[8*c +: 8]} + {2'b0, e1[8*c +: 8]} + 10'd1;        // c0 + c1 + 1
      q2 = {11'b0, n2} * 21'd683;
      q3 = {11'b0, n3} * 21'd683;
      p2[8*c +: 8] = four ? q2[18:11] : h[8:1];
      p3[8*c +: 8] = q3[18:11];
    end
  end

  always_comb begin
    unique case (idx)
      2'd0: rgba_o = {8'hff, e0};
      2'd1: rgba_o = {8'hff, e1};
      2'd2: rgba_o = {8'hff, p2};
      default: rgba_o = four ? {8'hff, p3} : 32'h0;
    endcase
  end
endmodule
