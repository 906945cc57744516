// Reciprocal of a positive unsigned code for the BRDF models (brdf::recip_of): the leading one
// (msb p) of q_i is found, the top RecipMantW bits left-justified (truncated) are M in [1, 2),
// and 1/q = R * 2^(F - p) with R from tu_recip_core. Latency 4 (the core), p delayed alongside.
module tu_brdf_recip #(
  parameter int InW = 23
) (
  input  logic                                   clk_i,
  input  logic                                   en_i,
  input  logic [InW-1:0]                         q_i,
  output logic [tu_formats_pkg::RecipOutW-1:0]   r_o,
  output logic [5:0]                             p_o
);
  localparam int MW = tu_formats_pkg::RecipMantW;
  localparam int JW = (InW > MW) ? InW : MW;  // left-justified width
  logic [5:0]    p;
  /* verilator lint_off UNUSEDSIGNAL */  // bits below the mantissa are truncated
  logic [JW-1:0] just;
  /* verilator lint_on UNUSEDSIGNAL */
  logic [MW-1:0] m;
  always_comb begin
    p = '0;
    for (int i = 0; i < InW; i++) begin
      if (q_i[i]) p = 6'(i);
    end
    just = JW'(q_i) << (JW - 1 - 32'(p));
    m    = just[JW-1 -: MW];
  end
  tu_recip_core u_core (.clk_i, .en_i, .m_i(m), .r_o);
  logic [5:0] p_q [4];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      p_q[0] <= p;
      for (int i = 1; i < 4; i++) p_q[i] <= p_q[i-1];
    end
  end
  assign p_o = p_q[3];
endmodule
