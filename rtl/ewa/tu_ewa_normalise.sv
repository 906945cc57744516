// Normalisation of weighted colour sums, exactly ewa::fx::normalise (cmodel/blocks/ewa/ewa_fx.cpp):
// wsum > 0 leading-one normalised to EwaNrmW bits (floor), tu_recip_core (4 stages) -> R,
// channel = min(255, round_half_up(acc_c R 2^-(RecipOutF + p - (EwaNrmW - 1)))) with p = msb(wsum).
//   load_i at clock t: p and the mantissa of wsum_i registered
//   t + 1 .. t + 4: the reciprocal core
//   t + 5 (= t + EwaNormCycles - 1): rgba_o = the channels of acc_i (combinational; acc_i must be
//   stable at t + 5), to be registered by the caller
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
  localparam int RW  = tu_formats_pkg::RecipOutW;
  logic [6:0]     p_d, p_q;
  logic [NrW-1:0] m_d;
  logic [MW-1:0]  mant_q;
  logic [RW-1:0]  r;
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
  tu_recip_core u_core (.clk_i, .en_i(1'b1), .m_i(mant_q), .r_o(r));
  always_comb begin
    for (int c = 0; c < 4; c++) begin
      logic [AccW+RW:0] pr;
      logic [7:0]       sh;
      sh = 8'(tu_formats_pkg::RecipOutF) + 8'(p_q);
      pr = ((AccW+RW+1)'(acc_i[c*AccW +: AccW]) * (AccW+RW+1)'(r) + ((AccW+RW+1)'(1) << (sh - 8'd1))) >> sh;
      rgba_o[8*c +: 8] = pr > (AccW+RW+1)'(255) ? 8'd255 : pr[7:0];
    end
  end
endmodule
