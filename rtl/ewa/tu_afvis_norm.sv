// EWA normalisation of the visibility walker (tu_afvis_walk; ewa::fx::finish, the same datapath as
// tu_ewa_walk's "normalisation" section): wsum leading-one normalised to EwaNrmW bits (floor),
// tu_recip_core (RecipCoreLatency stages), channel = min(255, round_half_up(acc_c R 2^-(RecipOutF
// + p))). load_i registers the mantissa and shift of wsum_i; rgba_o is valid EwaNormCycles - 1
// clocks later while acc_i is held.
module tu_afvis_norm (
  input  logic                                  clk_i,
  input  logic                                  load_i,
  input  logic [tu_formats_pkg::EwaWsumW-1:0]   wsum_i,
  input  logic [4*tu_formats_pkg::EwaAccW-1:0]  acc_i,  // {a, b, g, r}
  output logic [31:0]                           rgba_o
);
  localparam int WsW = tu_formats_pkg::EwaWsumW;
  localparam int AcW = tu_formats_pkg::EwaAccW;
  localparam int NrW = tu_formats_pkg::EwaNrmW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  logic [6:0]     p_d, p_q;
  logic [NrW-1:0] m_d;
  logic [MW-1:0]  mant_q;
  logic [RW-1:0]  r;
  always_comb begin
    p_d = '0;
    for (int i = 0; i < WsW; i++) if (wsum_i[i]) p_d = 7'(i);
    m_d = (p_d >= 7'(NrW - 1)) ? NrW'(wsum_i >> (p_d - 7'(NrW - 1))) : NrW'(wsum_i << (7'(NrW - 1) - p_d));
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
      logic [AcW+RW:0] pr;
      logic [7:0]      sh;
      sh = 8'(tu_formats_pkg::RecipOutF) + 8'(p_q);
      pr = ((AcW+RW+1)'(acc_i[AcW*c +: AcW]) * (AcW+RW+1)'(r) + ((AcW+RW+1)'(1) << (sh - 8'd1))) >> sh;
      rgba_o[8*c +: 8] = pr > (AcW+RW+1)'(255) ? 8'd255 : pr[7:0];
    end
  end
endmodule
