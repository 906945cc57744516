// Perlin fBm, pipelined scheme: one sample with all NoiseOctaves octaves per clock, one noise core
// per octave (core i sees the code shifted left by i = 2^i x), then the exact sum and the
// normalisation. Latency NoisePipeLatency, II = 1. coord_i[32k +: 32] = axis k (s32.16).
module tu_perlin_pipe #(
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
  localparam int CW  = tu_formats_pkg::NoiseCoordW;
  localparam int LW  = tu_formats_pkg::NoiseLatW;
  localparam int TF  = tu_formats_pkg::NoiseTF;
  localparam int VW  = tu_formats_pkg::NoiseValW;
  localparam int K   = tu_formats_pkg::NoiseOctaves;
  localparam int AccW = tu_formats_pkg::NoiseAccW;
  localparam int Lat = tu_formats_pkg::NoisePipeLatency;

  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  logic signed [VW-1:0] n [K];
  for (genvar i = 0; i < K; i++) begin : g_oct
    logic [Dims*LW-1:0] lattice;
    logic [Dims*TF-1:0] t;
    for (genvar k = 0; k < Dims; k++) begin : g_axis
      logic [LW+TF-1:0] low;  // lattice index and fraction of 2^i x
      assign low = (LW+TF)'(coord_i[k*CW +: CW] << i);
      assign lattice[k*LW +: LW] = low[TF +: LW];
      assign t[k*TF +: TF] = low[0 +: TF];
    end
    tu_noise_core #(.Dims(Dims)) u_core (.clk_i, .en_i(en), .cell_i(lattice), .t_i(t), .noise_o(n[i]));
  end

  logic signed [AccW-1:0] acc;
  always_comb begin
    acc = '0;
    for (int i = 0; i < K; i++) acc = acc + (AccW'(n[i]) <<< (K - 1 - i));
  end
  logic [tu_formats_pkg::NoiseOutW-1:0] fbm_d, fbm_q;
  tu_noise_norm #(.Dims(Dims)) u_norm (.acc_i(acc), .fbm_o(fbm_d));
  always_ff @(posedge clk_i) begin
    if (en) fbm_q <= fbm_d;
  end
  assign fbm_o = fbm_q;

  // The bits above the lattice index wrap away (period 256); valid bits live in u_ctrl.
  logic unused;
  always_comb begin
    unused = ^stage_valid;
    for (int k = 0; k < Dims; k++) unused = unused ^ (^coord_i[k*CW + LW + TF +: CW - LW - TF]);
  end
endmodule
