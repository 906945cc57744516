// Front end of every BRDF model (cmodel/blocks/brdf/brdf_common.hpp, brdf::front), combinational:
//   c = clamp(c_i, 0, 1) (c_i > 1 flags), n = clamp(n_i, 1, BrdfNMax) (flags),
//   t = 1 - c (exact, internal), u = n * t (exact, u30.20), cut = c < ccut_i (F = 0 below the cut-off).
module tu_brdf_front (
  input  logic [tu_formats_pkg::BrdfCW-1:0]  c_i,
  input  logic [tu_formats_pkg::BrdfNW-1:0]  n_i,
  input  logic [tu_formats_pkg::BrdfClW-1:0] ccut_i,
  output logic [tu_formats_pkg::BrdfClW-1:0] c_o,
  output logic [tu_formats_pkg::BrdfUW-1:0]  u_o,
  output logic [tu_formats_pkg::BrdfNW-1:0]  n_o,
  output logic                               cut_o,
  output logic                               flag_o
);
  localparam int CW  = tu_formats_pkg::BrdfCW;
  localparam int ClW = tu_formats_pkg::BrdfClW;
  localparam int NW  = tu_formats_pkg::BrdfNW;
  localparam int UW  = tu_formats_pkg::BrdfUW;
  localparam logic [ClW-1:0] One = ClW'(1) << tu_formats_pkg::BrdfCF;

  logic c_neg, c_big, n_low, n_high;
  assign c_neg  = c_i[CW-1];
  assign c_big  = !c_neg && (c_i[CW-2:0] > (CW-1)'(One));
  assign n_low  = n_i == '0;
  assign n_high = n_i > NW'(tu_formats_pkg::BrdfNMax);
  always_comb begin
    if (c_neg)      c_o = '0;
    else if (c_big) c_o = One;
    else            c_o = c_i[ClW-1:0];
    if (n_low)       n_o = NW'(1);
    else if (n_high) n_o = NW'(tu_formats_pkg::BrdfNMax);
    else             n_o = n_i;
  end
  logic [ClW-1:0] t;
  assign t      = One - c_o;
  assign u_o    = UW'(n_o * t);
  assign cut_o  = c_o < ccut_i;
  assign flag_o = c_big || n_low || n_high;
endmodule
