// Schlick F_SH = c / (u + c), II = 1 (brdf_schlick.hpp, the same formats and rounding):
//   stage 1: front, D = u + c (u32.22, exact)      stages 2-5: R, p = recip(D)
//   stage 6: F = sat(round_half_up(c R >> (14 + p)))     Latency BrdfSchlickLatency = 6.
module tu_brdf_schlick (
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
  localparam int Lat = tu_formats_pkg::BrdfSchlickLatency;
  localparam int DUp = tu_formats_pkg::BrdfDF - tu_formats_pkg::BrdfCF;
  localparam int FShift = tu_formats_pkg::BrdfCF + tu_formats_pkg::RecipOutF
                          - tu_formats_pkg::BrdfOutF - tu_formats_pkg::BrdfDF;
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
  assign d = (DW'(u) + DW'(c)) << DUp;
  logic [ClW-1:0] c_q1, c_q5;
  logic [1:0]     cf_q1, cf_q5;
  always_ff @(posedge clk_i) begin
    if (en) begin
      d_q1 <= d;  c_q1 <= c;  cf_q1 <= {cut, flag};
    end
  end

  // Stages 2-5
  logic [RW-1:0] r;
  logic [5:0]    p;
  tu_brdf_recip #(.InW(DW)) u_recip (.clk_i, .en_i(en), .q_i(d_q1), .r_o(r), .p_o(p));
  tu_brdf_delay #(.W(ClW + 2), .Depth(4)) u_dly (.clk_i, .en_i(en), .d_i({c_q1, cf_q1}),
                                                .q_o({c_q5, cf_q5}));

  // Stage 6
  logic [tu_formats_pkg::BrdfOutW-1:0] f, f_q6;
  logic flag_q6;
  tu_brdf_rnd #(.InW(ClW + RW), .OutW(tu_formats_pkg::BrdfOutW)) u_rnd_f (
    .x_i((ClW + RW)'(c_q5) * (ClW + RW)'(r)), .sh_i(7'(FShift) + 7'(p)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      f_q6 <= cf_q5[1] ? '0 : f;  flag_q6 <= cf_q5[0];
    end
  end
  assign f_o = f_q6;
  assign flag_o = flag_q6;

  logic unused;
  assign unused = ^stage_valid ^ (^n_unused);
endmodule
