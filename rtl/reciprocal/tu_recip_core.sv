// Reciprocal core: R ~ 1/M for a normalised mantissa M in [1,2), four pipeline stages.
// Piecewise quadratic, Horner form; formats and rounding exactly as cmodel/blocks/reciprocal:
//   stages 1-3 (tu_recip_core_y): y = c0 + floor((c1 + floor(c2 dx)) dx), RecipC0F fraction bits
//   stage 4: R  = sat(round_half_up(y))    (RecipOutF fraction bits)
// The EWA normalisation uses tu_recip_core_y alone and folds stage 4 into its product.
module tu_recip_core
(
  input  logic                 clk_i,
  input  logic                 en_i,
  input  logic [tu_formats_pkg::RecipMantW-1:0] m_i,
  output logic [tu_formats_pkg::RecipOutW-1:0]  r_o
);
  localparam int YW  = tu_formats_pkg::RecipC0W + 2;                   // c0 + t2 (signed)
  localparam int RndShift = tu_formats_pkg::RecipC0F - tu_formats_pkg::RecipOutF;

  // Stages 1-3
  logic signed [YW-1:0] y_q3;
  tu_recip_core_y u_y (.clk_i, .en_i, .m_i, .y_o(y_q3));

  // Stage 4: round half up, saturate to the unsigned output format
  logic signed [YW-1:0]        y_rnd;
  logic [tu_formats_pkg::RecipOutW-1:0]        r_d, r_q4;
  assign y_rnd = (y_q3 + YW'(1 << (RndShift - 1))) >>> RndShift;
  always_comb begin
    if (y_rnd < 0) begin
      r_d = '0;
    end else if (y_rnd > YW'({tu_formats_pkg::RecipOutW{1'b1}})) begin
      r_d = '1;
    end else begin
      r_d = tu_formats_pkg::RecipOutW'(y_rnd);
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      r_q4  <= r_d;
    end
  end

  assign r_o = r_q4;
endmodule
