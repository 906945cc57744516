// Perlin's grad(hash & 15, x, y, z) = +-u +-v (u, v two of the corner offsets); exact.
// Offsets s17.16 in [-1,1), result s19.16 in [-2,2]. Same as cmodel/blocks/noise/noise_grad.hpp.
module tu_noise_grad (
  input  logic [3:0]                                 hash_i,
  input  logic signed [tu_formats_pkg::NoiseDW-1:0]  x_i,
  input  logic signed [tu_formats_pkg::NoiseDW-1:0]  y_i,
  input  logic signed [tu_formats_pkg::NoiseDW-1:0]  z_i,
  output logic signed [tu_formats_pkg::NoiseValW-1:0] dot_o
);
  localparam int VW = tu_formats_pkg::NoiseValW;
  logic signed [VW-1:0] u, v;
  always_comb begin
    u = hash_i < 4'd8 ? VW'(x_i) : VW'(y_i);
    if (hash_i < 4'd4) v = VW'(y_i);
    else if (hash_i == 4'd12 || hash_i == 4'd14) v = VW'(x_i);
    else v = VW'(z_i);
    dot_o = (hash_i[0] ? -u : u) + (hash_i[1] ? -v : v);
  end
endmodule
