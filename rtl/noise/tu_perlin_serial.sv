// Perlin fBm, octave-serial scheme: one noise core reused for the NoiseOctaves octaves of a
// sample (octave i issued at clock i after acceptance, the code shifted left by i), the exact
// sum accumulated as the octaves leave the core, normalised into the output register.
// One sample per K clocks (II = NoiseSerialIi), latency NoiseSerialLatency. The whole datapath
// holds while the output register is full and not taken, so back-pressure loses nothing.
module tu_perlin_serial #(
  parameter int Dims = 3
) (
  input  logic                                        clk_i,
  input  logic                                        rst_ni,
  input  logic                                        in_valid_i,
  output logic                                        in_ready_o,
  input  logic [Dims*tu_formats_pkg::NoiseCoordW-1:0] coord_i,
  output logic                                        out_valid_o,
  input  logic                                        out_ready_i,
  output logic [tu_formats_pkg::NoiseOutW-1:0]        fbm_o
);
  localparam int CW   = tu_formats_pkg::NoiseCoordW;
  localparam int LW   = tu_formats_pkg::NoiseLatW;
  localparam int TF   = tu_formats_pkg::NoiseTF;
  localparam int VW   = tu_formats_pkg::NoiseValW;
  localparam int K    = tu_formats_pkg::NoiseOctaves;
  localparam int AccW = tu_formats_pkg::NoiseAccW;
  localparam int CL   = tu_formats_pkg::NoiseCoreLatency;
  localparam int OctW = $clog2(K);

  logic en;
  logic out_valid_q;
  assign en = !out_valid_q || out_ready_i;

  // ---- issue: octave cnt_q of the held sample (octave 0 straight from the input) ----
  logic [OctW-1:0] cnt_q;
  logic [Dims*CW-1:0] coord_q, coord;
  logic issue;
  assign in_ready_o = en && cnt_q == '0;
  assign coord = cnt_q == '0 ? coord_i : coord_q;
  assign issue = cnt_q != '0 || in_valid_i;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_q <= '0;
    end else if (en && issue) begin
      cnt_q <= cnt_q == OctW'(K - 1) ? '0 : cnt_q + 1'b1;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && cnt_q == '0) coord_q <= coord_i;
  end

  logic [Dims*LW-1:0] lattice;
  logic [Dims*TF-1:0] t;
  for (genvar k = 0; k < Dims; k++) begin : g_axis
    logic [LW+TF-1:0] low;
    assign low = (LW+TF)'(coord[k*CW +: CW] << cnt_q);
    assign lattice[k*LW +: LW] = low[TF +: LW];
    assign t[k*TF +: TF] = low[0 +: TF];
  end
  logic signed [VW-1:0] n;
  tu_noise_core #(.Dims(Dims)) u_core (.clk_i, .en_i(en), .cell_i(lattice), .t_i(t), .noise_o(n));

  // ---- valid and octave tags beside the core ----
  logic            vld_q [CL];
  logic [OctW-1:0] oct_q [CL];
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      for (int s = 0; s < CL; s++) vld_q[s] <= 1'b0;
    end else if (en) begin
      vld_q[0] <= issue;
      for (int s = 1; s < CL; s++) vld_q[s] <= vld_q[s-1];
    end
  end
  always_ff @(posedge clk_i) begin
    if (en) begin
      oct_q[0] <= cnt_q;
      for (int s = 1; s < CL; s++) oct_q[s] <= oct_q[s-1];
    end
  end

  // ---- accumulate, normalise the last octave's sum into the output register ----
  logic signed [AccW-1:0] acc_q, sum;
  logic [tu_formats_pkg::NoiseOutW-1:0] fbm_d, fbm_q;
  logic last;
  assign sum  = (oct_q[CL-1] == '0 ? '0 : acc_q) + (AccW'(n) <<< (OctW'(K - 1) - oct_q[CL-1]));
  assign last = vld_q[CL-1] && oct_q[CL-1] == OctW'(K - 1);
  tu_noise_norm #(.Dims(Dims)) u_norm (.acc_i(sum), .fbm_o(fbm_d));
  always_ff @(posedge clk_i) begin
    if (en && vld_q[CL-1]) acc_q <= sum;
    if (en && last) fbm_q <= fbm_d;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_q <= 1'b0;
    end else if (en) begin
      out_valid_q <= last;
    end
  end
  assign out_valid_o = out_valid_q;
  assign fbm_o = fbm_q;

  logic unused;
  always_comb begin
    unused = 1'b0;
    for (int k = 0; k < Dims; k++) unused = unused ^ (^coord[k*CW + LW + TF +: CW - LW - TF]);
  end
endmodule
