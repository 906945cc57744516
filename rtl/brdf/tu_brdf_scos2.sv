// Modified cosine-quadratic F_SCOS2 = max(0, (2c - 0.1u) / (u + 2c))^2, II = 1 (brdf_scos2.hpp):
//   stage 1: front, D = u + 2c (u32.22, exact), N = max(0, 2c - round_half_up(0.1 u))
//   stages 2-5: R, p = recip(D)     stage 6: B = sat(round_half_up(N R >> (p - 2))) (u25.24)
//   stage 7: F = sat(round_half_up(B^2 >> 40))     Latency BrdfScos2Latency = 7.
module tu_brdf_scos2 (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               in_valid_i,
  output logic                               in_ready_o,
  input  logic [tu_formats_pkg::BrdfCW-1:0]  c_i,
  input  logic [tu_formats_pkg::BrdfNW-1:0]  n_i,
  input  logic [tu_formats_pkg::BrdfClW-1:0] ccut_i,
  output logic                               out_valid_o,
  input  logic                               out_ready_i,
  output logic [tu_formats_pkg::BrdfOutW-1:0] f_o,
  output logic                               flag_o
);
  localparam int ClW = tu_formats_pkg::BrdfClW;
  localparam int UW  = tu_formats_pkg::BrdfUW;
  localparam int WF  = tu_formats_pkg::BrdfWF;
  localparam int W1  = WF + 1;
  localparam int OW  = tu_formats_pkg::BrdfOutW;
  localparam int DW  = tu_formats_pkg::BrdfDW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int NumW = ClW + 1;
  localparam int Lat = tu_formats_pkg::BrdfScos2Latency;
  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // Stage 1
  logic [ClW-1:0] c;
  logic [UW-1:0]  u;
  logic           cut, flag;
  logic [tu_formats_pkg::BrdfNW-1:0] n_unused;
  tu_brdf_front u_front (.c_i, .n_i, .ccut_i, .c_o(c), .u_o(u), .n_o(n_unused), .cut_o(cut),
                         .flag_o(flag));
  logic [DW-1:0] d, d_q1;
  assign d = (DW'(u) + (DW'(c) << 1)) << (tu_formats_pkg::BrdfDF - tu_formats_pkg::BrdfCF);
  logic [UW-1:0] tenth;
  tu_brdf_rnd #(.InW(UW + 21), .OutW(UW)) u_rnd_t (
    .x_i((UW + 21)'(u) * (UW + 21)'(tu_formats_pkg::BrdfK01)),
    .sh_i(7'(tu_formats_pkg::BrdfKF)), .y_o(tenth));
  logic [NumW-1:0] num, num_q1, num_q5;
  assign num = ((UW)'(c) << 1) > tenth ? NumW'(((UW)'(c) << 1) - tenth) : '0;
  logic [1:0] cf_q1, cf_q5, cf_q6;
  always_ff @(posedge clk_i) begin
    if (en) begin
      d_q1 <= d;  num_q1 <= num;  cf_q1 <= {cut, flag};
    end
  end

  // Stages 2-5
  logic [RW-1:0] r;
  logic [5:0]    p;
  tu_brdf_recip #(.InW(DW)) u_recip (.clk_i, .en_i(en), .q_i(d_q1), .r_o(r), .p_o(p));
  tu_brdf_delay #(.W(NumW + 2), .Depth(4)) u_dly (.clk_i, .en_i(en), .d_i({num_q1, cf_q1}),
                                                 .q_o({num_q5, cf_q5}));

  // Stage 6: the base, <= 1
  logic [W1-1:0] b, b_q6;
  tu_brdf_rnd #(.InW(NumW + RW), .OutW(W1)) u_rnd_b (
    .x_i((NumW + RW)'(num_q5) * (NumW + RW)'(r)),
    .sh_i(7'(p) - 7'(tu_formats_pkg::BrdfDF + WF - tu_formats_pkg::BrdfCF - tu_formats_pkg::RecipOutF)),
    .y_o(b));
  always_ff @(posedge clk_i) begin
    if (en) begin
      b_q6 <= b;  cf_q6 <= cf_q5;
    end
  end

  // Stage 7
  logic [OW-1:0] f, f_q7;
  logic flag_q7;
  tu_brdf_rnd #(.InW(2 * W1), .OutW(OW)) u_rnd_f (.x_i((2 * W1)'(b_q6) * (2 * W1)'(b_q6)),
    .sh_i(7'(2 * WF - tu_formats_pkg::BrdfOutF)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      f_q7 <= cf_q6[1] ? '0 : f;  flag_q7 <= cf_q6[0];
    end
  end
  assign f_o = f_q7;
  assign flag_o = flag_q7;

  logic unused;
  assign unused = ^stage_valid ^ (^n_unused);
endmodule
