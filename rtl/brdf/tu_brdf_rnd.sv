// Round half up by a run-time right shift and saturate: y = sat_OutW((x + 2^(sh-1)) >> sh), sh >= 1
// (brdf::rnd + sat). Combinational.
module tu_brdf_rnd #(
  parameter int InW = 48,
  parameter int OutW = 9
) (
  input  logic [InW-1:0]  x_i,
  input  logic [6:0]      sh_i,
  output logic [OutW-1:0] y_o
);
  logic [InW:0] sum, shifted;
  always_comb begin
    sum     = {1'b0, x_i} + ((InW+1)'(1) << (sh_i - 7'd1));
    shifted = sum >> sh_i;
    y_o     = (shifted > (InW+1)'({OutW{1'b1}})) ? '1 : OutW'(shifted);
  end
endmodule
