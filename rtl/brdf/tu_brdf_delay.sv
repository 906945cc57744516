// W-bit delay line of Depth stages advancing with the pipeline enable (Depth >= 1).
module tu_brdf_delay #(
  parameter int W = 1,
  parameter int Depth = 1
) (
  input  logic         clk_i,
  input  logic         en_i,
  input  logic [W-1:0] d_i,
  output logic [W-1:0] q_o
);
  logic [W-1:0] q [Depth];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      q[0] <= d_i;
      for (int i = 1; i < Depth; i++) q[i] <= q[i-1];
    end
  end
  assign q_o = q[Depth-1];
endmodule
