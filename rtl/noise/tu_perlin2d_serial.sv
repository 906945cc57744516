// Block top of perlin2d, octave-serial scheme (tu_perlin_serial): 2-D fBm of x, y (s32.16) -> fbm (u17.16).
module tu_perlin2d_serial (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::NoiseCoordW-1:0] x_i,
  input  logic [tu_formats_pkg::NoiseCoordW-1:0] y_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [tu_formats_pkg::NoiseOutW-1:0]  fbm_o
);
  tu_perlin_serial #(.Dims(2)) u_perlin (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .coord_i({y_i, x_i}), .out_valid_o, .out_ready_i, .fbm_o
  );
endmodule
