// log2 fraction of a mantissa 1.(MantW-1) by FracW truncating squarings (combinational): stage k
// squares m_k, and its integer part is fraction bit k (MSB first); m_{k+1} is the square
// renormalised to [1, 2). Bit-exact with cmodel/blocks/ellipse/ellipse_fx.cpp's log2 fraction.
// Unrolled into continuous assignments, one stage per bit: Icarus 11 never settled time 0 when
// this loop ran in always_comb blocks (the former function inside tu_ellipse) next to the
// ellipse's other loops; nets settle at once in every tool.
module tu_log2_frac #(
  parameter int MantW = 16,
  parameter int FracW = 11
) (
  input  logic [MantW-1:0] m_i,
  output logic [FracW-1:0] frac_o
);
  logic [MantW:0] m [FracW+1] /* verilator split_var */;  // one net per stage, not a loop
  assign m[0] = {1'b0, m_i};
  for (genvar k = 0; k < FracW; k++) begin : g_stage
    logic [2*MantW-1:0] sq;
    logic [MantW:0]     t;
    assign sq = m[k][MantW-1:0] * m[k][MantW-1:0];
    assign t = (MantW+1)'(sq >> (MantW - 1));
    assign frac_o[FracW-1-k] = t[MantW];
    assign m[k+1] = t[MantW] ? t >> 1 : t;
  end
  logic unused;
  assign unused = ^{m[FracW], m[0][MantW]};
endmodule
