// Simulation top of the relief stage (co-simulation only, not synthesised): tu_relief_stage with
// its depth RAM (tu_texel_ram, depth in the low 8 bits of a word) loaded through ram_* during
// reset, and the view stream offered beside the pixel: the harness row carries the pixel's view
// word, view_valid_i follows in_valid_i for relief pixels unless view_bubble_i (random) holds it
// back, so the stage sees pixels waiting for their view word.
module tu_relief_stage_sim #(
  parameter int SideW = 20,
  parameter int Words = 1 << 21  // depth RAM words (the default scene with its distance map: 1,114,112)
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  v_i,
  input  logic [3:0]                           lw_i,
  input  logic [3:0]                           lh_i,
  input  logic                                 rel_i,
  input  logic                                 guard_i,
  input  logic                                 adaptive_i,
  input  logic                                 iter_i,
  input  logic                                 dm_i,
  input  logic [tu_formats_pkg::DmLayersW-1:0] dlayers_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  dbase_i,
  input  logic [tu_formats_pkg::PomNW-1:0]     layers_i,
  input  logic [tu_formats_pkg::PomSW-1:0]     scale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  hbase_i,
  input  logic [3:0]                           hlw_i,
  input  logic [3:0]                           hlh_i,
  input  logic [SideW-1:0]                     side_i,
  input  logic                                 view_bubble_i,
  input  logic                                 view_ok_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]    vz_i,
  input  logic [tu_formats_pkg::PomCW-1:0]     vc_i,
  input  logic                                 ram_we_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]  ram_waddr_i,
  input  logic [31:0]                          ram_wdata_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [tu_formats_pkg::PerspUvW-1:0]  u_o,
  output logic [tu_formats_pkg::PerspUvW-1:0]  v_o,
  output logic [tu_formats_pkg::PomNW-1:0]     n_o,
  output logic [tu_formats_pkg::PomNW-1:0]     steps_o,
  output logic [2:0]                           flags_o,
  output logic [SideW-1:0]                     side_o
);
  logic                                d_req;
  logic [tu_formats_pkg::TexAddrW-1:0] d_addr;
  logic [31:0]                         d_word;
  logic                                view_valid, view_ready;
  assign view_valid = in_valid_i && rel_i && !view_bubble_i;

  tu_relief_stage #(.SideW(SideW)) u_stage (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .u_i, .v_i, .lw_i, .lh_i, .rel_i, .guard_i,
    .adaptive_i, .iter_i, .dm_i, .dlayers_i, .dbase_i, .layers_i, .scale_i, .hbase_i, .hlw_i, .hlh_i, .side_i,
    .view_valid_i(view_valid), .view_ready_o(view_ready), .view_ok_i, .vx_i, .vy_i, .vz_i, .vc_i,
    .d_req_o(d_req), .d_addr_o(d_addr), .d_data_i(d_word[7:0]),
    .out_valid_o, .out_ready_i, .u_o, .v_o, .n_o, .steps_o, .flags_o, .side_o
  );
  tu_texel_ram #(.Words(Words)) u_ram (
    .clk_i, .rd_en_i(d_req), .rd_addr_i(d_addr), .rd_data_o(d_word),
    .wr_en_i(ram_we_i), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
  );

  // The view word is accepted with its pixel (checked by the scoreboard through in_ready_o).
  logic unused;
  assign unused = ^{view_ready, d_word[31:8]};
endmodule
