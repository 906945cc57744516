// Major-axis direction of a B2 conic (c, s) = (cos theta, sin theta), exactly the EWA's
// (ewa::fx::vectoring / rotation, cmodel/blocks/ewa/ewa_fx.cpp): a sequential CORDIC.
//   start   d = Ae' - Ce', b = Be' block-normalised to EwaCordW - 3 bits (floor shifts), pre-rotated
//           into the right half-plane (a half turn); d = b = 0 (a circle) or unit_i: theta = 0
//   VEC     I/U clocks, CordUnroll iterations per clock -> 2 phi (binary angle)
//   ROT     I/U clocks from theta = phi + 1/4 turn reduced to [-1/4, 1/4) turn -> c, s rounded
//           half up to EwaCsF bits
// start_i at clock t -> finish_o at t + 2 I/U (the last rotation clock), done_o (c_o, s_o valid,
// held until the next start) from t + 1 + 2 I/U.
// Factored out of tu_ewa_setup's PRE / VEC / ROT states; tu_feline_setup uses it (the Feline
// probes' line is the EWA ellipse's major axis).
module tu_ewa_dir #(
  parameter int CordUnroll = 2  // CORDIC iterations per clock (divides EwaCordIter)
) (
  input  logic                                  clk_i,
  input  logic                                  rst_ni,
  input  logic                                  start_i,
  input  logic signed [63:0]                    d_i,     // Ae' - Ce' (both < 2^62)
  input  logic signed [63:0]                    b_i,     // Be'
  input  logic                                  unit_i,  // no axes: theta = 0
  output logic                                  finish_o,  // c_o, s_o valid from the next clock
  output logic                                  done_o,
  output logic signed [tu_formats_pkg::EwaCsW-1:0] c_o,
  output logic signed [tu_formats_pkg::EwaCsW-1:0] s_o
);
  localparam int Iter = tu_formats_pkg::EwaCordIter;
  localparam int AngW = tu_formats_pkg::EwaAngW;
  localparam int CW   = tu_formats_pkg::EwaCordW;
  localparam int XW   = CW + 2;
  localparam int ZW   = AngW + 2;
  localparam int RotF = CW - 3;
  localparam int CsF  = tu_formats_pkg::EwaCsF;
  localparam int CsW  = tu_formats_pkg::EwaCsW;
  localparam logic signed [ZW-1:0] Quarter = ZW'(1) <<< (AngW - 2);
  localparam logic signed [ZW-1:0] Half    = ZW'(1) <<< (AngW - 1);

  typedef enum logic [1:0] {DIdle, DVec, DRot, DDone} state_e;
  state_e st_q;
  logic [4:0] it_q;
  logic       zero_q;  // circle or unit: theta = 0
  logic       last;
  assign last = 32'(it_q) + CordUnroll >= Iter;

  // block normalisation and pre-rotation of the start vector
  logic signed [63:0] ad, ab, mx, xn, yn;
  logic [6:0]         msb, k;
  always_comb begin
    ad = d_i < 0 ? -d_i : d_i;
    ab = b_i < 0 ? -b_i : b_i;
    mx = ad > ab ? ad : ab;
    msb = '0;
    for (int i = 0; i < 64; i++) if (mx[i]) msb = 7'(i);
    k = (msb + 7'd1 > 7'(CW - 3)) ? msb + 7'd1 - 7'(CW - 3) : 7'd0;
    xn = d_i >>> k;
    yn = b_i >>> k;
  end

  logic signed [XW-1:0] cx_q, cy_q, cx_d, cy_d;
  logic signed [ZW-1:0] cz_q, cz_d;
  tu_ewa_cordic #(.Unroll(CordUnroll), .XW(XW), .ZW(ZW)) u_cordic (
    .rotate_i(st_q == DRot), .i0_i(it_q), .x_i(cx_q), .y_i(cy_q), .z_i(cz_q),
    .x_o(cx_d), .y_o(cy_d), .z_o(cz_d)
  );
  logic [CW-1:0]   gain;  // the rotation's start x
  logic [AngW-1:0] atan_unused;
  tu_ewa_atan_rom u_gain (.i_i(4'd0), .atan_o(atan_unused), .gain_o(gain));
  logic signed [ZW-1:0] two_phi, theta;
  always_comb begin
    two_phi = ZW'($signed(cz_d[AngW-1:0]));
    theta = (two_phi >>> 1) + Quarter;
    if (theta >= Quarter) theta = theta - Half;
    if (zero_q) theta = '0;
  end
  function automatic logic signed [CsW-1:0] cs_round(input logic signed [XW-1:0] v);
    /* verilator lint_off UNUSEDSIGNAL */
    logic signed [XW-1:0] tr;  // high bits: sign copies
    /* verilator lint_on UNUSEDSIGNAL */
    tr = (v + $signed(XW'(1) << (RotF - CsF - 1))) >>> (RotF - CsF);
    cs_round = CsW'(tr);
  endfunction

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= DIdle;
    else if (start_i) st_q <= DVec;
    else begin
      unique case (st_q)
        DVec:    if (last) st_q <= DRot;
        DRot:    if (last) st_q <= DDone;
        default: ;
      endcase
    end
  end
  always_ff @(posedge clk_i) begin
    if (start_i) begin
      zero_q <= unit_i || (d_i == 0 && b_i == 0);
      if (xn < 0) begin
        cx_q <= XW'(-xn);
        cy_q <= XW'(-yn);
        cz_q <= Half;
      end else begin
        cx_q <= XW'(xn);
        cy_q <= XW'(yn);
        cz_q <= '0;
      end
      it_q <= '0;
    end else if (st_q == DVec) begin
      if (last) begin
        cx_q <= XW'($signed({1'b0, gain}));
        cy_q <= '0;
        cz_q <= theta;
        it_q <= '0;
      end else begin
        cx_q <= cx_d;
        cy_q <= cy_d;
        cz_q <= cz_d;
        it_q <= it_q + 5'(CordUnroll);
      end
    end else if (st_q == DRot) begin
      cx_q <= cx_d;
      cy_q <= cy_d;
      cz_q <= cz_d;
      it_q <= it_q + 5'(CordUnroll);
      c_o  <= cs_round(cx_d);
      s_o  <= cs_round(cy_d);
    end
  end
  assign finish_o = st_q == DRot && last;
  assign done_o   = st_q == DDone;
  logic unused;
  assign unused = ^atan_unused;
endmodule
