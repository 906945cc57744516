// Texture unit top: B1 perspective divide -> B2 footprint -> B5 filter -> shading, one output per
// covered pixel, valid/ready throughout (docs/blocks/ewa.md "RTL"; shading: docs/blocks/brdf.md §6).
//
//   span in ─► fork ─► tu_persp_setup (2) ─┐                ┌─► tu_persp (8) ──┐
//                  └─► tu_num_setup (2) ───┴► join ─► tu_span_expand ─► fork ─┼─► tu_ellipse (5) ─┼► join ─► tu_fifo ─► filter ─► pixel out
//                                                                          └─► sideband FIFO ──┘
// One input = one span [x0, x1] of row y covered by one triangle: the B1 quantised coefficients
// A..I, the per-triangle B2 constants (numerator constants kux..kvy, m, nn and det3, exact, from
// the triangle set-up; ellipse::fx), and the material: texture (base address in the texel RAM,
// log2 size, wrap), EWA weight source and texel cap. The fixed-latency B1/B2 pipelines stall as a
// whole; the FIFO in front of the data-dependent filter lets them run ahead by FifoDepth pixels.
// The filter reads texels through a port with 1-cycle read latency (a C++ RAM model in co-simulation).
// With HasShading the filtered pixel is joined with its word from the shade port (the shader's
// N, L, H, exponent, cut-off and colours, brdf::shade::pack) and shaded by tu_shade (II = 1, the
// model's latency) on its way out.
// With HasNoise a procedural span (proc_i.on) sends its pixels to tu_noise_unit instead of a
// filter engine: the colour of the fBm / smoke at B1's (u, v) with the octave weights of B2's
// lrho (docs/blocks/noise.md §5); it takes turns with the engines and carries its pixels' fields.
// Per-pixel records: tu_records.svh (generated from cmodel/include/texunit/schema.hpp).
`include "tu_records.svh"
`include "tu_assert.svh"
module tu_texture_unit #(
  // Defaults from the unit configuration (rtl/0_pkg/tu_unit_cfg_pkg.sv: the full unit as committed;
  // `texunit plan SCENE --out rtl/0_pkg/tu_unit_cfg_pkg.sv` specialises it to a scene).
  // Filter engines: EWA (tu_ewa), bilinear at level 0 (tu_bilinear), trilinear (tu_trilinear),
  // nearest at level 0 (tu_nearest), Feline probes (tu_feline). Each span's filt_i picks one; a
  // span asking for an engine the unit leaves out goes to the first present of EWA, trilinear,
  // bilinear, nearest, Feline.
  parameter int HasEwa       = {31'b0, tu_unit_cfg_pkg::HasEwa},
  parameter int HasBilinear  = {31'b0, tu_unit_cfg_pkg::HasBilinear},
  parameter int HasTriFilter = {31'b0, tu_unit_cfg_pkg::HasTriFilter},
  parameter int HasNearest   = {31'b0, tu_unit_cfg_pkg::HasNearest},
  parameter int HasFeline    = {31'b0, tu_unit_cfg_pkg::HasFeline},
  // 1: relief stage (tu_relief_stage) between B1 and the filter, with its POM march (fixed or
  // adaptive layers) and iterative-parallax engines
  parameter int HasRelief   = {31'b0, tu_unit_cfg_pkg::HasRelief},
  // 1: shading stage (tu_shade: one light, diffuse + the BRDF model ShadeModel, brdf::Model codes)
  // after the filter; every output pixel takes one word from the shade port
  parameter int HasShading  = {31'b0, tu_unit_cfg_pkg::HasShading},
  parameter int ShadeModel  = tu_unit_cfg_pkg::ShadeModel,
  parameter int HasPom      = {31'b0, tu_unit_cfg_pkg::HasPom},
  parameter int HasIterParallax = {31'b0, tu_unit_cfg_pkg::HasIterParallax},
  parameter int HasDistanceMap = {31'b0, tu_unit_cfg_pkg::HasDistanceMap},
  // B2's Jacobian: 0 analytic (tu_ellipse), 1 the seed's forward-difference recurrences
  // (tu_ellipse_rec: latency EllRecLatency > PerspLatency, so B1's output waits in a FIFO)
  parameter int EllRecurrence = {31'b0, tu_unit_cfg_pkg::EllRecurrence},
  // EWA sub-texel border weights (tu_ewa_border in the walk; a span's clip_i turns them on) and
  // their clip volume (0 mm_p1, 1 mm_p3 Horner, 2 mm_p3 Estrin)
  parameter int HasEwaClip     = {31'b0, tu_unit_cfg_pkg::HasEwaClip},
  parameter int EwaClipVariant = tu_unit_cfg_pkg::EwaClipVariant,
  // 1: noise unit (tu_noise_unit) beside the filter engines for procedural materials (proc_i.on):
  // NoiseDims 2 (materials without time) or 3, NoiseCores octave cores (the largest octave count)
  parameter int HasNoise   = {31'b0, tu_unit_cfg_pkg::HasNoise},
  parameter int NoiseDims  = tu_unit_cfg_pkg::NoiseDims,
  parameter int NoiseCores = tu_unit_cfg_pkg::NoiseCores,
  // 1: the noise unit's water back-end (three octave sums, normal, Lambert; tu_noise_unit)
  parameter int HasWater   = {31'b0, tu_unit_cfg_pkg::HasWater},
  // noise scheme: 0 pipelined (NoiseCores cores, one octave sum per clock), 1 octave-serial (one
  // core, NoiseCores clocks per sum)
  parameter int NoiseScheme = tu_unit_cfg_pkg::NoiseScheme,
  // 1: AF with parallax visibility (tu_afvis, docs/blocks/afvis.md) beside tu_ewa in the EWA slot:
  // a shifted pixel of a material with afv takes it; its depth reads use the a_* port
  parameter int HasAfvis   = {31'b0, tu_unit_cfg_pkg::HasAfvis},
  // EWA texels per clock (tu_ewa Lanes: 1, or 4 = a 2 x 2 block over four bank ports, the texel
  // port and texk_* for banks 1..3) and its set-up units (EwaSetups: 1, or 2 .. 4 with 4 lanes)
  parameter int EwaLanes  = 1,
  parameter int EwaSetups = 1,
  // texel decode (tu_texel_decode): the storage formats kept (bit = TexFmt* code), the sRGB
  // tables, and the texel port's width (the widest stored format kept)
  parameter logic [6:0] TexFormats = tu_unit_cfg_pkg::TexFormats,
  parameter int HasSrgb   = {31'b0, tu_unit_cfg_pkg::HasSrgb},
  parameter int TexelW    = tu_unit_cfg_pkg::TexelW,
  // BC1 block fetch (tu_texel_port, tu_bc1_addr, tu_bc1_decode): the texel RAM word becomes 64 bits
  // (one BC1 block; a texel of another format in its low TexelW bits)
  parameter int HasBc1    = {31'b0, tu_unit_cfg_pkg::HasBc1},
  parameter int FifoDepth = 4   // pixels buffered between B2 and the filter
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
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
  // material trilinear LOD rule: bias, min / max lod (TexLodF fraction bits)
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] lbias_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lminlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]    lmaxlod_i,
  input  logic [3:0]                            lbase_i,  // material levels [base, top] (tex::level_range)
  input  logic [3:0]                            ltop_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   tbase_i,
  input  logic [3:0]                            tlw_i,
  input  logic [3:0]                            tlh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]     twrap_i,  // {v, u} Wrap* codes
  input  logic [tu_formats_pkg::TexFmtW-1:0]    tfmt_i,   // storage format (TexFmt* codes)
  input  logic                                  tsrgb_i,  // sRGB colour channels
  input  logic [1:0]                            wsrc_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]  cap_i,
  input  logic [tu_formats_pkg::EngineW-1:0]    filt_i,  // material filter: Eng* codes
  input  logic [tu_formats_pkg::FelProbeW-1:0]  fnmax_i, // material Feline probe cap (1..FelNMax)
  input  logic                                  clip_i,  // material EWA border weights (HasEwaClip)
  // material relief (POM): on, adaptive layers, layers (1..63), height scale S, depth map
  input  logic                                  rel_i,
  input  logic                                  radapt_i,
  input  logic                                  riter_i,   // iterative parallax (cap = rlayers)
  input  logic [tu_formats_pkg::PomNW-1:0]      rlayers_i,
  input  logic [tu_formats_pkg::PomSW-1:0]      rscale_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   hbase_i,
  input  logic [3:0]                            hlw_i,
  input  logic [3:0]                            hlh_i,
  input  logic                                  rdm_i,     // distance map (cap = rlayers)
  input  logic [tu_formats_pkg::DmLayersW-1:0]  dlayers_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]   dbase_i,   // the map in the depth RAM
  // material AF with parallax visibility (HasAfvis): on, the depth map's smallest code, bias, rule
  input  logic                                  afv_i,
  input  logic [7:0]                            admin_i,
  input  logic [7:0]                            abias_i,
  input  logic                                  arule_i,
  // procedural material (tu_proc_t; on = 0: a texture material)
  input  logic [tu_formats_pkg::ProcW-1:0]      proc_i,
  // per-pixel tangent-space view, one word per pixel of a relief span, in pixel order
  input  logic                                  view_valid_i,
  output logic                                  view_ready_o,
  input  logic                                  view_ok_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vx_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vy_i,
  input  logic [tu_formats_pkg::PomVzW-1:0]     vz_i,
  input  logic [tu_formats_pkg::PomCW-1:0]      vc_i,
  // depth-map port (1-cycle read latency; depth = 255 - height in the low 8 bits)
  output logic                                  d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   d_addr_o,
  input  logic [7:0]                            d_data_i,
  // the visibility engine's depth-map port (a second read port on the depth RAM; HasAfvis)
  output logic                                  a_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   a_addr_o,
  input  logic [7:0]                            a_data_i,
  // per-pixel shade word (brdf::shade::pack), one per output pixel in pixel order (HasShading)
  input  logic                                  shade_valid_i,
  output logic                                  shade_ready_o,
  input  logic [tu_formats_pkg::ShadeWordW-1:0] shade_i,
  // texel port (1-cycle read latency; a stored word, decoded by tu_texel_decode)
  output logic                                  tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]   tex_addr_o,
  input  logic [(HasBc1 != 0 ? 64 : TexelW)-1:0] tex_data_i,  // (HasBc1: 64 bits)
  // EWA bank ports 1..3 (EwaLanes = 4; 1-cycle read latency; stored words as the texel port's;
  // EwaLanes = 1: unused, req 0); the texel port is bank 0 then
  output logic [(EwaLanes > 1 ? EwaLanes - 1 : 1)-1:0]                         texk_req_o,
  output logic [(EwaLanes > 1 ? EwaLanes - 1 : 1)*tu_formats_pkg::TexAddrW-1:0] texk_addr_o,
  input  logic [(EwaLanes > 1 ? EwaLanes - 1 : 1)*(HasBc1 != 0 ? 64 : TexelW)-1:0] texk_data_i,
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
  output logic [tu_formats_pkg::PomNW-1:0]      rn_o,      // relief layers used (0: not shifted)
  output logic [tu_formats_pkg::PomNW-1:0]      rsteps_o,  // relief march steps or iterations
  output logic [2:0]                            rflags_o   // relief::ReliefFlag bits
);
  localparam int PW = tu_formats_pkg::PerspPW;
  localparam int QW = tu_formats_pkg::PerspQW;
  localparam int XW = tu_formats_pkg::PerspXyW;
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int AW = tu_formats_pkg::TexAddrW;
  localparam int NW = tu_formats_pkg::EllNxW;
  localparam int TriW  = tu_formats_pkg::TriW;     // tu_tri_t: per-triangle B2 fields
  localparam int PixW  = tu_formats_pkg::PixW;     // tu_pix_t: x, y, ovf, material, relief
  localparam int FPixW = tu_formats_pkg::FpixW;    // tu_fpix_t: after the relief stage
  localparam int SpanW = 2 * PW + 2 * QW + 3 * XW + TriW + tu_formats_pkg::MaterialW + tu_formats_pkg::ReliefW +
                         tu_formats_pkg::ProcW;

  // ---------------- span set-up: fork to B1 set-up and numerator set-up, join ----------------
  logic ps_in_ready, ns_in_ready, ps_valid, ns_valid, sj_valid, sj_ready;
  logic [PW-1:0] ps_pu, ps_pv;
  logic [QW-1:0] ps_q;
  logic          ps_ovf;
  logic [NW-1:0] ns_nux, ns_nvx, ns_nuy, ns_nvy, ns_m, ns_nn;
  logic [SpanW-1:0] span_side, ns_side;
  tu_tri_t      in_tri;
  tu_material_t in_mat;
  tu_relief_t   in_rel;
  always_comb begin
    in_tri.dm      = dm_i;
    in_tri.dexp    = dexp_i;
    in_tri.laniso  = laniso_i;
    in_tri.maxlod  = maxlod_i;
    in_tri.lbias   = lbias_i;
    in_tri.lminlod = lminlod_i;
    in_tri.lmaxlod = lmaxlod_i;
    in_tri.lbase   = lbase_i;
    in_tri.ltop    = ltop_i;
    in_mat.tlbase  = lbase_i;
    in_mat.lbias   = lbias_i;   // the Feline probes' lod rule (the tri record's copy feeds B2)
    in_mat.lminlod = lminlod_i;
    in_mat.lmaxlod = lmaxlod_i;
    in_mat.ltop    = ltop_i;
    in_mat.fnmax   = fnmax_i;
    in_mat.tbase   = tbase_i;
    in_mat.tlw     = tlw_i;
    in_mat.tlh     = tlh_i;
    in_mat.twrapu  = twrap_i[tu_formats_pkg::WrapW-1:0];
    in_mat.twrapv  = twrap_i[2*tu_formats_pkg::WrapW-1:tu_formats_pkg::WrapW];
    in_mat.wsrc    = wsrc_i;
    in_mat.cap     = cap_i;
    in_mat.filt    = filt_i;
    in_mat.clip    = clip_i;
    in_mat.tfmt    = tfmt_i;
    in_mat.tsrgb   = tsrgb_i;
    in_rel.rel     = rel_i;
    in_rel.radapt  = radapt_i;
    in_rel.riter   = riter_i;
    in_rel.rlayers = rlayers_i;
    in_rel.rscale  = rscale_i;
    in_rel.hbase   = hbase_i;
    in_rel.hlw     = hlw_i;
    in_rel.hlh     = hlh_i;
    in_rel.rdm     = rdm_i;
    in_rel.dlayers = dlayers_i;
    in_rel.dbase   = dbase_i;
    in_rel.afv     = afv_i;
    in_rel.admin   = admin_i;
    in_rel.abias   = abias_i;
    in_rel.arule   = arule_i;
  end
  assign span_side = {a_i, d_i, g_i, h_i, x0_i, x1_i, y_i, in_tri, in_mat, in_rel, proc_i};
  assign in_ready_o = ps_in_ready && ns_in_ready;

  tu_persp_setup u_psetup (
    .clk_i, .rst_ni, .in_valid_i(in_valid_i && ns_in_ready), .in_ready_o(ps_in_ready),
    .a_i, .b_i, .c_i, .d_i, .e_i, .f_i, .g_i, .h_i, .i_i, .x0_i, .x1_i, .y_i,
    .out_valid_o(ps_valid), .out_ready_i(sj_ready && ns_valid),
    .pu_o(ps_pu), .pv_o(ps_pv), .q_o(ps_q), .ovf_o(ps_ovf)
  );
  tu_num_setup #(.SideW(SpanW)) u_nsetup (
    .clk_i, .rst_ni, .in_valid_i(in_valid_i && ps_in_ready), .in_ready_o(ns_in_ready),
    .kux_i, .kvx_i, .kuy_i, .kvy_i, .m_i, .nn_i, .x0_i, .y_i, .side_i(span_side),
    .out_valid_o(ns_valid), .out_ready_i(sj_ready && ps_valid),
    .nux_o(ns_nux), .nvx_o(ns_nvx), .nuy_o(ns_nuy), .nvy_o(ns_nvy), .m_o(ns_m), .nn_o(ns_nn),
    .side_o(ns_side)
  );
  assign sj_valid = ps_valid && ns_valid;

  // unpack the span sideband
  logic [PW-1:0] s_a, s_d;
  logic [QW-1:0] s_g, s_h;
  logic [XW-1:0] s_x0, s_x1, s_y;
  tu_tri_t      s_tri;
  tu_material_t s_mat;
  tu_relief_t   s_rel;
  tu_proc_t     s_proc;
  assign {s_a, s_d, s_g, s_h, s_x0, s_x1, s_y, s_tri, s_mat, s_rel, s_proc} = ns_side;
  tu_pix_t s_pix;  // x: filled per pixel by the expander
  always_comb begin
    s_pix.fpix.x   = '0;
    s_pix.fpix.y   = s_y;
    s_pix.fpix.ovf = ps_ovf;
    s_pix.fpix.mat = s_mat;
    s_pix.fpix.proc = s_proc;
    s_pix.rel      = s_rel;
  end

  // ---------------- span -> pixels ----------------
  localparam int ExSideW = TriW + PixW;
  logic ex_valid, ex_ready;
  logic [PW-1:0] ex_pu0, ex_pv0, ex_a, ex_d;
  logic [QW-1:0] ex_q0, ex_g, ex_q;
  logic [XW-1:0] ex_n, ex_x;
  logic [tu_formats_pkg::EllNumW-1:0] ex_nux, ex_nvx, ex_nuy, ex_nvy;
  logic [tu_formats_pkg::EllRecQW-1:0] ex_qg, ex_qh;
  logic [ExSideW-1:0] ex_side;
  tu_span_expand #(.SideW(ExSideW)) u_expand (
    .clk_i, .rst_ni, .in_valid_i(sj_valid), .in_ready_o(sj_ready),
    .pu0_i(ps_pu), .pv0_i(ps_pv), .q0_i(ps_q), .a_i(s_a), .d_i(s_d), .g_i(s_g), .h_i(s_h),
    .nux_i(ns_nux), .nvx_i(ns_nvx), .nuy_i(ns_nuy), .nvy_i(ns_nvy), .m_i(ns_m), .nn_i(ns_nn),
    .x0_i(s_x0), .x1_i(s_x1), .side_i({s_tri, s_pix}),
    .out_valid_o(ex_valid), .out_ready_i(ex_ready),
    .pu0_o(ex_pu0), .pv0_o(ex_pv0), .q0_o(ex_q0), .a_o(ex_a), .d_o(ex_d), .g_o(ex_g), .n_o(ex_n),
    .x_o(ex_x), .q_o(ex_q), .qg_o(ex_qg), .qh_o(ex_qh), .nux_o(ex_nux), .nvx_o(ex_nvx), .nuy_o(ex_nuy), .nvy_o(ex_nvy),
    .side_o(ex_side)
  );
  tu_tri_t ex_tri;
  tu_pix_t ex_pix, ex_pix_x;
  assign {ex_tri, ex_pix} = ex_side;
  always_comb begin  // the x slot is filled per pixel
    ex_pix_x        = ex_pix;
    ex_pix_x.fpix.x = ex_x;
  end

  // ---------------- pixel fork: B1, B2 and the sideband FIFO; join ----------------
  logic b1_in_ready, b2_in_ready, sb_in_ready, b1_valid, b2_valid, sb_valid, pj_valid, pj_ready;
  logic [UW-1:0] b1_u, b1_v;
  logic          b1_flag;
  tu_pix_t       sb_pix;
  logic [tu_formats_pkg::EllCoefW-1:0] b2_ae, b2_be, b2_ce;
  logic [tu_formats_pkg::EllEexpW-1:0] b2_eexp;
  logic [tu_formats_pkg::EllFmW-1:0]   b2_fm;
  logic [tu_formats_pkg::EllFexpW-1:0] b2_fexp;
  logic [tu_formats_pkg::EllLogW-1:0]  b2_lmaj, b2_lmin;
  logic [tu_formats_pkg::EllLodW-1:0]  b2_lod, b2_tlod, b2_glod;  // EWA level, trilinear lod (the sampler rule); B2 lod
  logic [tu_formats_pkg::EllLogW-1:0]  b2_lrho;
  logic [2:0]                          b2_tflags;
  logic [4:0]                          b2_flags;
  assign ex_ready = b1_in_ready && b2_in_ready && sb_in_ready;
  assign pj_valid = b1_valid && b2_valid && sb_valid;

  // B1; with the recurrence ellipse its output waits in a FIFO for B2 (II = 1 kept: B1's
  // pipeline plus the FIFO hold more pixels than B2's EllRecLatency)
  logic          p1_valid, p1_ready;
  logic [UW-1:0] p1_u, p1_v;
  logic          p1_flag;
  tu_persp u_b1 (
    .clk_i, .rst_ni, .in_valid_i(ex_valid && b2_in_ready && sb_in_ready), .in_ready_o(b1_in_ready),
    .pu0_i(ex_pu0), .pv0_i(ex_pv0), .q0_i(ex_q0), .a_i(ex_a), .d_i(ex_d), .g_i(ex_g), .n_i(ex_n),
    .out_valid_o(p1_valid), .out_ready_i(p1_ready),
    .u_o(p1_u), .v_o(p1_v), .flag_o(p1_flag)
  );
  localparam int EllB2Lat = (EllRecurrence != 0) ? tu_formats_pkg::EllRecLatency : tu_formats_pkg::EllLatency;
  if (EllB2Lat > tu_formats_pkg::PerspLatency) begin : g_b1_fifo
    tu_fifo #(.Width(2 * UW + 1), .Depth(4)) u_b1q (
      .clk_i, .rst_ni, .in_valid_i(p1_valid), .in_ready_o(p1_ready), .in_data_i({p1_u, p1_v, p1_flag}),
      .out_valid_o(b1_valid), .out_ready_i(pj_ready && b2_valid && sb_valid), .out_data_o({b1_u, b1_v, b1_flag})
    );
  end else begin : g_b1_direct
    assign b1_valid = p1_valid;
    assign p1_ready = pj_ready && b2_valid && sb_valid;
    assign {b1_u, b1_v, b1_flag} = {p1_u, p1_v, p1_flag};
  end
  if (EllRecurrence != 0) begin : g_b2_rec
    tu_ellipse_rec u_b2 (
      .clk_i, .rst_ni, .in_valid_i(ex_valid && b1_in_ready && sb_in_ready), .in_ready_o(b2_in_ready),
      .nux_i(ex_nux), .nvx_i(ex_nvx), .nuy_i(ex_nuy), .nvy_i(ex_nvy), .q_i(ex_q), .qg_i(ex_qg), .qh_i(ex_qh),
      .laniso_i(ex_tri.laniso), .maxlod_i(ex_tri.maxlod),
      .lbias_i(ex_tri.lbias), .lminlod_i(ex_tri.lminlod), .lmaxlod_i(ex_tri.lmaxlod),
      .lbase_i(ex_tri.lbase), .ltop_i(ex_tri.ltop),
      .out_valid_o(b2_valid), .out_ready_i(pj_ready && b1_valid && sb_valid),
      .ae_o(b2_ae), .be_o(b2_be), .ce_o(b2_ce), .eexp_o(b2_eexp), .fm_o(b2_fm), .fexp_o(b2_fexp),
      .lmaj_o(b2_lmaj), .lmin_o(b2_lmin), .lod_o(b2_glod), .flags_o(b2_flags),
      .lrho_o(b2_lrho), .tlod_o(b2_tlod), .tflags_o(b2_tflags), .elod_o(b2_lod)
    );
    logic unused_det3;
    assign unused_det3 = ^{ex_tri.dm, ex_tri.dexp};  // det J is formed inside
  end else begin : g_b2_analytic
    tu_ellipse u_b2 (
      .clk_i, .rst_ni, .in_valid_i(ex_valid && b1_in_ready && sb_in_ready), .in_ready_o(b2_in_ready),
      .nux_i(ex_nux), .nvx_i(ex_nvx), .nuy_i(ex_nuy), .nvy_i(ex_nvy), .q_i(ex_q),
      .dm_i(ex_tri.dm), .dexp_i(ex_tri.dexp), .laniso_i(ex_tri.laniso), .maxlod_i(ex_tri.maxlod),
      .lbias_i(ex_tri.lbias), .lminlod_i(ex_tri.lminlod), .lmaxlod_i(ex_tri.lmaxlod),
      .lbase_i(ex_tri.lbase), .ltop_i(ex_tri.ltop),
      .out_valid_o(b2_valid), .out_ready_i(pj_ready && b1_valid && sb_valid),
      .ae_o(b2_ae), .be_o(b2_be), .ce_o(b2_ce), .eexp_o(b2_eexp), .fm_o(b2_fm), .fexp_o(b2_fexp),
      .lmaj_o(b2_lmaj), .lmin_o(b2_lmin), .lod_o(b2_glod), .flags_o(b2_flags),
      .lrho_o(b2_lrho), .tlod_o(b2_tlod), .tflags_o(b2_tflags), .elod_o(b2_lod)
    );
    logic unused_qgh;
    assign unused_qgh = ^{ex_qg, ex_qh};  // the recurrence's denominators
  end
  logic unused_b2;
  assign unused_b2 = ^{b2_tflags, b2_glod};  // the C model's record only; the EWA takes elod (the sampler's rule)
  // Holds the sideband of every pixel inside B1/B2 (at most max(PerspLatency, EllB2Lat) + 1).
  tu_fifo #(.Width(PixW), .Depth(16)) u_side (
    .clk_i, .rst_ni, .in_valid_i(ex_valid && b1_in_ready && b2_in_ready), .in_ready_o(sb_in_ready),
    .in_data_i(ex_pix_x), .out_valid_o(sb_valid), .out_ready_i(pj_ready && b1_valid && b2_valid),
    .out_data_o(sb_pix)
  );

  // ---------------- relief stage ----------------
  // B1's (u, v) shifted by the material's POM relief; everything else rides along in order.
  // With HasAfvis a pixel also carries what the visibility engine needs: {shifted with afv, the
  // view vx, vy, vz, S, the depth map base, log2 sides, its smallest code, bias, rule}.
  localparam int VzW = tu_formats_pkg::PomVzW;
  localparam int AfvW = HasAfvis != 0 ? 1 + 3 * VzW + tu_formats_pkg::PomSW + AW + 8 + 8 + 8 + 1 : 1;
  localparam int RSideW = FPixW + 1 + 3 * tu_formats_pkg::EllCoefW +
                                   3 * tu_formats_pkg::EllLogW + 2 * tu_formats_pkg::EllLodW + 5 + AfvW;
  tu_relief_t pj_rel;
  assign pj_rel = sb_pix.rel;
  logic [AfvW-1:0] afv_side;
  if (HasAfvis != 0) begin : g_afv_side
    // the relief stage shifts iff rel, no B1 guard and a view (tu_relief_stage shift)
    assign afv_side = {pj_rel.rel && pj_rel.afv && !b1_flag && view_ok_i, vx_i, vy_i, vz_i, pj_rel.rscale,
                       pj_rel.hbase, pj_rel.hlw, pj_rel.hlh, pj_rel.admin, pj_rel.abias, pj_rel.arule};
  end else begin : g_no_afv_side
    assign afv_side = 1'b0;
    logic unused_afv_rel;
    assign unused_afv_rel = ^{pj_rel.afv, pj_rel.admin, pj_rel.abias, pj_rel.arule};
  end
  logic [RSideW-1:0] rs_in, rs_out;
  assign rs_in = {sb_pix.fpix, b1_flag, b2_ae, b2_ce, b2_be, b2_lmaj, b2_lmin, b2_lod, b2_tlod, b2_flags, b2_lrho,
                  afv_side};
  logic          rs_valid, rs_ready;
  logic [UW-1:0] rs_u, rs_v;
  localparam int RrW = 2 * tu_formats_pkg::PomNW + 3;  // relief result: n, steps, flags
  logic [tu_formats_pkg::PomNW-1:0] rs_n, rs_steps;
  logic [2:0]                       rs_flags;
  if (HasRelief != 0) begin : g_relief
    tu_relief_stage #(.SideW(RSideW), .HasPom(HasPom), .HasIterParallax(HasIterParallax),
                      .HasDistanceMap(HasDistanceMap)) u_relief (
      .clk_i, .rst_ni, .in_valid_i(pj_valid), .in_ready_o(pj_ready),
      .u_i(b1_u), .v_i(b1_v), .lw_i(sb_pix.fpix.mat.tlw), .lh_i(sb_pix.fpix.mat.tlh), .rel_i(pj_rel.rel),
      .guard_i(b1_flag), .adaptive_i(pj_rel.radapt), .iter_i(pj_rel.riter), .layers_i(pj_rel.rlayers), .scale_i(pj_rel.rscale),
      .hbase_i(pj_rel.hbase), .hlw_i(pj_rel.hlw), .hlh_i(pj_rel.hlh),
      .dm_i(pj_rel.rdm), .dlayers_i(pj_rel.dlayers), .dbase_i(pj_rel.dbase), .side_i(rs_in),
      .view_valid_i, .view_ready_o, .view_ok_i, .vx_i, .vy_i, .vz_i, .vc_i,
      .d_req_o, .d_addr_o, .d_data_i,
      .out_valid_o(rs_valid), .out_ready_i(rs_ready), .u_o(rs_u), .v_o(rs_v), .n_o(rs_n), .steps_o(rs_steps), .flags_o(rs_flags),
      .side_o(rs_out)
    );
  end else begin : g_no_relief
    assign rs_valid     = pj_valid;
    assign pj_ready     = rs_ready;
    assign rs_u         = b1_u;
    assign rs_v         = b1_v;
    assign rs_n         = '0;
    assign rs_steps     = '0;
    assign rs_flags     = '0;
    assign rs_out       = rs_in;
    assign view_ready_o = 1'b0;
    assign d_req_o      = 1'b0;
    assign d_addr_o     = '0;
    logic unused_relief;
    assign unused_relief = ^{pj_rel, view_valid_i, view_ok_i, vx_i, vy_i, vz_i, vc_i, d_data_i};
  end

  // ---------------- FIFO in front of the filter ----------------
  localparam int FW = RSideW + 2 * UW + RrW;
  logic          fq_valid, fq_ready;
  logic [FW-1:0] fq_data;
  tu_fifo #(.Width(FW), .Depth(FifoDepth)) u_fifo (
    .clk_i, .rst_ni, .in_valid_i(rs_valid), .in_ready_o(rs_ready),
    .in_data_i({rs_out, rs_u, rs_v, rs_n, rs_steps, rs_flags}),
    .out_valid_o(fq_valid), .out_ready_i(fq_ready), .out_data_o(fq_data)
  );
  tu_fpix_t      f_pix;
  tu_material_t  f_mat;
  logic          f_guard;
  logic [UW-1:0] f_u, f_v;
  logic [RrW-1:0] f_rr;
  logic [tu_formats_pkg::EllCoefW-1:0] f_ae, f_ce, f_be;
  logic [tu_formats_pkg::EllLogW-1:0]  f_lmaj, f_lmin, f_lrho;
  logic [tu_formats_pkg::EllLodW-1:0]  f_lod, f_tlod;
  logic [4:0]                          f_eflags;
  logic [AfvW-1:0]                     f_afv_side;
  assign {f_pix, f_guard, f_ae, f_ce, f_be, f_lmaj, f_lmin, f_lod, f_tlod, f_eflags, f_lrho, f_afv_side, f_u, f_v, f_rr} = fq_data;
  assign f_mat = f_pix.mat;

  // ---------------- filter ----------------
  // Per-pixel fields the filter does not carry ride in a FIFO popped with its output (it holds
  // the pixels in flight in the engines).
  // The engines take turns: a pixel for another engine waits until the current one has output
  // all its pixels (cur_q: the engine of the pixels in flight, inflight_q: how many), so outputs
  // stay in order and only one engine drives the texel port. Switches happen at material changes
  // only (ewa::stream_cycles counts the drain).
  localparam int OsW = 2 * XW + 2 + 5 + RrW;
  // Pixels in flight in an engine: 2 (a set-up and a walk), Feline 3 (set-up, prober, normaliser),
  // the K = 4 EWA engine up to its set-up units (<= 4) + OutDepth (8) between hand-over and output: 16
  // (the FIFO never throttles it)
  localparam int OsDepth = EwaLanes > 1 ? 16 : HasFeline != 0 ? 4 : 2;
  localparam int IfW = $clog2(OsDepth + 1);
  // The texture's storage format (FkW: TexFmt code, sRGB) of the pixels in flight (fk_q): a pixel
  // of another format waits until they have left, as at an engine switch (ewa::stream_cycles
  // counts the drain), so every texel word the engines read decodes with fk_q, whatever engine
  // and however many pixels it holds.
  localparam int FkW = tu_formats_pkg::TexFmtW + 1;
  // the filtered pixel before the shading stage
  logic          p_valid, p_ready;
  logic [XW-1:0] p_x, p_y;
  logic [31:0]   p_rgba;
  logic [3:0]    p_level;
  logic [tu_formats_pkg::EwaCountW-1:0] p_visited, p_inside;
  logic [4:0]    p_flags, p_eflags;
  logic [1:0]    p_pflags;
  logic [RrW-1:0] p_rr;  // relief n, steps, flags
  localparam int EW = tu_formats_pkg::EngineW;
  localparam logic [EW-1:0] EngBil = tu_formats_pkg::EngBilinear, EngEwa = tu_formats_pkg::EngEwa,
                            EngTri = tu_formats_pkg::EngTrilinear, EngNst = tu_formats_pkg::EngNearest,
                            EngFel = tu_formats_pkg::EngFeline;
  localparam logic [EW-1:0] EngFirst = (HasEwa != 0) ? EngEwa : (HasTriFilter != 0) ? EngTri :
                                       (HasBilinear != 0) ? EngBil : (HasNearest != 0) ? EngNst : EngFel;
  logic          os_in_ready, os_valid, flt_valid, eng_ready, can_go, fire_flt, fire_out;
  logic [EW-1:0] sel, cur_q;
  logic [IfW-1:0] inflight_q;  // <= OsDepth: the sideband FIFO's depth bounds the pixels in flight
  logic [OsW-1:0] os_data;
  logic          ewa_in_ready, ewa_valid, bil_in_ready, bil_valid, tri_in_ready, tri_valid;
  logic          nst_in_ready, nst_valid, fel_in_ready, fel_valid;
  logic          ewa_req, bil_req, tri_req, nst_req, fel_req;
  logic [AW-1:0] ewa_addr, bil_addr, tri_addr, nst_addr, fel_addr;
  logic [31:0]   ewa_rgba, bil_rgba, tri_rgba, nst_rgba, fel_rgba;
  always_comb begin
    unique case (f_mat.filt)
      EngEwa:  sel = (HasEwa != 0) ? EngEwa : EngFirst;
      EngTri:  sel = (HasTriFilter != 0) ? EngTri : EngFirst;
      EngNst:  sel = (HasNearest != 0) ? EngNst : EngFirst;
      EngFel:  sel = (HasFeline != 0) ? EngFel : EngFirst;
      default: sel = (HasBilinear != 0) ? EngBil : EngFirst;
    endcase
  end
  // A procedural pixel goes to the noise unit (f_noise), which takes turns with the engines the
  // same way (nz_busy: it has pixels in flight) and carries its pixels' fields itself.
  logic f_noise, nz_busy, nz_in_ready, nz_valid;
  logic [31:0]   nz_rgba;
  assign f_noise   = HasNoise != 0 && f_pix.proc.on;
  assign can_go    = (inflight_q == '0 || (cur_q == sel && fk_q == f_fk && btex_q == f_btex)) && !nz_busy;
  logic [4:0]    in_ready_of, valid_of, req_of;  // indexed by engine
  logic [AW-1:0] cur_addr;
  logic [31:0]   cur_rgba;
  assign in_ready_of = {fel_in_ready, nst_in_ready, tri_in_ready, ewa_in_ready, bil_in_ready};
  assign valid_of    = {fel_valid, nst_valid, tri_valid, ewa_valid, bil_valid};
  assign req_of      = {fel_req, nst_req, tri_req, ewa_req, bil_req};
  always_comb begin  // (a case, not an array pattern: Yosys 0.23 parses the top for area)
    unique case (cur_q)
      EngEwa:  begin cur_addr = ewa_addr; cur_rgba = ewa_rgba; end
      EngTri:  begin cur_addr = tri_addr; cur_rgba = tri_rgba; end
      EngNst:  begin cur_addr = nst_addr; cur_rgba = nst_rgba; end
      EngFel:  begin cur_addr = fel_addr; cur_rgba = fel_rgba; end
      default: begin cur_addr = bil_addr; cur_rgba = bil_rgba; end
    endcase
  end
  assign eng_ready = in_ready_of[sel];
  assign fq_ready  = f_noise ? inflight_q == '0 && nz_in_ready : can_go && eng_ready && os_in_ready;
  assign fire_flt  = fq_valid && fq_ready && !f_noise;
  tu_fifo #(.Width(OsW), .Depth(OsDepth)) u_osb (
    .clk_i, .rst_ni, .in_valid_i(fq_valid && !f_noise && can_go && eng_ready), .in_ready_o(os_in_ready),
    .in_data_i({f_pix.x, f_pix.y, f_pix.ovf, f_guard, f_eflags, f_rr}), .out_valid_o(os_valid),
    .out_ready_i(p_ready && flt_valid), .out_data_o(os_data)
  );
  // cur_q is the engine of the oldest pixel in flight (set when it accepted its first).
  logic eng_in_valid;
  assign eng_in_valid = fq_valid && !f_noise && can_go && os_in_ready;
  assign flt_valid   = valid_of[cur_q];
  assign p_valid     = nz_busy ? nz_valid : flt_valid && os_valid;
  assign fire_out    = flt_valid && os_valid && p_ready;
  logic [OsW-1:0] nz_side;
  assign {p_x, p_y, p_pflags, p_eflags, p_rr} = nz_busy ? nz_side : os_data;
  // Texel ports: the stored words of the pixels in flight's texture (fk_q) to RGBA8, one
  // tu_texel_port (tu_texel_decode; with HasBc1 the BC1 block address and decode) per texel port
  // (the K = 4 EWA's bank ports too). A BC1 texture's block address needs the texture itself:
  // with HasBc1 the key of the pixels in flight also holds a BC1 texture's base and sides (btex_q),
  // so a pixel of another BC1 texture waits as at a format change (ewa::stream_cycles: texfmt).
  logic [FkW-1:0] f_fk, fk_q;
  assign f_fk = {f_mat.tfmt, f_mat.tsrgb};
  localparam logic [tu_formats_pkg::TexFmtW-1:0] TexFmtBc1 = 3'd7;  // tex::TexelFormat::Bc1
  localparam int BtW = AW + 8;
  logic           f_bc1;
  logic [BtW-1:0] f_btex, btex_q;  // {base, lw, lh} of a BC1 texture, else 0
  assign f_bc1  = HasBc1 != 0 && f_mat.tfmt == TexFmtBc1;
  assign f_btex = f_bc1 ? {f_mat.tbase, f_mat.tlw, f_mat.tlh} : '0;
  localparam int KP = EwaLanes > 1 ? EwaLanes - 1 : 1;
  localparam int TPW = HasBc1 != 0 ? 64 : TexelW;  // texel RAM word
  logic [31:0]    tex_rgba;
  logic [KP*32-1:0] texk_rgba;
  logic [KP-1:0]    texk_ereq;   // the EWA's bank ports 1..3 before tu_texel_port
  logic [KP*AW-1:0] texk_eaddr;
  logic             bc1_q;
  assign bc1_q = HasBc1 != 0 && fk_q[FkW-1:1] == TexFmtBc1;
  tu_texel_port #(.TexelW(TexelW), .Formats(TexFormats), .HasSrgb(HasSrgb), .HasBc1(HasBc1)) u_port (
    .clk_i, .req_i(tex_req_o), .addr_i(cur_addr), .addr_o(tex_addr_o), .word_i(tex_data_i),
    .fmt_i(fk_q[FkW-1:1]), .srgb_i(fk_q[0]), .bc1_i(bc1_q),
    .base_i(btex_q[BtW-1:8]), .lw_i(btex_q[7:4]), .lh_i(btex_q[3:0]), .rgba_o(tex_rgba)
  );
  assign texk_req_o = texk_ereq;
  if (EwaLanes > 1) begin : g_bank_decode
    for (genvar k = 0; k < KP; k++) begin : g_port
      tu_texel_port #(.TexelW(TexelW), .Formats(TexFormats), .HasSrgb(HasSrgb), .HasBc1(HasBc1)) u_port (
        .clk_i, .req_i(texk_ereq[k]), .addr_i(texk_eaddr[k*AW +: AW]), .addr_o(texk_addr_o[k*AW +: AW]),
        .word_i(texk_data_i[k*TPW +: TPW]), .fmt_i(fk_q[FkW-1:1]), .srgb_i(fk_q[0]), .bc1_i(bc1_q),
        .base_i(btex_q[BtW-1:8]), .lw_i(btex_q[7:4]), .lh_i(btex_q[3:0]), .rgba_o(texk_rgba[k*32 +: 32])
      );
    end
  end else begin : g_no_bank_decode
    assign texk_rgba   = '0;
    assign texk_addr_o = '0;
    logic unused_texk_data;
    assign unused_texk_data = ^{texk_data_i, texk_eaddr};
  end
  assign p_rgba      = nz_busy ? nz_rgba : cur_rgba;
  // Only the engine with pixels in flight reads texels.
  assign tex_req_o   = req_of[cur_q];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cur_q      <= EngFirst;
      fk_q       <= '0;
      btex_q     <= '0;
      inflight_q <= '0;
    end else begin
      if (fire_flt) cur_q <= sel;
      if (fire_flt) fk_q <= f_fk;
      if (fire_flt) btex_q <= f_btex;
      inflight_q <= inflight_q + IfW'(fire_flt) - IfW'(fire_out);
    end
  end

  logic [3:0]                           ewa_level, tri_level;
  logic [tu_formats_pkg::EwaCountW-1:0] ewa_visited, ewa_inside;
  logic [4:0]                           ewa_flags;
  if (HasEwa != 0) begin : g_ewa
    // plain EWA (tu_ewa) and, with HasAfvis, the visibility engine (tu_afvis) share the EWA slot;
    // they take turns like the engines (afv_cur_q: the engine of the slot's pixels in flight)
    logic pe_in_ready, pe_valid, pe_req, f_afv, afv_cur_q, av_in_ready, av_valid, av_req;
    logic [AW-1:0] pe_addr, av_addr;
    logic [31:0]   pe_rgba, av_rgba;
    logic [3:0]    pe_level, av_level;
    logic [tu_formats_pkg::EwaCountW-1:0] pe_visited, pe_inside, av_visited, av_inside;
    logic [4:0]    pe_flags, av_flags;
    // tu_ewa's texel ports: lane 0 on the texel port, lanes 1..3 (EwaLanes 4) on texk_* (tu_afvis
    // reads lane 0's port only; the two engines take turns, so never both at once)
    logic [EwaLanes-1:0]    ewa_req_v;
    logic [EwaLanes*AW-1:0] ewa_addr_v;
    logic [EwaLanes*32-1:0] ewa_data_v;
    assign pe_req  = ewa_req_v[0];
    assign pe_addr = ewa_addr_v[AW-1:0];
    if (EwaLanes > 1) begin : g_banks
      assign ewa_data_v  = {texk_rgba, tex_rgba};
      assign texk_ereq  = ewa_req_v[EwaLanes-1:1];
      assign texk_eaddr = ewa_addr_v[EwaLanes*AW-1:AW];
    end else begin : g_one_port
      assign ewa_data_v  = tex_rgba;
      assign texk_ereq   = '0;
      assign texk_eaddr  = '0;
      logic unused_texk;
      assign unused_texk = ^texk_rgba;
    end
    assign f_afv = HasAfvis != 0 && f_afv_side[AfvW-1];
    assign ewa_in_ready = (f_afv ? av_in_ready : pe_in_ready) && (inflight_q == '0 || afv_cur_q == f_afv);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) afv_cur_q <= 1'b0;
      else if (fire_flt && sel == EngEwa) afv_cur_q <= f_afv;
    end
    tu_ewa #(.HasClip(HasEwaClip), .ClipVariant(EwaClipVariant), .Lanes(EwaLanes), .Setups(EwaSetups)) u_ewa (
      .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngEwa && !f_afv && ewa_in_ready), .in_ready_o(pe_in_ready),
      .u_i(f_u), .v_i(f_v), .ae_i(f_ae), .ce_i(f_ce), .be_i(f_be), .lmaj_i(f_lmaj), .lmin_i(f_lmin),
      .lod_i(f_lod), .eflags_i(f_eflags), .guard_i(f_guard), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
      .wrap_i({f_mat.twrapv, f_mat.twrapu}), .wsrc_i(f_mat.wsrc), .cap_i(f_mat.cap), .clip_i(f_mat.clip),
      .tex_req_o(ewa_req_v), .tex_addr_o(ewa_addr_v), .tex_data_i(ewa_data_v),
      .out_valid_o(pe_valid), .out_ready_i(p_ready && os_valid && cur_q == EngEwa && !afv_cur_q),
      .rgba_o(pe_rgba), .level_o(pe_level), .visited_o(pe_visited), .inside_o(pe_inside),
      .flags_o(pe_flags)
    );
    if (HasAfvis != 0) begin : g_afvis
      logic [VzW-1:0] a_vx, a_vy, a_vz;
      logic [tu_formats_pkg::PomSW-1:0] a_s;
      logic [AW-1:0]  a_hbase;
      logic [3:0]     a_hlw, a_hlh;
      logic [7:0]     a_dmin, a_bias;
      logic           a_rule, a_on;
      logic [tu_formats_pkg::EwaCountW-1:0] a_kept, a_traced;
      logic [23:0]    a_steps;
      assign {a_on, a_vx, a_vy, a_vz, a_s, a_hbase, a_hlw, a_hlh, a_dmin, a_bias, a_rule} = f_afv_side;
      tu_afvis u_afvis (
        .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngEwa && f_afv && ewa_in_ready), .in_ready_o(av_in_ready),
        .u_i(f_u), .v_i(f_v), .ae_i(f_ae), .ce_i(f_ce), .be_i(f_be), .lmaj_i(f_lmaj), .lmin_i(f_lmin),
        .lod_i(f_lod), .eflags_i(f_eflags), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
        .wrap_i({f_mat.twrapv, f_mat.twrapu}), .wsrc_i(f_mat.wsrc), .cap_i(f_mat.cap),
        .vx_i(a_vx), .vy_i(a_vy), .vz_i(a_vz), .scale_i(a_s), .hbase_i(a_hbase), .hlw_i(a_hlw), .hlh_i(a_hlh),
        .dmin_i(a_dmin), .bias_i(a_bias), .rule_i(a_rule),
        .tex_req_o(av_req), .tex_addr_o(av_addr), .tex_data_i(tex_rgba),
        .d_req_o(a_req_o), .d_addr_o(a_addr_o), .d_data_i(a_data_i),
        .out_valid_o(av_valid), .out_ready_i(p_ready && os_valid && cur_q == EngEwa && afv_cur_q),
        .rgba_o(av_rgba), .level_o(av_level), .visited_o(av_visited), .inside_o(av_inside),
        .flags_o(av_flags), .kept_o(a_kept), .traced_o(a_traced), .steps_o(a_steps)
      );
      logic unused_afv;
      assign unused_afv = ^{a_on, a_kept, a_traced, a_steps};  // counts: the block's outputs only
    end else begin : g_no_afvis
      assign {av_in_ready, av_valid, av_req, av_addr, av_rgba, av_level, av_visited, av_inside, av_flags} = '0;
      assign a_req_o  = 1'b0;
      assign a_addr_o = '0;
      logic unused_afv;
      assign unused_afv = ^{a_data_i, f_afv_side};
    end
    assign ewa_valid   = afv_cur_q ? av_valid : pe_valid;
    assign ewa_req     = afv_cur_q ? av_req : pe_req;
    assign ewa_addr    = afv_cur_q ? av_addr : pe_addr;
    assign ewa_rgba    = afv_cur_q ? av_rgba : pe_rgba;
    assign ewa_level   = afv_cur_q ? av_level : pe_level;
    assign ewa_visited = afv_cur_q ? av_visited : pe_visited;
    assign ewa_inside  = afv_cur_q ? av_inside : pe_inside;
    assign ewa_flags   = afv_cur_q ? av_flags : pe_flags;
  end else begin : g_no_ewa
    assign ewa_in_ready = 1'b0;
    assign ewa_valid    = 1'b0;
    assign ewa_req      = 1'b0;
    assign ewa_addr     = '0;
    assign texk_ereq    = '0;
    assign texk_eaddr   = '0;
    assign ewa_rgba     = '0;
    assign ewa_level    = '0;
    assign ewa_visited  = '0;
    assign ewa_inside   = '0;
    assign ewa_flags    = '0;
    assign a_req_o      = 1'b0;
    assign a_addr_o     = '0;
    logic unused_ewa;
    assign unused_ewa = ^{f_ae, f_ce, f_be, f_lmaj, f_lmin, f_lod, f_mat.wsrc, f_mat.cap, f_mat.clip, a_data_i, f_afv_side,
                          texk_rgba};
  end
  if (HasBilinear != 0) begin : g_bilinear
    tu_bilinear u_bil (
      .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngBil), .in_ready_o(bil_in_ready),
      .u_i(f_u), .v_i(f_v), .guard_i(f_guard), .level_i(f_mat.tlbase), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
      .wrap_i({f_mat.twrapv, f_mat.twrapu}), .tex_req_o(bil_req), .tex_addr_o(bil_addr), .tex_data_i(tex_rgba),
      .out_valid_o(bil_valid), .out_ready_i(p_ready && os_valid && cur_q == EngBil), .rgba_o(bil_rgba)
    );
  end else begin : g_no_bilinear
    assign bil_in_ready = 1'b0;
    assign bil_valid    = 1'b0;
    assign bil_req      = 1'b0;
    assign bil_addr     = '0;
    assign bil_rgba     = '0;
    logic unused_bil;
    assign unused_bil = ^f_mat.tlbase;  // the base level feeds tu_bilinear and tu_nearest only
  end
  if (HasTriFilter != 0) begin : g_trilinear
    tu_trilinear u_tri (
      .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngTri), .in_ready_o(tri_in_ready),
      .u_i(f_u), .v_i(f_v), .lod_i(f_tlod), .guard_i(f_guard), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
      .wrap_i({f_mat.twrapv, f_mat.twrapu}), .tex_req_o(tri_req), .tex_addr_o(tri_addr), .tex_data_i(tex_rgba),
      .out_valid_o(tri_valid), .out_ready_i(p_ready && os_valid && cur_q == EngTri), .rgba_o(tri_rgba),
      .level_o(tri_level)
    );
  end else begin : g_no_trilinear
    assign tri_in_ready = 1'b0;
    assign tri_valid    = 1'b0;
    assign tri_req      = 1'b0;
    assign tri_addr     = '0;
    assign tri_rgba     = '0;
    assign tri_level    = '0;
    logic unused_tri;
    assign unused_tri = ^f_tlod;  // the GL LOD feeds tu_trilinear only
  end
  if (HasNearest != 0) begin : g_nearest
    tu_nearest u_nst (
      .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngNst), .in_ready_o(nst_in_ready),
      .u_i(f_u), .v_i(f_v), .guard_i(f_guard), .level_i(f_mat.tlbase), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
      .wrap_i({f_mat.twrapv, f_mat.twrapu}), .tex_req_o(nst_req), .tex_addr_o(nst_addr), .tex_data_i(tex_rgba),
      .out_valid_o(nst_valid), .out_ready_i(p_ready && os_valid && cur_q == EngNst), .rgba_o(nst_rgba)
    );
  end else begin : g_no_nearest
    assign nst_in_ready = 1'b0;
    assign nst_valid    = 1'b0;
    assign nst_req      = 1'b0;
    assign nst_addr     = '0;
    assign nst_rgba     = '0;
    logic unused_nst;
    assign unused_nst = ^f_mat.tlbase;
  end
  logic [3:0]                           fel_level;
  logic [tu_formats_pkg::EwaCountW-1:0] fel_texels;
  logic [tu_formats_pkg::FelProbeW-1:0] fel_probes;
  if (HasFeline != 0) begin : g_feline
    logic [2:0] fel_flags_unused;
    tu_feline u_fel (
      .clk_i, .rst_ni, .in_valid_i(eng_in_valid && sel == EngFel), .in_ready_o(fel_in_ready),
      .u_i(f_u), .v_i(f_v), .ae_i(f_ae), .ce_i(f_ce), .be_i(f_be), .lmaj_i(f_lmaj), .lmin_i(f_lmin),
      .lrho_i(f_lrho), .eflags_i(f_eflags), .guard_i(f_guard), .nmax_i(f_mat.fnmax),
      .bias_i(f_mat.lbias), .minlod_i(f_mat.lminlod), .maxlod_i(f_mat.lmaxlod), .lbase_i(f_mat.tlbase),
      .ltop_i(f_mat.ltop), .base_i(f_mat.tbase), .lw_i(f_mat.tlw), .lh_i(f_mat.tlh),
      .wrap_i({f_mat.twrapv, f_mat.twrapu}), .tex_req_o(fel_req), .tex_addr_o(fel_addr), .tex_data_i(tex_rgba),
      .out_valid_o(fel_valid), .out_ready_i(p_ready && os_valid && cur_q == EngFel),
      .rgba_o(fel_rgba), .level_o(fel_level), .texels_o(fel_texels), .probes_o(fel_probes),
      .flags_o(fel_flags_unused)
    );
    logic unused_fel;
    assign unused_fel = ^fel_flags_unused;  // not in the unit's output record
  end else begin : g_no_feline
    assign fel_in_ready = 1'b0;
    assign fel_valid    = 1'b0;
    assign fel_req      = 1'b0;
    assign fel_addr     = '0;
    assign fel_rgba     = '0;
    assign fel_level    = '0;
    assign fel_texels   = '0;
    assign fel_probes   = '0;
    logic unused_fel;
    assign unused_fel = ^{f_mat.fnmax, f_mat.lbias, f_mat.lminlod, f_mat.lmaxlod, f_mat.ltop};
  end
  // Noise unit: a procedural pixel's colour from tu_noise_unit at (u, v) with lrho, no texels.
  if (HasNoise != 0) begin : g_noise
    localparam int NzCntW = $clog2(tu_formats_pkg::NoiseWaterLatency + 2);
    logic [NzCntW-1:0] nz_inflight_q;
    logic              nz_fire_in, nz_fire_out;
    assign nz_fire_in  = fq_valid && f_noise && fq_ready;
    assign nz_fire_out = nz_valid && p_ready;
    tu_noise_unit #(.Dims(NoiseDims), .Octaves(NoiseCores), .SideW(OsW), .HasWater(HasWater),
                    .Serial(NoiseScheme)) u_noise (
      .clk_i, .rst_ni, .in_valid_i(fq_valid && f_noise && inflight_q == '0), .in_ready_o(nz_in_ready),
      .u_i(f_u), .v_i(f_v), .guard_i(f_guard), .lrho_i(f_lrho), .proc_i(f_pix.proc),
      .side_i({f_pix.x, f_pix.y, f_pix.ovf, f_guard, f_eflags, f_rr}),
      .out_valid_o(nz_valid), .out_ready_i(p_ready), .rgba_o(nz_rgba), .side_o(nz_side)
    );
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) nz_inflight_q <= '0;
      else nz_inflight_q <= nz_inflight_q + NzCntW'(nz_fire_in) - NzCntW'(nz_fire_out);
    end
    assign nz_busy = nz_inflight_q != '0;
  end else begin : g_no_noise
    assign nz_busy     = 1'b0;
    assign nz_in_ready = 1'b0;
    assign nz_valid    = 1'b0;
    assign nz_rgba     = '0;
    assign nz_side     = '0;
    logic unused_noise;
    assign unused_noise = ^{f_lrho, f_pix.proc};
  end
  // Bilinear pixels: level 0, four texels; trilinear: floor(lod), eight; nearest: level 0, one;
  // no EWA flags; Feline: floor(probe lod), its texels, inside = its probes; procedural pixels:
  // none of these.
  assign p_level   = nz_busy ? '0 : cur_q == EngEwa ? ewa_level : cur_q == EngTri ? tri_level :
                     cur_q == EngFel ? fel_level : '0;
  assign p_visited = nz_busy ? '0 : cur_q == EngEwa ? ewa_visited : cur_q == EngFel ? fel_texels
                                     : tu_formats_pkg::EwaCountW'(cur_q == EngTri ? 8 : cur_q == EngNst ? 1 : 4);
  assign p_inside  = nz_busy ? '0 : cur_q == EngEwa ? ewa_inside :
                     cur_q == EngFel ? tu_formats_pkg::EwaCountW'(fel_probes) : '0;
  assign p_flags   = nz_busy || cur_q != EngEwa ? '0 : ewa_flags;


  // ---------------- shading ----------------
  // The filtered pixel joined with its shade word; every other output field rides along.
  localparam int ShSideW = 2 * XW + 4 + 2 * tu_formats_pkg::EwaCountW + 5 + 5 + 2 + RrW;
  if (HasShading != 0) begin : g_shade
    logic sh_in_ready;
    assign p_ready       = sh_in_ready && shade_valid_i;
    assign shade_ready_o = sh_in_ready && p_valid;
    tu_shade #(.Model(ShadeModel), .SideW(ShSideW)) u_shade (
      .clk_i, .rst_ni, .in_valid_i(p_valid && shade_valid_i), .in_ready_o(sh_in_ready),
      .rgba_i(p_rgba), .shade_i,
      .side_i({p_x, p_y, p_level, p_visited, p_inside, p_flags, p_eflags, p_pflags, p_rr}),
      .out_valid_o, .out_ready_i, .rgba_o,
      .side_o({x_o, y_o, level_o, visited_o, inside_o, flags_o, eflags_o, pflags_o, rn_o, rsteps_o, rflags_o})
    );
  end else begin : g_no_shade
    assign p_ready       = out_ready_i;
    assign shade_ready_o = 1'b0;
    assign out_valid_o   = p_valid;
    assign {x_o, y_o, rgba_o, level_o, visited_o, inside_o, flags_o, eflags_o, pflags_o, rn_o, rsteps_o, rflags_o} =
           {p_x, p_y, p_rgba, p_level, p_visited, p_inside, p_flags, p_eflags, p_pflags, p_rr};
    logic unused_shade;
    assign unused_shade = ^{shade_valid_i, shade_i};
  end

  logic unused;
  assign unused = ^{b2_eexp, b2_fm, b2_fexp, ex_pix.fpix.x};  // x slot: filled per pixel

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {x_o, y_o, rgba_o, level_o, visited_o, inside_o, flags_o, eflags_o, pflags_o, rn_o, rsteps_o, rflags_o})
  // The span's fields in three groups: Verilator 5.006 emits broken C++ for the sampled copy of
  // one 1,300-bit value under --assert.
  `TU_ASSERT_HANDSHAKE(InHandshakeB1, in_valid_i, in_ready_o, {a_i, b_i, c_i, d_i, e_i, f_i, g_i, h_i, i_i, x0_i, x1_i, y_i})
  `TU_ASSERT_HANDSHAKE(InHandshakeB2, in_valid_i, in_ready_o, {kux_i, kvx_i, kuy_i, kvy_i, m_i, nn_i})
  `TU_ASSERT_HANDSHAKE(InHandshakeMat, in_valid_i, in_ready_o, {dm_i, dexp_i, laniso_i, maxlod_i, tbase_i, tlw_i, tlh_i, twrap_i, tfmt_i, tsrgb_i,
                                                                 wsrc_i, cap_i, filt_i, fnmax_i, clip_i, rel_i, radapt_i, riter_i, rlayers_i, rscale_i, hbase_i,
                                                                 hlw_i, hlh_i, rdm_i, dlayers_i, dbase_i, afv_i, admin_i, abias_i, arule_i})
  `TU_ASSERT_HANDSHAKE(InHandshakeProc, in_valid_i, in_ready_o, {proc_i})
  `TU_ASSERT_HANDSHAKE(ViewHandshake, view_valid_i, view_ready_o, {view_ok_i, vx_i, vy_i, vz_i, vc_i})
  `TU_ASSERT_HANDSHAKE(ShadeHandshake, shade_valid_i, shade_ready_o, {shade_i})
endmodule
