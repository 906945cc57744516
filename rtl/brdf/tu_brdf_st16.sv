// Cosine-"power" F_ST16 = max(0, 1 - u/16)^16, four squarings, II = 1 (brdf_st16.hpp):
//   stage 1: front, B = max(0, 1 - u/16) (u25.24: u's raw code read with 24 fraction bits)
//   stages 2-5: S = round_half_up(S^2) (u25.24); stage 5 also F = round_half_up(S4) (u9.8).
//   Latency BrdfSt16Latency = 5.
module tu_brdf_st16 (
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
  localparam int Lat = tu_formats_pkg::BrdfSt16Latency;
  localparam logic [UW:0] One = (UW+1)'(1) << WF;
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
  logic [W1-1:0] b;
  assign b = (UW+1)'(u) < One ? W1'(One - (UW+1)'(u)) : '0;
  // s_q[0] = B (stage 1), s_q[k] = S_k (stage k + 1); the fourth square feeds the output stage.
  logic [W1-1:0] s_q [4];
  logic [W1-1:0] sq [4];
  logic [1:0]    cf_q [4];
  for (genvar k = 0; k < 4; k++) begin : g_sq
    tu_brdf_rnd #(.InW(2 * W1), .OutW(W1)) u_rnd (
      .x_i((2 * W1)'(s_q[k]) * (2 * W1)'(s_q[k])), .sh_i(7'(WF)), .y_o(sq[k]));
  end
  logic [OW-1:0] f, f_q5;
  logic flag_q5;
  tu_brdf_rnd #(.InW(W1), .OutW(OW)) u_rnd_f (.x_i(sq[3]),
    .sh_i(7'(WF - tu_formats_pkg::BrdfOutF)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      s_q[0] <= b;  cf_q[0] <= {cut, flag};
      for (int k = 1; k < 4; k++) begin
        s_q[k] <= sq[k-1];  cf_q[k] <= cf_q[k-1];
      end
      f_q5 <= cf_q[3][1] ? '0 : f;  flag_q5 <= cf_q[3][0];
    end
  end
  assign f_o = f_q5;
  assign flag_o = flag_q5;

  logic unused;
  assign unused = ^stage_valid ^ (^n_unused) ^ (^c);
endmodule
