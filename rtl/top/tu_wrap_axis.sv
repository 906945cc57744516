// One axis of tu_texel_addr (combinational): texel coordinate x (any integer) wrapped into
// [0, m], m = 2^l - 1, like tex::wrap_index:
//   repeat x & m; mirror bit l of x ? ~x & m : x & m; clamp to [0, m];
//   border x & m with oob_o = x outside [0, m] (the border colour); mirror once
//   min(x < 0 ? ~x : x, m) (~x = -1 - x: mirrored about -1/2).
// m is a mask (2^l - 1), so no compare needs a carry chain: x outside [0, m] <=> x has a bit
// outside m (x & ~m != 0, the sign bit included); x > m <=> x >= 0 and x & ~m != 0.
// Modes (bit = tu_formats_pkg::Wrap* code) keeps a mode's logic; a code whose mode is left out
// wraps as repeat (the plan's unit never receives one).
module tu_wrap_axis #(
  parameter int         CoordW = 32,
  parameter logic [4:0] Modes  = 5'b11111
) (
  input  logic signed [CoordW-1:0]            x_i,
  input  logic [3:0]                          l_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] m_i,     // 2^l - 1
  input  logic [tu_formats_pkg::WrapW-1:0]    mode_i,
  output logic [tu_formats_pkg::TexAddrW-1:0] idx_o,
  output logic                                oob_o
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  logic [CoordW-1:0]        mw;   // m as CoordW bits (m < 2^15 <= 2^(CoordW-1))
  logic [CoordW-1:0]        mx;   // mirrored about -1/2 (mirror once): x < 0 ? ~x : x
  /* verilator lint_off UNUSEDSIGNAL */
  logic signed [CoordW-1:0] xs;   // x >> l: the repeat number (its parity is used)
  /* verilator lint_on UNUSEDSIGNAL */
  logic                     odd;  // bit l of x: an odd repeat (mirror)
  logic                     neg;  // x < 0
  logic                     out;  // x outside [0, m]
  logic                     above;  // x > m
  logic                     mx_above;  // mx > m
  assign mw       = CoordW'(m_i);
  assign neg      = x_i[CoordW-1];
  assign mx       = neg ? ~x_i : x_i;
  assign xs       = x_i >>> l_i;
  assign odd      = xs[0];
  assign out      = |(x_i & ~mw);
  assign above    = !neg && out;
  assign mx_above = |(mx & ~mw);
  always_comb begin
    oob_o = 1'b0;
    idx_o = AW'(x_i) & m_i;  // repeat, and the default of a left-out mode
    if (Modes[tu_formats_pkg::WrapMirror] && mode_i == tu_formats_pkg::WrapMirror) begin
      idx_o = AW'(x_i ^ {CoordW{odd}}) & m_i;
    end else if (Modes[tu_formats_pkg::WrapClamp] && mode_i == tu_formats_pkg::WrapClamp) begin
      idx_o = neg ? '0 : above ? m_i : AW'(x_i) & m_i;
    end else if (Modes[tu_formats_pkg::WrapBorder] && mode_i == tu_formats_pkg::WrapBorder) begin
      oob_o = out;
    end else if (Modes[tu_formats_pkg::WrapMirrorOnce] && mode_i == tu_formats_pkg::WrapMirrorOnce) begin
      idx_o = mx_above ? m_i : AW'(mx) & m_i;
    end
  end
endmodule
