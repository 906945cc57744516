// Blinn F_B = c^n, LSB-first square-and-multiply over the BrdfNW bits of n, II = 1 (brdf_blinn.hpp):
//   stage 1: front, b = c, r = 1 (u29.28)
//   stages 2-11 (bit i): r = n[i] ? round_half_up(r b) : r, b = round_half_up(b^2);
//   stage 11 also F = round_half_up(r) (u9.8).     Latency BrdfBlinnLatency = 11.
module tu_brdf_blinn (
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
  localparam int OW  = tu_formats_pkg::BrdfOutW;
  localparam int NW  = tu_formats_pkg::BrdfNW;
  localparam int BF  = tu_formats_pkg::BrdfBlinnF;
  localparam int BW  = BF + 1;
  localparam int Lat = tu_formats_pkg::BrdfBlinnLatency;
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
  tu_brdf_front u_front (.c_i, .n_i, .ccut_i, .c_o(c), .u_o(u), .n_o(n), .cut_o(cut),
                         .flag_o(flag));
  logic [NW-1:0] n;
  // Registers of stage k + 1 (k = 0..NW-1) hold r, b before the step for bit k of n.
  logic [BW-1:0] r_q [NW];
  logic [BW-1:0] b_q [NW];
  logic [NW-1:0] n_q [NW];
  logic [1:0]    cf_q [NW];
  logic [BW-1:0] rb [NW];
  logic [BW-1:0] bb [NW];
  logic [BW-1:0] r_next [NW];
  for (genvar k = 0; k < NW; k++) begin : g_step
    tu_brdf_rnd #(.InW(2 * BW), .OutW(BW)) u_rnd_r (
      .x_i((2 * BW)'(r_q[k]) * (2 * BW)'(b_q[k])), .sh_i(7'(BF)), .y_o(rb[k]));
    tu_brdf_rnd #(.InW(2 * BW), .OutW(BW)) u_rnd_b (
      .x_i((2 * BW)'(b_q[k]) * (2 * BW)'(b_q[k])), .sh_i(7'(BF)), .y_o(bb[k]));
    assign r_next[k] = n_q[k][k] ? rb[k] : r_q[k];
  end
  logic [OW-1:0] f, f_q;
  logic flag_q;
  tu_brdf_rnd #(.InW(BW), .OutW(OW)) u_rnd_f (.x_i(r_next[NW-1]),
    .sh_i(7'(BF - tu_formats_pkg::BrdfOutF)), .y_o(f));
  always_ff @(posedge clk_i) begin
    if (en) begin
      b_q[0] <= BW'(c) << (BF - tu_formats_pkg::BrdfCF);
      r_q[0] <= BW'(1) << BF;
      n_q[0] <= n;  cf_q[0] <= {cut, flag};
      for (int k = 1; k < NW; k++) begin
        r_q[k] <= r_next[k-1];  b_q[k] <= bb[k-1];
        n_q[k] <= n_q[k-1];     cf_q[k] <= cf_q[k-1];
      end
      f_q <= cf_q[NW-1][1] ? '0 : f;  flag_q <= cf_q[NW-1][0];
    end
  end
  assign f_o = f_q;
  assign flag_o = flag_q;

  logic unused;
  assign unused = ^stage_valid ^ (^u);
endmodule
