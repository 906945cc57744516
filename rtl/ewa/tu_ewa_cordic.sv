// CORDIC datapath of the EWA set-up (combinational): Unroll consecutive iterations i0 .. i0+Unroll-1
// of either mode, exactly ewa::fx::vectoring / rotation (cmodel/blocks/ewa/ewa_fx.cpp):
//   vectoring (rotate_i = 0): sigma = y >= 0 ? -1 : +1   rotation: sigma = z >= 0 ? +1 : -1
//   x -= sigma (y >>> i),  y += sigma (x >>> i),  z -= sigma atan_i   (floor shifts)
// The set-up FSM applies it once per clock (Unroll iterations per clock).
module tu_ewa_cordic #(
  parameter int Unroll = 2,
  parameter int XW = tu_formats_pkg::EwaCordW + 2,  // headroom over the C model's int64
  parameter int ZW = tu_formats_pkg::EwaAngW + 2
) (
  input  logic                 rotate_i,
  input  logic [4:0]           i0_i,
  input  logic signed [XW-1:0] x_i,
  input  logic signed [XW-1:0] y_i,
  input  logic signed [ZW-1:0] z_i,
  output logic signed [XW-1:0] x_o,
  output logic signed [XW-1:0] y_o,
  output logic signed [ZW-1:0] z_o
);
  localparam int AngW = tu_formats_pkg::EwaAngW;
  logic [AngW-1:0] at [Unroll];
  for (genvar j = 0; j < Unroll; j++) begin : g_rom
    logic [tu_formats_pkg::EwaCordW-1:0] gain_unused;  // the rotation start value: read by the set-up
    tu_ewa_atan_rom u_rom (.i_i(4'(i0_i + 5'(j))), .atan_o(at[j]), .gain_o(gain_unused));
  end
  always_comb begin
    logic signed [XW-1:0] x, y, xs, ys;
    logic signed [ZW-1:0] z, a;
    logic                 neg;  // sigma = -1
    x = x_i;
    y = y_i;
    z = z_i;
    for (int j = 0; j < Unroll; j++) begin
      xs  = x >>> (32'(i0_i) + j);
      ys  = y >>> (32'(i0_i) + j);
      a   = ZW'($signed({1'b0, at[j]}));
      neg = rotate_i ? z < 0 : y >= 0;
      if (neg) begin
        x = x + ys;
        y = y - xs;
        z = z + a;
      end else begin
        x = x - ys;
        y = y + xs;
        z = z - a;
      end
    end
    x_o = x;
    y_o = y;
    z_o = z;
  end
endmodule
