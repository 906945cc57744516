// Quadratic F_QR = max(0, c (1 - 0.786 u)), II = 1 (brdf_qr.hpp):
//   stage 1: front, A = round_half_up(0.786 u) (u34.24), Wq = max(0, 1 - A) (u25.24)
//   stage 2: F = sat(round_half_up(c Wq >> 36))     Latency BrdfQrLatency = 2.
module tu_brdf_qr (
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
  localparam int Lat = tu_formats_pkg::BrdfQrLatency;
  localparam int AW = UW + 4;
  localparam logic [AW-1:0] One = AW'(1) << WF;
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
  logic [AW-1:0] a;
  tu_brdf_rnd #(.InW(UW + 24), .OutW(AW)) u_rnd_a (
    .x_i((UW + 24)'(u) * (UW + 24)'(tu_formats_pkg::BrdfK786)),
    .sh_i(7'(tu_formats_pkg::BrdfCF + tu_formats_pkg::BrdfKF - WF)), .y_o(a));
  logic [W1-1:0] w, w_q1;
  assign w = a < One ? W1'(One - a) : '0;
  logic [ClW-1:0] c_q1;
  logic [1:0] cf_q1;
  logic [OW-1:0] f, f_q2;
  logic flag_q2;
  tu_brdf_rnd #(.InW(ClW + W1), .OutW(OW)) u_rnd_f (.x_i((ClW + W1)'(c_q1) * (ClW + W1)'(w_q1)),
    .sh_i(7'(tu_formats_pkg::BrdfCF + WF - tu_formats_pkg::BrdfOutF)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      w_q1 <= w;  c_q1 <= c;  cf_q1 <= {cut, flag};
      f_q2 <= cf_q1[1] ? '0 : f;  flag_q2 <= cf_q1[0];
    end
  end
  assign f_o = f_q2;
  assign flag_o = flag_q2;

  logic unused;
  assign unused = ^stage_valid ^ (^n_unused);
endmodule
