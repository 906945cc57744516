// Synchronous FIFO, valid/ready on both sides, Depth entries (a power of two >= 2, checked),
// registered storage.
// Decouples the fixed-latency B1/B2 pipelines from the data-dependent filter engine.
`include "tu_assert.svh"
module tu_fifo #(
  parameter int Width = 8,
  parameter int Depth = 4
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  input  logic [Width-1:0] in_data_i,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic [Width-1:0] out_data_o
);
  // The pointers wrap by overflow and the count compares with Depth: a power of two, at least 2.
  `TU_ASSERT_PARAM(g_depth_pow2, Depth >= 2 && (Depth & (Depth - 1)) == 0,
                   "Depth must be a power of two >= 2")
  localparam int PtrW = $clog2(Depth);
  logic [Width-1:0] mem_q [Depth];
  logic [PtrW-1:0]  wr_q, rd_q;
  logic [PtrW:0]    cnt_q;
  logic             push, pop;
  assign in_ready_o  = cnt_q != (PtrW+1)'(Depth);
  assign out_valid_o = cnt_q != '0;
  assign out_data_o  = mem_q[rd_q];
  assign push = in_valid_i && in_ready_o;
  assign pop  = out_valid_o && out_ready_i;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wr_q  <= '0;
      rd_q  <= '0;
      cnt_q <= '0;
    end else begin
      if (push) wr_q <= wr_q + PtrW'(1);
      if (pop)  rd_q <= rd_q + PtrW'(1);
      cnt_q <= cnt_q + (PtrW+1)'(push) - (PtrW+1)'(pop);
    end
  end
  always_ff @(posedge clk_i) begin
    if (push) mem_q[wr_q] <= in_data_i;
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {out_data_o})
endmodule
