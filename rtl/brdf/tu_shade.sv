// Shading stage of the texture unit (brdf_shade.hpp, same formats and rounding): the filtered
// colour modulated by one light, diffuse + specular, with the BRDF model Model (brdf::Model
// codes: 0 blinn, 1 schlick, 2 msh, 3 dsh, 4 scos2, 5 st16, 6 qr).
//   input (combinational): N.L, N.H exact, rounded half up to BrdfCF and saturated to s(BrdfCW);
//     d = round_half_up(clamp(N.L, 0, 1)) u9.8; fork: c = N.H, n, c_cut to the model's block,
//     the colour, d and the colours to a FIFO (SideW bits of the caller's fields ride along);
//   output (combinational at the join): E = amb + round_half_up(lc d),
//     out = min(255, round_half_up((t E 2^8 + 255 ks F) / 2^16)) per RGB channel.
// Latency: the model's (Brdf*Latency, brdf::shade::latency), II = 1.
module tu_shade #(
  parameter int Model = 2,
  parameter int SideW = 1
) (
  input  logic                                    clk_i,
  input  logic                                    rst_ni,
  input  logic                                    in_valid_i,
  output logic                                    in_ready_o,
  input  logic [31:0]                             rgba_i,
  input  logic [tu_formats_pkg::ShadeWordW-1:0]   shade_i,
  input  logic [SideW-1:0]                        side_i,
  output logic                                    out_valid_o,
  input  logic                                    out_ready_i,
  output logic [31:0]                             rgba_o,
  output logic [SideW-1:0]                        side_o
);
  localparam int VW  = tu_formats_pkg::ShadeVecW;
  localparam int DtW = tu_formats_pkg::ShadeDotW;
  localparam int KW  = tu_formats_pkg::ShadeColW;
  localparam int KF  = tu_formats_pkg::ShadeColF;
  localparam int CW  = tu_formats_pkg::BrdfCW;
  localparam int CF  = tu_formats_pkg::BrdfCF;
  localparam int NW  = tu_formats_pkg::BrdfNW;
  localparam int ClW = tu_formats_pkg::BrdfClW;
  localparam int OW  = tu_formats_pkg::BrdfOutW;
  localparam int DdW = tu_formats_pkg::ShadeDiffW;
  localparam int EW  = tu_formats_pkg::ShadeEW;
  localparam int Down = 2 * tu_formats_pkg::ShadeVecF - CF;

  // shade word, from the least significant bit up: amb, lc b g r, ks b g r, c_cut, n, H, L, N, on
  localparam int PosLc = KW, PosKs = 4 * KW, PosCut = 7 * KW, PosN = PosCut + ClW, PosH = PosN + NW;
  localparam int PosL = PosH + 3 * VW, PosNv = PosL + 3 * VW, PosOn = PosNv + 3 * VW;
  logic [KW-1:0]  amb;
  logic [3*KW-1:0] lc, ks;
  logic [ClW-1:0] ccut;
  logic [NW-1:0]  nexp;
  logic [VW-1:0]  hx, hy, hz, lx, ly, lz, nx, ny, nz;
  logic           on;
  assign amb  = shade_i[0 +: KW];
  assign lc   = shade_i[PosLc +: 3 * KW];
  assign ks   = shade_i[PosKs +: 3 * KW];
  assign ccut = shade_i[PosCut +: ClW];
  assign nexp = shade_i[PosN +: NW];
  assign {hx, hy, hz} = shade_i[PosH +: 3 * VW];
  assign {lx, ly, lz} = shade_i[PosL +: 3 * VW];
  assign {nx, ny, nz} = shade_i[PosNv +: 3 * VW];
  assign on   = shade_i[PosOn];
  logic unused_word;
  assign unused_word = ^shade_i[tu_formats_pkg::ShadeWordW-1:PosOn+1];

  // N.L, N.H: exact sums of products, round half up (floor of + half), saturate to s(BrdfCW)
  function automatic logic [CW-1:0] dot3(input logic [VW-1:0] ax, input logic [VW-1:0] ay,
                                         input logic [VW-1:0] az, input logic [VW-1:0] bx,
                                         input logic [VW-1:0] by, input logic [VW-1:0] bz);
    logic signed [DtW-1:0] s, r, xa, ya, za, xb, yb, zb;
    // sign-extended to DtW bits first (the products are then exact)
    xa = {{(DtW - VW){ax[VW-1]}}, ax};  ya = {{(DtW - VW){ay[VW-1]}}, ay};  za = {{(DtW - VW){az[VW-1]}}, az};
    xb = {{(DtW - VW){bx[VW-1]}}, bx};  yb = {{(DtW - VW){by[VW-1]}}, by};  zb = {{(DtW - VW){bz[VW-1]}}, bz};
    s = xa * xb + ya * yb + za * zb;
    r = (s + (DtW'(1) <<< (Down - 1))) >>> Down;
    if (r > $signed(DtW'((1 << (CW - 1)) - 1)))       dot3 = {1'b0, {(CW - 1){1'b1}}};
    else if (r < -$signed(DtW'(1 << (CW - 1))))       dot3 = {1'b1, {(CW - 1){1'b0}}};
    else                                              dot3 = r[CW-1:0];
  endfunction
  logic [CW-1:0] nl, nh;
  assign nl = dot3(nx, ny, nz, lx, ly, lz);
  assign nh = dot3(nx, ny, nz, hx, hy, hz);
  logic          lit;  // N.L > 0: the highlight exists
  logic [CW-1:0] dcl;
  logic [DdW-1:0] d;
  assign lit = !nl[CW-1] && nl != '0;
  assign dcl = nl[CW-1] ? '0 : (nl > CW'(1 << CF)) ? CW'(1 << CF) : nl;
  assign d   = DdW'((dcl + CW'(1 << (CF - KF - 1))) >> (CF - KF));

  // fork: the model's block and the FIFO of everything else; join at the output
  localparam int QW = 32 + DdW + 2 + 7 * KW + SideW;
  logic b_in_ready, q_in_ready, b_valid, q_valid, b_flag;
  logic [OW-1:0] b_f;
  logic [QW-1:0] q_data;
  assign in_ready_o = b_in_ready && q_in_ready;
  logic b_in_valid, b_out_ready;
  assign b_in_valid  = in_valid_i && q_in_ready;
  assign b_out_ready = out_ready_i && q_valid;
  if (Model == 0) begin : g_blinn
    tu_brdf_blinn u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                       .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else if (Model == 1) begin : g_schlick
    tu_brdf_schlick u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                         .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else if (Model == 3) begin : g_dsh
    tu_brdf_dsh u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                     .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else if (Model == 4) begin : g_scos2
    tu_brdf_scos2 u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                       .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else if (Model == 5) begin : g_st16
    tu_brdf_st16 u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                      .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else if (Model == 6) begin : g_qr
    tu_brdf_qr u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                    .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end else begin : g_msh
    tu_brdf_msh u_m (.clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready), .c_i(nh), .n_i(nexp),
                     .ccut_i(ccut), .out_valid_o(b_valid), .out_ready_i(b_out_ready), .f_o(b_f), .flag_o(b_flag));
  end
  // Holds the pixels inside the model's pipeline (at most its latency + 1 <= 12).
  tu_fifo #(.Width(QW), .Depth(16)) u_side (
    .clk_i, .rst_ni, .in_valid_i(in_valid_i && b_in_ready), .in_ready_o(q_in_ready),
    .in_data_i({rgba_i, d, on, lit, ks, lc, amb, side_i}), .out_valid_o(q_valid),
    .out_ready_i(out_ready_i && b_valid), .out_data_o(q_data)
  );
  assign out_valid_o = b_valid && q_valid;

  logic [31:0]    t;
  logic [DdW-1:0] q_d;
  logic           q_on, q_lit;
  logic [3*KW-1:0] q_ks, q_lc;
  logic [KW-1:0]  q_amb;
  assign {t, q_d, q_on, q_lit, q_ks, q_lc, q_amb, side_o} = q_data;
  logic [OW-1:0] f;
  assign f = q_lit ? b_f : '0;  // no highlight with the light behind the surface
  logic [23:0] shaded;
  for (genvar ch = 0; ch < 3; ch++) begin : g_ch
    // channel ch: r = 0 (bits 7:0 of rgba, ks / lc most significant), g = 1, b = 2
    logic [KW-1:0] lck, ksk;
    logic [EW-1:0] e;
    logic [27:0]   acc;
    assign lck = q_lc[(2 - ch) * KW +: KW];
    assign ksk = q_ks[(2 - ch) * KW +: KW];
    assign e   = EW'(q_amb) + EW'(((KW + DdW)'(lck) * (KW + DdW)'(q_d) + (KW + DdW)'(1 << (KF - 1))) >> KF);
    assign acc = ((28'(t[8 * ch +: 8]) * 28'(e)) << KF) + 28'(255) * 28'(ksk) * 28'(f) + 28'(1 << (2 * KF - 1));
    assign shaded[8 * ch +: 8] = (acc >> (2 * KF)) > 28'(255) ? 8'd255 : acc[2 * KF +: 8];
  end
  assign rgba_o = q_on ? {t[31:24], shaded} : t;

  logic unused;
  assign unused = b_flag;
endmodule
