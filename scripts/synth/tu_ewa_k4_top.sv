// Synthesis wrapper for scripts/yosys_ewa_k4.sh: tu_ewa with Lanes = 4, Setups = 3 (the corridor
// unit's K = 4 engine; Yosys 0.23's chparam / hierarchy -chparam fail on tu_ewa). Not in the manifest.
module tu_ewa_k4_top (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
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
  input  logic                                  guard_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   base_i,
  input  logic [3:0]                            lw_i,
  input  logic [3:0]                            lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]    wrap_i,
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic                                  clip_i,
  output logic [3:0]                            tex_req_o,
  output logic [4*tu_formats_pkg::TexAddrW-1:0] tex_addr_o,
  input  logic [4*32-1:0]                       tex_data_i,
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]  inside_o,
  output logic [4:0]                            flags_o
);
  tu_ewa #(.Lanes(4), .Setups(3)) u_ewa (.*);
endmodule
