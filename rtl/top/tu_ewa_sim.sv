// Simulation top of the EWA engine (block "ewa"): tu_ewa with the texel RAM model attached; the
// testbench loads the texture through the RAM's write port before the pixel stream.
module tu_ewa_sim #(
  parameter int Words = 1 << 17,
  parameter int ClipVariant = 0,  // border weights' clip volume (the block's: mm_p1)
  parameter int Lanes = 1,        // tu_ewa Lanes (block ewa_k4: 4, with Setups 2)
  parameter int Setups = 1
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  ram_we_i,
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
  input  logic [2*tu_formats_pkg::WrapW-1:0]     wrap_i,
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic                                  clip_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  inside_o,
  output logic [4:0]                            flags_o
);
  logic [Lanes-1:0]                          tex_req;
  logic [Lanes*tu_formats_pkg::TexAddrW-1:0] tex_addr;
  logic [Lanes*32-1:0]                       tex_data;
  tu_ewa #(.HasClip(1), .ClipVariant(ClipVariant), .Lanes(Lanes), .Setups(Setups)) u_ewa (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .u_i, .v_i, .ae_i, .ce_i, .be_i, .lmaj_i, .lmin_i,
    .lod_i, .eflags_i, .guard_i(1'b0), .base_i, .lw_i, .lh_i, .wrap_i, .wsrc_i, .cap_i, .clip_i,
    .tex_req_o(tex_req), .tex_addr_o(tex_addr), .tex_data_i(tex_data),
    .out_valid_o, .out_ready_i, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o
  );
  tu_texel_ram #(.Words(Words), .Ports(Lanes)) u_ram (
    .clk_i, .rd_en_i(tex_req), .rd_addr_i(tex_addr), .rd_data_o(tex_data),
    .wr_en_i(ram_we_i), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
  );
endmodule
