// Unsigned floor division n / d with a QW-bit quotient, one quotient bit per pipeline stage
// (restoring); exact when n < 2^QW d (the caller guarantees it where the result is used).
// Latency QW stages advancing with en_i.
module tu_udiv_pipe #(
  parameter int NW = 50,
  parameter int DW = 35,
  parameter int QW = 12
) (
  input  logic          clk_i,
  input  logic          en_i,
  input  logic [NW-1:0] n_i,
  input  logic [DW-1:0] d_i,
  output logic [QW-1:0] q_o
);
  logic [NW-1:0] rem_q [QW];
  logic [DW-1:0] den_q [QW];
  logic [QW-1:0] quo_q [QW];
  logic [NW-1:0] rem_in [QW], rem_d [QW];
  logic [DW-1:0] den_in [QW];
  logic [QW-1:0] quo_in [QW], quo_d [QW];
  always_comb begin
    rem_in[0] = n_i;
    den_in[0] = d_i;
    quo_in[0] = '0;
    for (int s = 1; s < QW; s++) begin
      rem_in[s] = rem_q[s-1];
      den_in[s] = den_q[s-1];
      quo_in[s] = quo_q[s-1];
    end
    for (int s = 0; s < QW; s++) begin
      logic [NW:0] diff;
      diff     = {1'b0, rem_in[s]} - ((NW+1)'(den_in[s]) << (QW - 1 - s));
      rem_d[s] = diff[NW] ? rem_in[s] : diff[NW-1:0];
      quo_d[s] = diff[NW] ? quo_in[s] : quo_in[s] | (QW'(1) << (QW - 1 - s));
    end
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int s = 0; s < QW; s++) begin
        rem_q[s] <= rem_d[s];
        den_q[s] <= den_in[s];
        quo_q[s] <= quo_d[s];
      end
    end
  end
  assign q_o = quo_q[QW-1];
endmodule
