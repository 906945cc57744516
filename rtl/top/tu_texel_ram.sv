// Texel RAM model for simulation: one synchronous read port (1-cycle latency, DataW-bit words: a
// texel in its storage format, decoded by tu_texel_decode; RGBA8 r | g << 8 | b << 16 | a << 24)
// and one write port the testbench uses to load textures (every mip level of a power-of-two
// texture at its level base offset, tu_texel_addr). Not synthesised for area: the texture unit's
// texel port stands for a texture cache.
module tu_texel_ram #(
  parameter int AddrW = tu_formats_pkg::TexAddrW,
  parameter int Words = 1 << 17,
  parameter int DataW = 32
) (
  input  logic             clk_i,
  input  logic             rd_en_i,
  input  logic [AddrW-1:0] rd_addr_i,
  output logic [DataW-1:0] rd_data_o,
  input  logic             wr_en_i,
  input  logic [AddrW-1:0] wr_addr_i,
  input  logic [DataW-1:0] wr_data_i
);
  localparam int IdxW = $clog2(Words);
  logic [DataW-1:0] mem_q [Words];
  always_ff @(posedge clk_i) begin
    if (wr_en_i && wr_addr_i < AddrW'(Words)) mem_q[IdxW'(wr_addr_i)] <= wr_data_i;
    // Out-of-range reads return 0 (the texture unit never issues one for a loaded texture).
    if (rd_en_i) rd_data_o <= (rd_addr_i < AddrW'(Words)) ? mem_q[IdxW'(rd_addr_i)] : '0;
  end
endmodule
