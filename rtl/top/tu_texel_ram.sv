// Texel RAM model for simulation: Ports synchronous read ports (1-cycle latency, DataW-bit words:
// a texel in its storage format, decoded by tu_texel_decode; RGBA8 r | g << 8 | b << 16 | a << 24;
// port p at rd_*[p]) and one write port the testbench uses to load textures (every mip level of a
// power-of-two texture at its level base offset, tu_texel_addr). Not synthesised for area: the
// texture unit's texel port stands for a texture cache.
// Ports = 4 serves the multi-texel EWA walk's four bank ports (tu_ewa_walk_lanes): each port only
// ever reads texels of one parity class {y & 1, x & 1} (checked there), so the same traffic runs
// on four single-port banks holding a quarter of the texels each; this model keeps one array.
module tu_texel_ram #(
  parameter int AddrW = tu_formats_pkg::TexAddrW,
  parameter int Words = 1 << 17,
  parameter int Ports = 1,
  parameter int DataW = 32
) (
  input  logic                   clk_i,
  input  logic [Ports-1:0]       rd_en_i,
  input  logic [Ports*AddrW-1:0] rd_addr_i,
  output logic [Ports*DataW-1:0] rd_data_o,
  input  logic                   wr_en_i,
  input  logic [AddrW-1:0]       wr_addr_i,
  input  logic [DataW-1:0]       wr_data_i
);
  localparam int IdxW = $clog2(Words);
  logic [DataW-1:0] mem_q [Words];
  always_ff @(posedge clk_i) begin
    if (wr_en_i && wr_addr_i < AddrW'(Words)) mem_q[IdxW'(wr_addr_i)] <= wr_data_i;
  end
  for (genvar p = 0; p < Ports; p++) begin : g_port
    logic [AddrW-1:0] a;
    assign a = rd_addr_i[p*AddrW +: AddrW];
    // Out-of-range reads return 0 (the texture unit never issues one for a loaded texture).
    always_ff @(posedge clk_i) begin
      if (rd_en_i[p]) rd_data_o[p*DataW +: DataW] <= (a < AddrW'(Words)) ? mem_q[IdxW'(a)] : '0;
    end
  end
endmodule
