// Two-generating-function F_dsh = max(0, (F_SH + G) / 2), G = 2 (c+0.1)^8 / E - 0.25,
// E = 1.953125 (u + c^8)^2 + 1.5, II = 1 (brdf_dsh.hpp, the same formats and rounding):
//   stage 1: front, D_SH = u + c (u32.22, exact), c^2, q = c + 0.1     stages 2-5: recip(D_SH)
//   stages 2-4: c^4, c^8 and q^2, q^4, q^8 (half up, 24 fraction bits); stage 4: w = u + c^8
//   stage 5: w2 = round_half_up(w^2)     stage 6: E = 125 w2 + 1.5 (30 fraction bits), S = c / D_SH
//   stages 7-10: recip(E)     stage 11: G1 = 2 q^8 / E, F = round_half_up(max(0, S + G1 - 1/4) / 2)
// Latency BrdfDshLatency = 11.
module tu_brdf_dsh (
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
  localparam int QW  = WF + 2;   // (c + 0.1)^k <= 2.144
  localparam int WW  = UW + 4;   // w = u + c^8 with WF fraction bits
  localparam int W2W = 44;       // w^2 <= 1001^2, WF fraction bits
  localparam int EW  = tu_formats_pkg::BrdfEW;
  localparam int DW  = tu_formats_pkg::BrdfDW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int OW  = tu_formats_pkg::BrdfOutW;
  localparam int Lat = tu_formats_pkg::BrdfDshLatency;
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
  assign d = (DW'(u) + DW'(c)) << (tu_formats_pkg::BrdfDF - tu_formats_pkg::BrdfCF);
  logic [W1-1:0] c2, c2_q1, c4, c4_q2, c8, c8_q3;
  tu_brdf_rnd #(.InW(2 * ClW), .OutW(W1)) u_rnd_c2 (.x_i((2 * ClW)'(c) * (2 * ClW)'(c)),
    .sh_i(7'(2 * tu_formats_pkg::BrdfCF - WF)), .y_o(c2));
  logic [QW-1:0] q, q_q1, q2, q2_q2, q4, q4_q3, q8, q8_q4;
  assign q = (QW'(c) << (WF - tu_formats_pkg::BrdfCF)) + QW'(tu_formats_pkg::BrdfK01);
  logic [ClW-1:0] c_q1, c_q5;
  logic [UW-1:0]  u_q1, u_q2, u_q3;
  logic [1:0]     cf_q1, cf_q6, cf_q10;
  always_ff @(posedge clk_i) begin
    if (en) begin
      d_q1 <= d;  c2_q1 <= c2;  q_q1 <= q;  c_q1 <= c;  u_q1 <= u;  cf_q1 <= {cut, flag};
    end
  end

  // Stages 2-4: the two eighth powers; stage 4 adds w = u + c^8.
  tu_brdf_rnd #(.InW(2 * W1), .OutW(W1)) u_rnd_c4 (.x_i((2 * W1)'(c2_q1) * (2 * W1)'(c2_q1)),
    .sh_i(7'(WF)), .y_o(c4));
  tu_brdf_rnd #(.InW(2 * W1), .OutW(W1)) u_rnd_c8 (.x_i((2 * W1)'(c4_q2) * (2 * W1)'(c4_q2)),
    .sh_i(7'(WF)), .y_o(c8));
  tu_brdf_rnd #(.InW(2 * QW), .OutW(QW)) u_rnd_q2 (.x_i((2 * QW)'(q_q1) * (2 * QW)'(q_q1)),
    .sh_i(7'(WF)), .y_o(q2));
  tu_brdf_rnd #(.InW(2 * QW), .OutW(QW)) u_rnd_q4 (.x_i((2 * QW)'(q2_q2) * (2 * QW)'(q2_q2)),
    .sh_i(7'(WF)), .y_o(q4));
  tu_brdf_rnd #(.InW(2 * QW), .OutW(QW)) u_rnd_q8 (.x_i((2 * QW)'(q4_q3) * (2 * QW)'(q4_q3)),
    .sh_i(7'(WF)), .y_o(q8));
  logic [WW-1:0] w_q4;
  always_ff @(posedge clk_i) begin
    if (en) begin
      c4_q2 <= c4;  q2_q2 <= q2;  u_q2 <= u_q1;
      q4_q3 <= q4;  c8_q3 <= c8;  u_q3 <= u_q2;
      w_q4  <= (WW'(u_q3) << (WF - tu_formats_pkg::BrdfCF)) + WW'(c8_q3);
      q8_q4 <= q8;
    end
  end

  // Schlick's reciprocal, stages 2-5; c and the flags ride along.
  logic [RW-1:0] rs;
  logic [5:0]    ps;
  tu_brdf_recip #(.InW(DW)) u_recip_s (.clk_i, .en_i(en), .q_i(d_q1), .r_o(rs), .p_o(ps));
  logic [1:0] cf_q5;
  tu_brdf_delay #(.W(ClW + 2), .Depth(4)) u_dly_c (.clk_i, .en_i(en), .d_i({c_q1, cf_q1}),
                                                  .q_o({c_q5, cf_q5}));

  // Stage 5: w^2.  Stage 6: E, S.
  logic [W2W-1:0] w2, w2_q5;
  tu_brdf_rnd #(.InW(2 * WW), .OutW(W2W)) u_rnd_w2 (.x_i((2 * WW)'(w_q4) * (2 * WW)'(w_q4)),
    .sh_i(7'(WF)), .y_o(w2));
  logic [QW-1:0] q8_q5;
  logic [W1-1:0] s, s_q6, s_q10;
  tu_brdf_rnd #(.InW(ClW + RW), .OutW(W1)) u_rnd_s (.x_i((ClW + RW)'(c_q5) * (ClW + RW)'(rs)),
    .sh_i(7'(ps) - 7'(tu_formats_pkg::BrdfDF + WF - tu_formats_pkg::BrdfCF - tu_formats_pkg::RecipOutF)),
    .y_o(s));
  logic [EW-1:0] e_q6;
  logic [QW-1:0] q8_q6, q8_q10;
  always_ff @(posedge clk_i) begin
    if (en) begin
      w2_q5 <= w2;  q8_q5 <= q8_q4;
      e_q6  <= EW'(w2_q5) * EW'(125) + (EW'(3) << (tu_formats_pkg::BrdfEF - 1));
      s_q6  <= s;  q8_q6 <= q8_q5;  cf_q6 <= cf_q5;
    end
  end

  // Stages 7-10: 1/E.
  logic [RW-1:0] re;
  logic [5:0]    pe;
  tu_brdf_recip #(.InW(EW)) u_recip_e (.clk_i, .en_i(en), .q_i(e_q6), .r_o(re), .p_o(pe));
  tu_brdf_delay #(.W(W1 + QW + 2), .Depth(4)) u_dly_s (.clk_i, .en_i(en),
    .d_i({s_q6, q8_q6, cf_q6}), .q_o({s_q10, q8_q10, cf_q10}));

  // Stage 11
  logic [QW:0] g1;
  tu_brdf_rnd #(.InW(QW + RW), .OutW(QW + 1)) u_rnd_g (.x_i((QW + RW)'(q8_q10) * (QW + RW)'(re)),
    .sh_i(7'(pe) - 7'(tu_formats_pkg::BrdfEF + 1 - tu_formats_pkg::RecipOutF)), .y_o(g1));
  logic [QW+1:0] sum;
  logic [OW-1:0] f, f_q11;
  logic flag_q11;
  localparam logic [QW+1:0] Quarter = (QW+2)'(1) << (WF - 2);
  assign sum = (QW+2)'(s_q10) + (QW+2)'(g1);
  tu_brdf_rnd #(.InW(QW + 2), .OutW(OW)) u_rnd_f (.x_i(sum > Quarter ? sum - Quarter : '0),
    .sh_i(7'(WF - tu_formats_pkg::BrdfOutF + 1)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      f_q11 <= cf_q10[1] ? '0 : f;  flag_q11 <= cf_q10[0];
    end
  end
  assign f_o = f_q11;
  assign flag_o = flag_q11;

  logic unused;
  assign unused = ^stage_valid ^ (^n_unused);
endmodule
