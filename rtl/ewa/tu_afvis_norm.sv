// EWA normalisation of the visibility walker (tu_afvis_walk; ewa::fx::finish, the same datapath as
// tu_ewa_walk's "normalisation" section): wsum leading-one normalised to EwaNrmW bits (floor),
// the reciprocal core, channel = min(255, round_half_up(acc_c R 2^-(RecipOutF + p))). load_i
// registers the mantissa and shift of wsum_i (clock t); tu_recip_core_y's y at t + 4, acc_i read
// at t + 3 (tu_ewa_norm_tail: its shift amounts from p_q at t + 2, the pre-shift at t + 3; t + 4
// carry-save products; t + 5 carry chain, fixed
// shift, saturation): rgba_o is valid EwaNormCycles - 1 clocks after the load while acc_i is held.
module tu_afvis_norm (
  input  logic                                  clk_i,
  input  logic                                  load_i,
  input  logic [tu_formats_pkg::EwaWsumW-1:0]   wsum_i,
  input  logic [4*tu_formats_pkg::EwaAccW-1:0]  acc_i,  // {a, b, g, r}
  output logic [31:0]                           rgba_o
);
  localparam int WsW = tu_formats_pkg::EwaWsumW;
  localparam int NrW = tu_formats_pkg::EwaNrmW;
  localparam int MW  = tu_formats_pkg::RecipMantW;
  logic [6:0]     p_d, p_q;
  logic [NrW-1:0] m_d;
  logic [MW-1:0]  mant_q;
  logic signed [tu_formats_pkg::RecipC0W+1:0] y;
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
  tu_recip_core_y u_core (.clk_i, .en_i(1'b1), .m_i(mant_q), .y_o(y));
  tu_ewa_norm_tail u_tail (.clk_i, .p_i(p_q), .acc_i, .y_i(y), .rgba_o);
endmodule
