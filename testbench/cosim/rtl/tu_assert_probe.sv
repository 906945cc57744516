// Test fixture for rtl/common/tu_assert.svh (not a block of rtl/): a producer that can break the
// valid/ready rule on purpose. drop_i = 0: valid held high, data constant (legal under any stall);
// drop_i = 1: valid toggles and data counts regardless of ready (illegal while ready is low).
`include "tu_assert.svh"
module tu_assert_probe (
  input  logic       clk_i,
  input  logic       rst_ni,
  input  logic       drop_i,
  output logic       out_valid_o,
  input  logic       out_ready_i,
  output logic [7:0] data_o
);
  logic [7:0] cnt_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) cnt_q <= '0;
    else         cnt_q <= cnt_q + 8'd1;
  end
  assign out_valid_o = drop_i ? cnt_q[0] : 1'b1;
  assign data_o      = drop_i ? cnt_q : 8'd7;

  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, data_o)
endmodule
