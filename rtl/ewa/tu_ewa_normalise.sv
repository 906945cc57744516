// Normalisation of weighted colour sums, exactly ewa::fx::normalise (cmodel/blocks/ewa/ewa_fx.cpp):
// wsum > 0 leading-one normalised to EwaNrmW bits (floor), the reciprocal core -> R,
// channel = min(255, round_half_up(acc_c R 2^-(RecipOutF + p - (EwaNrmW - 1)))) with p = msb(wsum).
//   load_i at clock t: p and the mantissa of wsum_i registered
//   t + 1 .. t + 3: the reciprocal core up to its unrounded y (tu_recip_core_y)
//   t + 2: WsumW - 1 - p registered per channel (tu_ewa_norm_tail; p_q held since t + 1)
//   t + 3: acc_i read (it must be stable then): pre-shifted by WsumW - 1 - p
//   t + 4: the products as carry-save pairs (the core's rounding folded in)
//   t + 5 (= t + EwaNormCycles - 1): rgba_o = the channels (combinational: the carry chain, a
//   fixed shift, saturation), to be registered by the caller
// Factored out of tu_ewa_walk's normalisation; tu_feline uses it on its probe sums.
module tu_ewa_normalise #(
  parameter int AccW  = tu_formats_pkg::EwaAccW,   // per-channel weighted sum (GaussSqF fraction bits)
  parameter int WsumW = tu_formats_pkg::EwaWsumW   // weight sum
) (
  input  logic             clk_i,
  input  logic             load_i,
  input  logic [WsumW-1:0] wsum_i,
  input  logic [4*AccW-1:0] acc_i,   // channel c at [c AccW +: AccW]
  output logic [31:0]      rgba_o
);
  localparam int NrW = tu_formats_pkg::EwaNrmW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  logic [6:0]     p_d, p_q;
  logic [NrW-1:0] m_d;
  logic [MW-1:0]  mant_q;
  logic signed [tu_formats_pkg::RecipC0W+1:0] y;
  logic [WsumW+NrW-1:0] wx;  // room for the left shift of a narrow sum
  always_comb begin
    p_d = '0;
    for (int i = 0; i < WsumW; i++) if (wsum_i[i]) p_d = 7'(i);
    wx  = (WsumW+NrW)'(wsum_i);
    m_d = (p_d >= 7'(NrW - 1)) ? NrW'(wx >> (p_d - 7'(NrW - 1))) : NrW'(wx << (7'(NrW - 1) - p_d));
  end
  always_ff @(posedge clk_i) begin
    if (load_i) begin
      p_q    <= p_d;
      mant_q <= MW'(m_d) << (MW - NrW);  // recip::eval: the msb of a positive code at bit MW-1
    end
  end
  tu_recip_core_y u_core (.clk_i, .en_i(1'b1), .m_i(mant_q), .y_o(y));
  tu_ewa_norm_tail #(.AccW(AccW), .WsumW(WsumW)) u_tail (.clk_i, .p_i(p_q), .acc_i, .y_i(y), .rgba_o);
endmodule
