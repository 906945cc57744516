// Normalisation in front of tu_recip_core for a positive unsigned code q (InW <= RecipInW - 1
// bits): p = msb position of q, M = q << (RecipMantW - 1 - p) in [1, 2). Combinational; the same
// rule as recip::eval. q = 0 gives p = 0, M = 0 (the caller must not use the result).
module tu_recip_norm #(
  parameter int InW = 16
) (
  input  logic [InW-1:0]                           q_i,
  output logic [tu_formats_pkg::RecipMantW-1:0]    m_o,
  output logic [tu_formats_pkg::RecipShiftW-1:0]   p_o
);
  localparam int MW = tu_formats_pkg::RecipMantW;
  always_comb begin
    p_o = '0;
    for (int i = 0; i < InW; i++) begin
      if (q_i[i]) p_o = tu_formats_pkg::RecipShiftW'(i);
    end
    m_o = MW'({{MW{1'b0}}, q_i} << (MW - 1 - 32'(p_o)));
  end
endmodule
