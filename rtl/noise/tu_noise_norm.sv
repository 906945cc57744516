// fBm normalisation (cmodel/blocks/noise/noise_fbm.hpp fbm_normalise), combinational:
//   fbm = clamp(round_half_up(acc * C + 1/2), 0, 1),   C = NoiseNorm3 (Dims 3) or NoiseNorm2.
// acc: exact octave sum, NoiseTF + NoiseOctaves - 1 fraction bits; fbm u17.16.
module tu_noise_norm #(
  parameter int Dims = 3
) (
  input  logic signed [tu_formats_pkg::NoiseAccW-1:0] acc_i,
  output logic [tu_formats_pkg::NoiseOutW-1:0]        fbm_o
);
  localparam int AccW  = tu_formats_pkg::NoiseAccW;
  localparam int NormW = tu_formats_pkg::NoiseNormW;
  localparam int ProdF = tu_formats_pkg::NoiseTF + tu_formats_pkg::NoiseOctaves - 1 + tu_formats_pkg::NoiseNormF;
  localparam int Drop  = ProdF - tu_formats_pkg::NoiseTF;
  localparam int PW    = AccW + NormW + 2;
  localparam int OW    = tu_formats_pkg::NoiseOutW;
  localparam logic [NormW-1:0] Norm = NormW'(Dims == 2 ? tu_formats_pkg::NoiseNorm2 : tu_formats_pkg::NoiseNorm3);

  logic signed [PW-1:0] prod;
  logic signed [PW-1:0] q;
  always_comb begin
    prod = PW'(acc_i) * $signed({2'b0, Norm});
    q = (prod + (PW'(1) <<< (ProdF - 1)) + (PW'(1) <<< (Drop - 1))) >>> Drop;
    if (q < 0) fbm_o = '0;
    else if (q > PW'(1 << tu_formats_pkg::NoiseTF)) fbm_o = OW'(1 << tu_formats_pkg::NoiseTF);
    else fbm_o = OW'(q);
  end
endmodule
