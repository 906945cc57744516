// Simulation top of the visibility engine (block "afvis"): tu_afvis with the texel RAM and the
// depth RAM models attached; the testbench loads the texture (ram_sel_i 0) and the depth map
// (ram_sel_i 1, one code per word) through the write port before the pixel stream.
module tu_afvis_sim #(
  parameter int Words = 1 << 17,
  parameter int DepthWords = 1 << 16
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  ram_we_i,
  input  logic                                  ram_sel_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   ram_waddr_i,
  input  logic [31:0]                           ram_wdata_i,
  input  logic                                  in_valid_i,
  output logic                                  in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ae_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   ce_i,
  input  logic [tu_formats_pkg::EllCoefW-1:0]   be_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmaj_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]    lmin_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lod_i,
  input  logic [4:0]                            eflags_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   base_i,
  input  logic [3:0]                            lw_i,
  input  logic [3:0]                            lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]    wrap_i,
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vz_i,
  input  logic [tu_formats_pkg::PomSW-1:0]      scale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   hbase_i,
  input  logic [3:0]                            hlw_i,
  input  logic [3:0]                            hlh_i,
  input  logic [7:0]                            dmin_i,
  input  logic [7:0]                            bias_i,
  input  logic                                  rule_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  inside_o,
  output logic [4:0]                            flags_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  kept_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  traced_o,
  output logic [23:0]                           steps_o
);
  logic                                tex_req, d_req;
  logic [tu_formats_pkg::TexAddrW-1:0] tex_addr, d_addr;
  logic [31:0]                         tex_data, d_word;
  tu_afvis u_afvis (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .u_i, .v_i, .ae_i, .ce_i, .be_i, .lmaj_i, .lmin_i,
    .lod_i, .eflags_i, .base_i, .lw_i, .lh_i, .wrap_i, .wsrc_i, .cap_i, .vx_i, .vy_i, .vz_i, .scale_i,
    .hbase_i, .hlw_i, .hlh_i, .dmin_i, .bias_i, .rule_i,
    .tex_req_o(tex_req), .tex_addr_o(tex_addr), .tex_data_i(tex_data),
    .d_req_o(d_req), .d_addr_o(d_addr), .d_data_i(d_word[7:0]),
    .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o,
    .kept_o, .traced_o, .steps_o
  );
  tu_texel_ram #(.Words(Words)) u_ram (
    .clk_i, .rd_en_i(tex_req), .rd_addr_i(tex_addr), .rd_data_o(tex_data),
    .wr_en_i(ram_we_i && !ram_sel_i), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
  );
  tu_texel_ram #(.Words(DepthWords)) u_depth (
    .clk_i, .rd_en_i(d_req), .rd_addr_i(d_addr), .rd_data_o(d_word),
    .wr_en_i(ram_we_i && ram_sel_i), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
  );
  logic unused;
  assign unused = ^d_word[31:8];
endmodule
