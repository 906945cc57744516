// L = a + round_half_up(s (b - a)), s u17.16 in [0,1], a, b, L s19.16; L lies between a and b.
// Same as cmodel/blocks/noise/noise_lerp.hpp (0.5 ULP).
module tu_noise_lerp (
  input  logic [tu_formats_pkg::NoiseSW-1:0]          s_i,
  input  logic signed [tu_formats_pkg::NoiseValW-1:0] a_i,
  input  logic signed [tu_formats_pkg::NoiseValW-1:0] b_i,
  output logic signed [tu_formats_pkg::NoiseValW-1:0] l_o
);
  localparam int VW = tu_formats_pkg::NoiseValW;
  localparam int SW = tu_formats_pkg::NoiseSW;
  localparam int TF = tu_formats_pkg::NoiseTF;
  logic signed [VW:0]        diff;
  logic signed [VW+SW+1:0]   prod;
  logic signed [VW:0]        step;
  always_comb begin
    diff = (VW+1)'(b_i) - (VW+1)'(a_i);
    prod = $signed({1'b0, s_i}) * diff;
    step = (VW+1)'((prod + (VW+SW+2)'(1 << (TF - 1))) >>> TF);
    l_o  = VW'((VW+1)'(a_i) + step);
  end
endmodule
