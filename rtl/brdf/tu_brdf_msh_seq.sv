// F_MSH on one shared multiplier (brdf_msh.hpp, bit-identical to tu_brdf_msh): an FSM takes one
// input at a time and sends every product through one MulW x MulW multiplier:
//   SU:  u  = n t (exact)                     SKC: KC = round_half_up(1.6 c), D = u + 1.25c (exact)
//   SW0-SW3: tu_recip_core on norm(D)         SR2: R2 = round_half_up(R^2)
//   SF:  F = sat(round_half_up(KC R2 >> (2p - 4)))   then DONE until the output is taken.
// A new input is accepted in IDLE or in the cycle DONE's output is taken: latency
// BrdfMshSeqLatency, initiation interval BrdfMshSeqIi.
module tu_brdf_msh_seq (
  input  logic                               clk_i,
  input  logic                               rst_ni,
  input  logic                               in_valid_i,
  output logic                               in_ready_o,
  input  logic [tu_formats_pkg::BrdfCW-1:0]  c_i,
  input  logic [tu_formats_pkg::BrdfNW-1:0]  n_i,
  input  logic [tu_formats_pkg::BrdfClW-1:0] ccut_i,
  output logic                               out_valid_o,
  input  logic                               out_ready_i,
  output logic [tu_formats_pkg::BrdfOutW-1:0] f_o,
  output logic                               flag_o
);
  localparam int ClW = tu_formats_pkg::BrdfClW;
  localparam int NW  = tu_formats_pkg::BrdfNW;
  localparam int UW  = tu_formats_pkg::BrdfUW;
  localparam int DW  = tu_formats_pkg::BrdfDW;
  localparam int RW  = tu_formats_pkg::RecipOutW;
  localparam int WF  = tu_formats_pkg::BrdfWF;
  localparam int W1  = WF + 1;
  localparam int OW  = tu_formats_pkg::BrdfOutW;
  localparam int MulW = 26;  // widest operand: the constant 1.6 (BrdfK16)
  localparam int PW  = 2 * MulW;
  localparam logic [ClW-1:0] One = ClW'(1) << tu_formats_pkg::BrdfCF;

  typedef enum logic [3:0] {Idle, Su, Skc, Sw0, Sw1, Sw2, Sw3, Sr2, Sf, Done} state_e;
  state_e state_q, state_d;

  logic [ClW-1:0] c, c_q;
  logic [UW-1:0]  u_unused;
  logic [NW-1:0]  n, n_q;
  logic           cut, flag, cut_q, flag_q;
  tu_brdf_front u_front (.c_i, .n_i, .ccut_i, .c_o(c), .u_o(u_unused), .n_o(n), .cut_o(cut),
                         .flag_o(flag));

  logic accept, take;
  assign take       = state_q == Done && out_ready_i;
  assign accept     = in_valid_i && in_ready_o;
  assign in_ready_o = state_q == Idle || take;
  assign out_valid_o = state_q == Done;

  // The shared multiplier and its operands.
  logic [MulW-1:0] ma, mb;
  logic [ClW-1:0]  t_q;
  assign t_q = One - c_q;
  logic [PW-1:0]   prod;
  logic [UW-1:0]   u_q;
  logic [W1-1:0]   kc_q, r2_q;
  logic [DW-1:0]   d_q;
  logic [RW-1:0]   r;
  logic [5:0]      p;
  always_comb begin
    ma = '0;
    mb = '0;
    case (state_q)
      Su:  begin ma = MulW'(n_q);  mb = MulW'(t_q); end
      Skc: begin ma = MulW'(tu_formats_pkg::BrdfK16);  mb = MulW'(c_q); end
      Sr2: begin ma = MulW'(r);    mb = MulW'(r); end
      Sf:  begin ma = MulW'(kc_q); mb = MulW'(r2_q); end
      default: ;
    endcase
  end
  assign prod = ma * mb;

  logic [6:0] sh;
  always_comb begin
    case (state_q)
      Skc:     sh = 7'(tu_formats_pkg::BrdfCF + tu_formats_pkg::BrdfKF - WF);
      Sr2:     sh = 7'(2 * tu_formats_pkg::RecipOutF - WF);
      default: sh = 7'({p, 1'b0}) - 7'(2 * tu_formats_pkg::BrdfDF + tu_formats_pkg::BrdfOutF - 2 * WF);
    endcase
  end
  logic [PW-1:0] rounded;
  tu_brdf_rnd #(.InW(PW), .OutW(PW)) u_rnd (.x_i(prod), .sh_i(sh), .y_o(rounded));
  logic [OW-1:0] f_sat, f_q;
  assign f_sat = rounded > PW'({OW{1'b1}}) ? '1 : OW'(rounded);

  logic [DW-1:0] d;
  assign d = (DW'(u_q) << 2) + (DW'(c_q) << 2) + DW'(c_q);  // u + 1.25c, CF + 2 = DF frac bits

  // D stays in d_q while the core's four stages fill (free-running enable).
  tu_brdf_recip #(.InW(DW)) u_recip (.clk_i, .en_i(1'b1), .q_i(d_q), .r_o(r), .p_o(p));

  always_comb begin
    state_d = state_q;
    case (state_q)
      Idle:    if (accept) state_d = Su;
      Su:      state_d = Skc;
      Skc:     state_d = Sw0;
      Sw0:     state_d = Sw1;
      Sw1:     state_d = Sw2;
      Sw2:     state_d = Sw3;
      Sw3:     state_d = Sr2;
      Sr2:     state_d = Sf;
      Sf:      state_d = Done;
      Done: begin
        if (take && accept) state_d = Su;
        else if (take)      state_d = Idle;
      end
      default: state_d = Idle;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) state_q <= Idle;
    else         state_q <= state_d;
  end
  always_ff @(posedge clk_i) begin
    if (accept) begin
      c_q <= c;  n_q <= n;  cut_q <= cut;  flag_q <= flag;
    end
    case (state_q)
      Su:  u_q <= UW'(prod);
      Skc: begin kc_q <= W1'(rounded);  d_q <= d; end
      Sr2: r2_q <= W1'(rounded);
      Sf:  f_q <= cut_q ? '0 : f_sat;
      default: ;
    endcase
  end
  assign f_o = f_q;
  assign flag_o = flag_q;

  logic unused;
  assign unused = ^u_unused;
endmodule
