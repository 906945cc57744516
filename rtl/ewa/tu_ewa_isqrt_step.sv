// Restoring integer square root, Step result bits per call (combinational): the EWA set-up
// applies it once per clock to the two half-extent radicands. After RootW/Step calls from
// rem = root = 0, root = floor(sqrt(x)) and rem = x - root^2 (so ceil(sqrt(x)) = root + (rem != 0)).
module tu_ewa_isqrt_step #(
  parameter int RootW = 16,
  parameter int Step  = 4
) (
  input  logic [2*RootW-1:0] x_i,     // radicand bits still to consume, msb first
  input  logic [RootW+1:0]   rem_i,
  input  logic [RootW-1:0]   root_i,
  output logic [2*RootW-1:0] x_o,
  output logic [RootW+1:0]   rem_o,
  output logic [RootW-1:0]   root_o
);
  always_comb begin
    logic [2*RootW-1:0] x;
    logic [RootW+1:0]   rem, test;
    logic [RootW-1:0]   root;
    x    = x_i;
    rem  = rem_i;
    root = root_i;
    for (int j = 0; j < Step; j++) begin
      rem  = {rem[RootW-1:0], x[2*RootW-1 -: 2]};
      x    = x << 2;
      test = {root, 2'b01};
      root = root << 1;
      if (rem >= test) begin
        rem  = rem - test;
        root = root | RootW'(1);
      end
    end
    x_o    = x;
    rem_o  = rem;
    root_o = root;
  end
endmodule
