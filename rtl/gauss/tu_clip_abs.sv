// Clip-volume front end shared by every scheme (docs/blocks/gaussian.md): a = min(|d|, 0.5) (u12.12), neg = d < 0.
module tu_clip_abs (
  input  logic [tu_formats_pkg::ClipInW-1:0] d_i,
  output logic [tu_formats_pkg::ClipAW-1:0]  a_o,
  output logic                                neg_o
);
  localparam int InW = tu_formats_pkg::ClipInW;
  localparam logic [InW-1:0] Half = InW'(1) << (tu_formats_pkg::ClipInF - 1);
  logic [InW-1:0] mag;
  assign neg_o = d_i[InW-1];
  assign mag   = neg_o ? (~d_i + InW'(1)) : d_i;  // |-1.0| wraps to 1.0 (bit InW-1), clamped below
  assign a_o   = (neg_o && mag[InW-1]) || (mag > Half) ? tu_formats_pkg::ClipAW'(Half)
                                                      : tu_formats_pkg::ClipAW'(mag);
endmodule
