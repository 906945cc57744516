// Clip volume, degree-3 polynomial (variant mm_p3), Horner on ONE shared multiplier (FSM).
//   accept (cycle 0): a, neg, acc = c3          busy (cycles 1..3): acc = c_k + floor(acc * a)
//   done (cycle 4):   out_valid, v = fold(round(acc)); a new input is accepted in the same cycle
//                     when the output is taken.
// Bit-identical to the pipelined Horner scheme. Latency ClipSeqLatency = 4, II ClipSeqIi = 4.
`include "tu_assert.svh"
module tu_clip_seq (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::ClipInW-1:0]  d_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::ClipOutW-1:0] v_o
);
  localparam int AccW = tu_formats_pkg::ClipAccW;
  typedef enum logic [1:0] {Idle, Busy, Done} state_e;
  state_e state_q;
  logic [1:0] k_q;
  logic [tu_formats_pkg::ClipAW-1:0] a, a_q;
  logic neg, neg_q, load;
  logic signed [AccW-1:0] acc_q, prod, ck;
  logic signed [tu_formats_pkg::ClipCoefW-1:0] c0, c1, c2, c3;
  tu_clip_coef_mm3 u_coef (.c0_o(c0), .c1_o(c1), .c2_o(c2), .c3_o(c3));
  tu_clip_abs u_abs (.d_i, .a_o(a), .neg_o(neg));
  tu_clip_mulfloor u_mul (.x_i(acc_q), .a_i(a_q), .c_i(AccW'(0)), .y_o(prod));  // the one multiplier
  always_comb begin
    unique case (k_q)
      2'd2:    ck = AccW'(c2);
      2'd1:    ck = AccW'(c1);
      default: ck = AccW'(c0);
    endcase
  end

  assign out_valid_o = state_q == Done;
  assign in_ready_o  = state_q == Idle || (state_q == Done && out_ready_i);
  assign load        = in_valid_i && in_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= Idle;
      k_q     <= '0;
    end else if (load) begin
      state_q <= Busy;
      k_q     <= 2'd2;
    end else if (state_q == Busy) begin
      k_q <= k_q - 2'd1;
      if (k_q == 2'd0) state_q <= Done;
    end else if (state_q == Done && out_ready_i) begin
      state_q <= Idle;
    end
  end
  always_ff @(posedge clk_i) begin
    if (load) begin
      a_q   <= a;
      neg_q <= neg;
      acc_q <= AccW'(c3);
    end else if (state_q == Busy) begin
      acc_q <= ck + prod;
    end
  end
  tu_clip_fold u_fold (.acc_i(acc_q), .neg_i(neg_q), .v_o(v_o));

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {v_o})
endmodule
