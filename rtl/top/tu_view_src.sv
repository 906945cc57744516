// Per-pixel stream model for simulation: words the shader hands the unit per pixel, in pixel
// order, on a valid/ready port: the tangent-space view of every pixel of a relief span (the
// texture unit's view port, DataW = 64) or the shade word of every output pixel (its shade port,
// DataW = ShadeWordW). The testbench writes the words during reset through a 32-bit port (part j
// of word i at address Stride i + j, Stride = the parts rounded up to a power of two); the model
// then offers them in order. Not synthesised for area.
`include "tu_assert.svh"
module tu_view_src #(
  parameter int AddrW = tu_formats_pkg::TexAddrW,
  parameter int Words = 1 << 16,
  parameter int DataW = 64  // a multiple of 32
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             wr_en_i,
  input  logic [AddrW-1:0] wr_addr_i,
  input  logic [31:0]      wr_data_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [DataW-1:0] out_data_o
);
  localparam int IdxW = $clog2(Words);
  localparam int Parts = DataW / 32;
  localparam int PartW = Parts > 1 ? $clog2(Parts) : 1;
  localparam int StrideLog2 = Parts > 1 ? $clog2(Parts) : 0;
  logic [DataW-1:0] mem_q [Words];
  logic [IdxW:0] count_q = '0;  // words written (loaded during reset, so not reset itself)
  logic [IdxW:0] rd_q;
  logic [AddrW-1:0] widx;
  logic [PartW-1:0] part;
  assign widx = wr_addr_i >> StrideLog2;
  assign part = wr_addr_i[PartW-1:0];
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
