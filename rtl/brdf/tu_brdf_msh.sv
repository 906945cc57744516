// Modified Schlick F_MSH = 1.6 c / (u + 1.25 c)^2, II = 1 (brdf_msh.hpp, same formats/rounding):
//   stage 1: front, D = u + c + c/4 (u32.22, exact), KC = round_half_up(1.6 c) (u25.24)
//   stages 2-5: R, p = recip(D)     stage 6: R2 = round_half_up(R^2) (u25.24)
//   stage 7: F = sat(round_half_up(KC R2 >> (2p - 4)))     Latency BrdfMshLatency = 7.
module tu_brdf_msh (
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
  localparam int DW  = tu_formats_pkg::BrdfDW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int WF  = tu_formats_pkg::BrdfWF;
  localparam int W1  = WF + 1;
  localparam int Lat = tu_formats_pkg::BrdfMshLatency;
  localparam int FDown = 2 * tu_formats_pkg::BrdfDF + tu_formats_pkg::BrdfOutF - 2 * WF;  // shift 2p - FDown
  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // Stage 1: D from u + 1.25c at CF + 2 fraction bits; KC = 1.6 c.
  logic [ClW-1:0] c;
  logic [UW-1:0]  u;
  logic           cut, flag;
  logic [tu_formats_pkg::BrdfNW-1:0] n_unused;
  tu_brdf_front u_front (.c_i, .n_i, .ccut_i, .c_o(c), .u_o(u), .n_o(n_unused), .cut_o(cut),
                         .flag_o(flag));
  logic [DW-1:0] d, d_q1;
  logic [W1-1:0] kc, kc_q1, kc_q5, kc_q6;
  // u + 1.25c with CF + 2 = DF fraction bits
  assign d = (DW'(u) << 2) + (DW'(c) << 2) + DW'(c);
  tu_brdf_rnd #(.InW(ClW + 26), .OutW(W1)) u_rnd_kc (
    .x_i((ClW + 26)'(c) * (ClW + 26)'(tu_formats_pkg::BrdfK16)),
    .sh_i(7'(tu_formats_pkg::BrdfCF + tu_formats_pkg::BrdfKF - WF)), .y_o(kc));
  logic [1:0] cf_q1, cf_q5, cf_q6;
  always_ff @(posedge clk_i) begin
    if (en) begin
      d_q1 <= d;  kc_q1 <= kc;  cf_q1 <= {cut, flag};
    end
  end

  // Stages 2-5
  logic [RW-1:0] r;
  logic [5:0]    p;
  tu_brdf_recip #(.InW(DW)) u_recip (.clk_i, .en_i(en), .q_i(d_q1), .r_o(r), .p_o(p));
  tu_brdf_delay #(.W(W1 + 2), .Depth(4)) u_dly (.clk_i, .en_i(en), .d_i({kc_q1, cf_q1}),
                                               .q_o({kc_q5, cf_q5}));

  // Stage 6: R^2
  logic [W1-1:0] r2, r2_q6;
  logic [5:0]    p_q6;
  tu_brdf_rnd #(.InW(2 * RW), .OutW(W1)) u_rnd_r2 (
    .x_i((2 * RW)'(r) * (2 * RW)'(r)), .sh_i(7'(2 * tu_formats_pkg::RecipOutF - WF)), .y_o(r2));
  always_ff @(posedge clk_i) begin
    if (en) begin
      r2_q6 <= r2;  kc_q6 <= kc_q5;  p_q6 <= p;  cf_q6 <= cf_q5;
    end
  end

  // Stage 7
  logic [tu_formats_pkg::BrdfOutW-1:0] f, f_q7;
  logic flag_q7;
  tu_brdf_rnd #(.InW(2 * W1), .OutW(tu_formats_pkg::BrdfOutW)) u_rnd_f (
    .x_i((2 * W1)'(kc_q6) * (2 * W1)'(r2_q6)), .sh_i(7'({p_q6, 1'b0}) - 7'(FDown)), .y_o(f));
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
