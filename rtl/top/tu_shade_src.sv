// Per-pixel shade stream model for simulation: the shader's shading inputs of every output pixel
// (brdf::shade::pack: {on, N, L, H, n, c_cut, ks*lc, lc, ambient}), in pixel order (the texture
// unit's shade port). The testbench writes the words during reset through a 32-bit port (part j
// of word i at address 16 i + j); the model then offers them in order on a valid/ready port. Not
// synthesised for area.
`include "tu_assert.svh"
module tu_shade_src #(
  parameter int AddrW = tu_formats_pkg::TexAddrW,
  parameter int Words = 1 << 16
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  wr_en_i,
  input  logic [AddrW-1:0]                      wr_addr_i,
  input  logic [31:0]                           wr_data_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [tu_formats_pkg::ShadeWordW-1:0] out_data_o
);
  localparam int IdxW = $clog2(Words);
  localparam int Parts = tu_formats_pkg::ShadeWordW / 32;
  logic [tu_formats_pkg::ShadeWordW-1:0] mem_q [Words];
  logic [IdxW:0] count_q = '0;  // words written (loaded during reset, so not reset itself)
  logic [IdxW:0] rd_q;
  logic [AddrW-1:0] widx;
  logic [3:0]       part;
  assign widx = wr_addr_i >> 4;
  assign part = wr_addr_i[3:0];
  always_ff @(posedge clk_i) begin
    if (wr_en_i && widx < AddrW'(Words) && 32'(part) < Parts) begin
      mem_q[IdxW'(widx)][32 * part +: 32] <= wr_data_i;
      if ((IdxW + 1)'(widx) >= count_q) count_q <= (IdxW + 1)'(widx) + 1'b1;
    end
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rd_q <= '0;
    else if (out_valid_o && out_ready_i) rd_q <= rd_q + 1'b1;
  end
  assign out_valid_o = rd_q < count_q;
  assign out_data_o  = mem_q[IdxW'(rd_q)];

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {out_data_o})
endmodule
