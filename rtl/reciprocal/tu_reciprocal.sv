// Reciprocal unit with valid/ready: q (signed RecipInW-bit code) -> 1/q = R * 2^(F - p).
// Stage 0 normalises q (leading-one detect + left shift) to M in [1,2); q <= 0 raises flag and
// saturates (R = all ones, p = 0). Then tu_recip_core. Latency RecipLatency, II = 1.
`include "tu_assert.svh"
module tu_reciprocal
(
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   in_valid_i,
  output logic                   in_ready_o,
  input  logic [tu_formats_pkg::RecipInW-1:0]    q_i,
  output logic                   out_valid_o,
  input  logic                   out_ready_i,
  output logic [tu_formats_pkg::RecipOutW-1:0]   mant_o,
  output logic [tu_formats_pkg::RecipShiftW-1:0] shift_o,
  output logic                   flag_o
);
  localparam int CoreLat = tu_formats_pkg::RecipCoreLatency;  // tu_recip_core
  logic                 en;
  logic [tu_formats_pkg::RecipLatency-1:0] stage_valid;

  tu_pipe_valid #(.Depth(tu_formats_pkg::RecipLatency)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // Stage 0: normalise.
  logic                   bad;
  logic [tu_formats_pkg::RecipShiftW-1:0] msb;
  logic [tu_formats_pkg::RecipMantW-1:0]  m_d, m_q0;
  always_comb begin
    bad = q_i[tu_formats_pkg::RecipInW-1] || (q_i == '0);
    msb = '0;
    for (int i = 0; i < tu_formats_pkg::RecipInW - 1; i++) begin
      if (q_i[i]) msb = tu_formats_pkg::RecipShiftW'(i);
    end
    m_d = bad ? {1'b1, {(tu_formats_pkg::RecipMantW-1){1'b0}}}
              : tu_formats_pkg::RecipMantW'(q_i << (tu_formats_pkg::RecipMantW - 1 - 32'(msb)));
  end

  logic [tu_formats_pkg::RecipShiftW-1:0] p_q [CoreLat+1];
  logic                   bad_q [CoreLat+1];
  always_ff @(posedge clk_i) begin
    if (en) begin
      m_q0     <= m_d;
      p_q[0]   <= bad ? '0 : msb;
      bad_q[0] <= bad;
      for (int i = 1; i <= CoreLat; i++) begin
        p_q[i]   <= p_q[i-1];
        bad_q[i] <= bad_q[i-1];
      end
    end
  end

  logic [tu_formats_pkg::RecipOutW-1:0] r;
  tu_recip_core u_core (.clk_i, .en_i(en), .m_i(m_q0), .r_o(r));

  // The core's output lines up with the last delay slot (cycle tu_formats_pkg::RecipLatency after acceptance).
  assign mant_o  = bad_q[CoreLat] ? '1 : r;
  assign shift_o = p_q[CoreLat];
  assign flag_o  = bad_q[CoreLat];

  logic unused_stage_valid;
  assign unused_stage_valid = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {mant_o, shift_o, flag_o})
endmodule
