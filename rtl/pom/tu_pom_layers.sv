// Adaptive POM layer counter (docs/blocks/relief.md; C model cmodel/blocks/pom/pom_layers.hpp).
//   stage 0: idx = round(min(|Vz|,1) * 2^PomIdxF), f = ROM[idx], T = 255*(Nmax-2*Nmin) + Nmax*code
//   stage 1: y = (f*T >>> (PomFF+1)) + 255*PomBias
//   stage 2: N = Nmin + ((y*PomDivM) >> PomDivS) - PomBias, clamped to [max(Nmin,1), max(Nmax,lo)]
// Latency PomLayersLatency (3), II = 1.
`include "tu_assert.svh"
module tu_pom_layers
(
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomVzW-1:0]   vz_i,
  input  logic [tu_formats_pkg::PomCW-1:0]    c_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    nmin_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    nmax_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PomNW-1:0]    n_o,
  output logic                                neg_o
);
  localparam int VzW  = tu_formats_pkg::PomVzW;
  localparam int NW   = tu_formats_pkg::PomNW;
  localparam int FW   = tu_formats_pkg::PomFW;
  localparam int TW   = tu_formats_pkg::PomTW;
  localparam int PW   = tu_formats_pkg::PomPW;
  localparam int QW   = tu_formats_pkg::PomQW;
  localparam int IdxW = tu_formats_pkg::PomIdxW;
  localparam int Sh   = tu_formats_pkg::PomVzF - tu_formats_pkg::PomIdxF;
  localparam int DivS = tu_formats_pkg::PomDivS;
  localparam int DW   = QW + 16;  // y * PomDivM (PomDivM < 2^16)

  logic en;
  logic [tu_formats_pkg::PomLayersLatency-1:0] stage_valid;
  tu_pipe_valid #(.Depth(tu_formats_pkg::PomLayersLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- Stage 0 -----------------------------------------------------------------------------
  logic [VzW-1:0]  vz_abs, a_sat;
  logic [IdxW-1:0] idx;
  logic [FW-1:0]   f_d;
  logic signed [TW-1:0] t_d;
  localparam logic signed [TW-1:0] K255 = TW'(255);
  logic signed [TW-1:0] nmax_s, nmin2_s, c_s;  // zero-extended operands
  assign nmax_s  = TW'(nmax_i);
  assign nmin2_s = TW'({nmin_i, 1'b0});
  assign c_s     = TW'(c_i);
  always_comb begin
    vz_abs = vz_i[VzW-1] ? (~vz_i + 1'b1) : vz_i;  // -2^15 -> 2^15 (unsigned), saturated below
    a_sat  = (vz_abs > VzW'(1 << tu_formats_pkg::PomVzF)) ? VzW'(1 << tu_formats_pkg::PomVzF)
                                                          : vz_abs;
    idx    = IdxW'((a_sat + VzW'(1 << (Sh - 1))) >> Sh);
    t_d    = K255 * (nmax_s - nmin2_s) + nmax_s * c_s;
  end
  tu_pom_f_rom u_rom (.idx_i(idx), .f_o(f_d));

  logic [FW-1:0]        f_q;
  logic signed [TW-1:0] t_q;
  logic [NW-1:0]        nmin_q [2];
  logic [NW-1:0]        lo_q [2];
  logic [NW-1:0]        hi_q [2];
  logic                 neg_q [2];
  logic [NW-1:0]        lo_d, hi_d;
  assign lo_d = (nmin_i == '0) ? NW'(1) : nmin_i;
  assign hi_d = (nmax_i > lo_d) ? nmax_i : lo_d;

  // ---- Stage 1 -----------------------------------------------------------------------------
  logic signed [PW-1:0] p_d, f_ext, t_ext;
  logic signed [PW-1:0] q_full;
  logic [QW-1:0]        y_d, y_q;
  assign f_ext  = PW'(f_q);  // zero-extended
  assign t_ext  = PW'(t_q);  // sign-extended
  assign p_d    = f_ext * t_ext;
  assign q_full = p_d >>> (tu_formats_pkg::PomFF + 1);
  assign y_d    = QW'(q_full + PW'(255 * tu_formats_pkg::PomBias));

  // ---- Stage 2 -----------------------------------------------------------------------------
  logic [DW-1:0]  prod;
  logic signed [NW+2:0] n_full;  // Nmin + floor(y/255) - PomBias, |.| < 2^(NW+2)
  logic [NW-1:0]  n_d, n_q;
  always_comb begin
    prod   = DW'(y_q) * DW'(tu_formats_pkg::PomDivM);
    n_full = $signed((NW+3)'(nmin_q[1])) + $signed((NW+3)'(prod >> DivS))
           - $signed((NW+3)'(tu_formats_pkg::PomBias));
    if (n_full < $signed((NW+3)'(lo_q[1])))      n_d = lo_q[1];
    else if (n_full > $signed((NW+3)'(hi_q[1]))) n_d = hi_q[1];
    else                                         n_d = n_full[NW-1:0];
  end

  logic neg_out_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      f_q       <= f_d;
      t_q       <= t_d;
      nmin_q[0] <= nmin_i;
      lo_q[0]   <= lo_d;
      hi_q[0]   <= hi_d;
      neg_q[0]  <= vz_i[VzW-1];
      y_q       <= y_d;
      nmin_q[1] <= nmin_q[0];
      lo_q[1]   <= lo_q[0];
      hi_q[1]   <= hi_q[0];
      neg_q[1]  <= neg_q[0];
      n_q       <= n_d;
      neg_out_q <= neg_q[1];
    end
  end
  assign n_o   = n_q;
  assign neg_o = neg_out_q;

  logic unused;
  assign unused = ^{stage_valid, prod[DivS-1:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {n_o, neg_o})
endmodule
