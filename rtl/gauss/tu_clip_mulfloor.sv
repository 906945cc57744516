// tu_clip_mulfloor: floor(x * a) to ClipCoefF fraction bits (x s24.18, a u12.12), wrapped to ClipAccW.
module tu_clip_mulfloor (
  input  logic signed [tu_formats_pkg::ClipAccW-1:0] x_i,
  input  logic [tu_formats_pkg::ClipAW-1:0]          a_i,
  output logic signed [tu_formats_pkg::ClipAccW-1:0] y_o
);
  localparam int PW = tu_formats_pkg::ClipAccW + tu_formats_pkg::ClipAW + 1;
  logic signed [PW-1:0] prod;
  assign prod = PW'(x_i) * $signed({1'b0, a_i});
  assign y_o  = tu_formats_pkg::ClipAccW'(prod >>> tu_formats_pkg::ClipInF);
endmodule
