// tu_clip_mulfloor: c + floor(x * a) to ClipCoefF fraction bits (x, c s24.18, a u12.12), wrapped to
// ClipAccW. One multiply-add: c * 2^ClipInF joins the product's carry-save tree (c + floor(p / 2^k)
// = floor((p + c 2^k) / 2^k) exactly), so a Horner step costs one carry chain, not an adder in
// front of the multiplier and another behind it.
module tu_clip_mulfloor (
  input  logic signed [tu_formats_pkg::ClipAccW-1:0] x_i,
  input  logic [tu_formats_pkg::ClipAW-1:0]          a_i,
  input  logic signed [tu_formats_pkg::ClipAccW-1:0] c_i,
  output logic signed [tu_formats_pkg::ClipAccW-1:0] y_o
);
  localparam int PW = tu_formats_pkg::ClipAccW + tu_formats_pkg::ClipAW + 1;
  logic signed [PW-1:0] prod;
  assign prod = PW'(x_i) * $signed({1'b0, a_i}) + (PW'(c_i) <<< tu_formats_pkg::ClipInF);
  assign y_o  = tu_formats_pkg::ClipAccW'(prod >>> tu_formats_pkg::ClipInF);
endmodule
