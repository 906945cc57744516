// Simulation top of the texture unit: tu_texture_unit with the texel RAM, the depth-map RAM and
// the per-pixel view and shade stream models attached; the testbench loads every texture, every
// relief depth map, the view words and the shade words through the write port (ram_sel_i:
// 0 texels, 1 depth, 2 views, 3 shade words) during reset, before the spans. With HasBc1 the texel
// RAM's words are 64 bits (ram_wdata_hi_i the upper half: a BC1 block; other formats leave it 0).
module tu_texture_unit_sim #(
  parameter int HasEwa      = {31'b0, tu_unit_cfg_pkg::HasEwa},
  parameter int HasBilinear = {31'b0, tu_unit_cfg_pkg::HasBilinear},
  parameter int HasTriFilter = {31'b0, tu_unit_cfg_pkg::HasTriFilter},
  parameter int HasNearest = {31'b0, tu_unit_cfg_pkg::HasNearest},
  parameter int HasFeline  = {31'b0, tu_unit_cfg_pkg::HasFeline},
  parameter int HasRelief   = {31'b0, tu_unit_cfg_pkg::HasRelief},
  parameter int HasShading  = {31'b0, tu_unit_cfg_pkg::HasShading},
  parameter int HasPom      = {31'b0, tu_unit_cfg_pkg::HasPom},
  parameter int HasIterParallax = {31'b0, tu_unit_cfg_pkg::HasIterParallax},
  parameter int HasDistanceMap = {31'b0, tu_unit_cfg_pkg::HasDistanceMap},
  parameter int EllRecurrence = {31'b0, tu_unit_cfg_pkg::EllRecurrence},
  parameter int HasEwaClip     = {31'b0, tu_unit_cfg_pkg::HasEwaClip},
  parameter int EwaClipVariant = tu_unit_cfg_pkg::EwaClipVariant,
  parameter int HasNoise      = {31'b0, tu_unit_cfg_pkg::HasNoise},
  parameter int NoiseDims     = tu_unit_cfg_pkg::NoiseDims,
  parameter int NoiseCores    = tu_unit_cfg_pkg::NoiseCores,
  parameter int HasWater      = {31'b0, tu_unit_cfg_pkg::HasWater},
  parameter int NoiseScheme   = tu_unit_cfg_pkg::NoiseScheme,
  parameter int HasAfvis      = {31'b0, tu_unit_cfg_pkg::HasAfvis},
  parameter int EwaLanes      = 1,  // tu_texture_unit EwaLanes / EwaSetups (4 / 2 .. 4: the texel RAM has 4 ports)
  parameter int EwaSetups     = 1,
  parameter logic [6:0] TexFormats = tu_unit_cfg_pkg::TexFormats,
  parameter int HasSrgb       = {31'b0, tu_unit_cfg_pkg::HasSrgb},
  parameter int TexelW        = tu_unit_cfg_pkg::TexelW,  // the texel RAM's word (stored texel)
  parameter int HasBc1        = {31'b0, tu_unit_cfg_pkg::HasBc1},  // BC1 blocks: 64-bit RAM words
  parameter int Words  = 1 << tu_formats_pkg::TexRamLog2Words,
  // the depth RAM also holds the distance maps (the default scene's wall: 1,114,112 words)
  parameter int DepthWords = 2 * Words
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  ram_we_i,
  input  logic [1:0]                            ram_sel_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   ram_waddr_i,
  input  logic [31:0]                           ram_wdata_i,
  input  logic [31:0]                           ram_wdata_hi_i,  // texel RAM bits 63:32 (HasBc1)
  // span input
  input  logic                                  in_valid_i,
  output logic                                  in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]    a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]    b_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]    c_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]    d_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]    e_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]    f_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]    g_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]    h_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]    i_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]   x0_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]   x1_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]   y_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     kux_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     kvx_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     kuy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     kvy_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     m_i,
  input  logic [tu_formats_pkg::EllNxW-1:0]     nn_i,
  input  logic [tu_formats_pkg::EllDetW-1:0]    dm_i,
  input  logic [tu_formats_pkg::EllDetExpW-1:0] dexp_i,
  input  logic [tu_formats_pkg::EllAnisoW-1:0]  laniso_i,
  input  logic [tu_formats_pkg::EllMaxLodW-1:0] maxlod_i,
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] lbias_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lminlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lmaxlod_i,
  input  logic [3:0]                            lbase_i,
  input  logic [3:0]                            ltop_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   tbase_i,
  input  logic [3:0]                            tlw_i,
  input  logic [3:0]                            tlh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]     twrap_i,
  input  logic [tu_formats_pkg::TexFmtW-1:0]    tfmt_i,
  input  logic                                  tsrgb_i,
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic [tu_formats_pkg::EngineW-1:0]    filt_i,
  input  logic [tu_formats_pkg::FelProbeW-1:0]  fnmax_i,
  input  logic                                  clip_i,
  input  logic                                  rel_i,
  input  logic                                  radapt_i,
  input  logic                                  riter_i,
  input  logic [tu_formats_pkg::PomNW-1:0]      rlayers_i,
  input  logic [tu_formats_pkg::PomSW-1:0]      rscale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   hbase_i,
  input  logic [3:0]                            hlw_i,
  input  logic [3:0]                            hlh_i,
  input  logic                                  rdm_i,
  input  logic [tu_formats_pkg::DmLayersW-1:0]  dlayers_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   dbase_i,
  input  logic                                  afv_i,
  input  logic [7:0]                            admin_i,
  input  logic [7:0]                            abias_i,
  input  logic                                  arule_i,
  input  logic [tu_formats_pkg::ProcW-1:0]      proc_i,
  // pixel output
  output logic                                  out_valid_o,
  input  logic                                  out_ready_i,
  output logic [tu_formats_pkg::PerspXyW-1:0]   x_o,
  output logic [tu_formats_pkg::PerspXyW-1:0]   y_o,
  output logic [31:0]                           rgba_o,
  output logic [3:0]                            level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0] visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0] inside_o,
  output logic [4:0]                            flags_o,   // filter flags (tu_ewa, ewa::fx::Flag)
  output logic [4:0]                            eflags_o,  // B2 flags
  output logic [1:0]                            pflags_o,  // B1: {span set-up overflow, guard}
  output logic [tu_formats_pkg::PomNW-1:0]      rn_o,      // relief layers used
  output logic [tu_formats_pkg::PomNW-1:0]      rsteps_o,  // relief march steps or iterations
  output logic [2:0]                            rflags_o   // relief::ReliefFlag bits
);
  localparam int KP = EwaLanes > 1 ? EwaLanes - 1 : 1;  // bank ports 1..3
  localparam int TPW = HasBc1 != 0 ? 64 : TexelW;        // texel RAM word
  logic [63:0] ram_wdata64;
  assign ram_wdata64 = {ram_wdata_hi_i, ram_wdata_i};
  logic                                   tex_req;
  logic [tu_formats_pkg::TexAddrW-1:0]    tex_addr;
  logic [TPW-1:0]                         tex_data;
  logic [KP-1:0]                          texk_req;
  logic [KP*tu_formats_pkg::TexAddrW-1:0] texk_addr;
  logic [KP*TPW-1:0]                      texk_data;
  localparam int VzW = tu_formats_pkg::PomVzW;
  logic                                view_valid, view_ready, d_req;
  logic [63:0]                         view;
  logic [tu_formats_pkg::TexAddrW-1:0] d_addr;
  logic [31:0]                         d_word;
  logic                                a_req;
  logic [tu_formats_pkg::TexAddrW-1:0] a_addr;
  logic [31:0]                         a_word;
  logic                                 shade_valid, shade_ready;
  logic [tu_formats_pkg::ShadeWordW-1:0] shade;
  tu_texture_unit #(.HasEwa(HasEwa), .HasBilinear(HasBilinear), .HasTriFilter(HasTriFilter), .HasNearest(HasNearest),
                    .HasFeline(HasFeline), .HasRelief(HasRelief), .HasShading(HasShading),
                    .HasPom(HasPom), .HasIterParallax(HasIterParallax), .HasDistanceMap(HasDistanceMap),
                    .EllRecurrence(EllRecurrence),
                    .HasEwaClip(HasEwaClip), .EwaClipVariant(EwaClipVariant),
                    .HasNoise(HasNoise), .NoiseDims(NoiseDims), .NoiseCores(NoiseCores), .HasWater(HasWater),
                    .NoiseScheme(NoiseScheme), .HasAfvis(HasAfvis), .EwaLanes(EwaLanes), .EwaSetups(EwaSetups),
                    .TexFormats(TexFormats), .HasSrgb(HasSrgb), .TexelW(TexelW), .HasBc1(HasBc1)) u_tu (
    .clk_i, .rst_ni,
    .in_valid_i, .in_ready_o, .a_i, .b_i, .c_i, .d_i, .e_i, .f_i,
    .g_i, .h_i, .i_i, .x0_i, .x1_i, .y_i, .kux_i, .kvx_i,
    .kuy_i, .kvy_i, .m_i, .nn_i, .dm_i, .dexp_i, .laniso_i, .maxlod_i, .lbias_i, .lminlod_i, .lmaxlod_i, .lbase_i, .ltop_i,
    .tbase_i, .tlw_i, .tlh_i, .twrap_i, .tfmt_i, .tsrgb_i, .wsrc_i, .cap_i, .filt_i, .fnmax_i, .clip_i,
    .rel_i, .radapt_i, .riter_i, .rlayers_i, .rscale_i, .hbase_i, .hlw_i, .hlh_i, .rdm_i, .dlayers_i, .dbase_i,
    .afv_i, .admin_i, .abias_i, .arule_i, .proc_i,
    .view_valid_i(view_valid), .view_ready_o(view_ready), .view_ok_i(view[3 * VzW + tu_formats_pkg::PomCW]),
    .vx_i(view[2 * VzW + tu_formats_pkg::PomCW +: VzW]), .vy_i(view[VzW + tu_formats_pkg::PomCW +: VzW]),
    .vz_i(view[tu_formats_pkg::PomCW +: VzW]), .vc_i(view[0 +: tu_formats_pkg::PomCW]),
    .d_req_o(d_req), .d_addr_o(d_addr), .d_data_i(d_word[7:0]),
    .a_req_o(a_req), .a_addr_o(a_addr), .a_data_i(a_word[7:0]),
    .shade_valid_i(shade_valid), .shade_ready_o(shade_ready), .shade_i(shade),
    .out_valid_o, .out_ready_i,
    .x_o, .y_o, .rgba_o, .level_o, .visited_o, .inside_o, .flags_o, .eflags_o,
    .pflags_o, .rn_o, .rsteps_o, .rflags_o,
    .tex_req_o(tex_req), .tex_addr_o(tex_addr), .tex_data_i(tex_data),
    .texk_req_o(texk_req), .texk_addr_o(texk_addr), .texk_data_i(texk_data)
  );
  if (EwaLanes > 1) begin : g_banked_ram
    tu_texel_ram #(.Words(Words), .Ports(EwaLanes), .DataW(TPW)) u_ram (
      .clk_i, .rd_en_i({texk_req, tex_req}), .rd_addr_i({texk_addr, tex_addr}), .rd_data_o({texk_data, tex_data}),
      .wr_en_i(ram_we_i && ram_sel_i == 2'd0), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata64[TPW-1:0])
    );
  end else begin : g_ram
    tu_texel_ram #(.Words(Words), .DataW(TPW)) u_ram (
      .clk_i, .rd_en_i(tex_req), .rd_addr_i(tex_addr), .rd_data_o(tex_data),
      .wr_en_i(ram_we_i && ram_sel_i == 2'd0), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata64[TPW-1:0])
    );
    assign texk_data = '0;
    logic unused_texk;
    assign unused_texk = ^{texk_req, texk_addr};
  end
  // view word: {ok, vx, vy, vz, c} from bit 3 VzW + PomCW down
  tu_texel_ram #(.Words(DepthWords)) u_depth (
    .clk_i, .rd_en_i(d_req), .rd_addr_i(d_addr), .rd_data_o(d_word),
    .wr_en_i(ram_we_i && ram_sel_i == 2'd1), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
  );
  // the visibility engine's read port on the depth RAM: a copy written with it (a dual-port RAM)
  if (HasAfvis != 0) begin : g_depth2
    tu_texel_ram #(.Words(DepthWords)) u_depth2 (
      .clk_i, .rd_en_i(a_req), .rd_addr_i(a_addr), .rd_data_o(a_word),
      .wr_en_i(ram_we_i && ram_sel_i == 2'd1), .wr_addr_i(ram_waddr_i), .wr_data_i(ram_wdata_i)
    );
  end else begin : g_no_depth2
    assign a_word = '0;
    logic unused_a;
    assign unused_a = ^{a_req, a_addr};
  end
  tu_view_src #(.Words(Words)) u_views (
    .clk_i, .rst_ni, .wr_en_i(ram_we_i && ram_sel_i == 2'd2), .wr_addr_i(ram_waddr_i),
    .wr_data_i(ram_wdata_i), .out_valid_o(view_valid), .out_ready_i(view_ready), .out_data_o(view)
  );
  tu_view_src #(.Words(1 << 16), .DataW(tu_formats_pkg::ShadeWordW)) u_shades (
    .clk_i, .rst_ni, .wr_en_i(ram_we_i && ram_sel_i == 2'd3), .wr_addr_i(ram_waddr_i),
    .wr_data_i(ram_wdata_i), .out_valid_o(shade_valid), .out_ready_i(shade_ready), .out_data_o(shade)
  );
  if (TPW < 64) begin : g_no_hi
    logic unused_hi;
    assign unused_hi = ^ram_wdata64[63:TPW];
  end
  logic unused;
  assign unused = ^{d_word[31:8], a_word[31:8], view[63:3 * VzW + tu_formats_pkg::PomCW + 1]};
endmodule
