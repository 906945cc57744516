// Floor square root of an InW-bit unsigned value, one root bit per pipeline stage (restoring,
// digit by digit): rem = x - r^2 is kept, bit b of r is set when rem >= 2^(b+1) r + 2^(2b).
// Latency InW / 2 stages advancing with en_i; = ellipse::fx::isqrt (floor) on every input.
module tu_isqrt_pipe #(
  parameter int InW = 48
) (
  input  logic               clk_i,
  input  logic               en_i,
  input  logic [InW-1:0]     x_i,
  output logic [InW/2-1:0]   r_o
);
  localparam int OutW = InW / 2;
  logic [InW-1:0]  rem_q  [OutW];
  logic [OutW-1:0] root_q [OutW];
  logic [InW-1:0]  rem_in  [OutW];
  logic [OutW-1:0] root_in [OutW];
  logic [InW-1:0]  rem_d  [OutW];
  logic [OutW-1:0] root_d [OutW];
  always_comb begin
    rem_in[0]  = x_i;
    root_in[0] = '0;
    for (int s = 1; s < OutW; s++) begin
      rem_in[s]  = rem_q[s-1];
      root_in[s] = root_q[s-1];
    end
    for (int s = 0; s < OutW; s++) begin
      logic [InW:0] trial, diff;
      // bit OutW-1-s: trial = 2^(b+1) r + 2^(2b) (r has no bits at or below b yet)
      trial = ((InW+1)'(root_in[s]) << (OutW - s)) | ((InW+1)'(1) << (2 * (OutW - 1 - s)));
      diff  = {1'b0, rem_in[s]} - trial;
      rem_d[s]  = diff[InW] ? rem_in[s] : diff[InW-1:0];
      root_d[s] = diff[InW] ? root_in[s] : root_in[s] | (OutW'(1) << (OutW - 1 - s));
    end
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int s = 0; s < OutW; s++) begin
        rem_q[s]  <= rem_d[s];
        root_q[s] <= root_d[s];
      end
    end
  end
  assign r_o = root_q[OutW-1];
endmodule
