// Valid tracking and global stall for a fixed-latency pipeline with a valid/ready interface.
// Every stage advances together when the last stage is empty or its output is taken, so the
// pipeline accepts one input per clock (II = 1) while the consumer keeps up, and holds every
// stage (losing nothing) while it does not.
module tu_pipe_valid #(
  parameter int Depth = 1
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             in_valid_i,
  output logic             in_ready_o,
  output logic             out_valid_o,
  input  logic             out_ready_i,
  output logic             en_o,          // advance every stage this cycle
  output logic [Depth-1:0] stage_valid_o  // valid bit of each stage register
);
  logic [Depth-1:0] valid_d, valid_q;

  assign en_o        = !valid_q[Depth-1] || out_ready_i;
  assign in_ready_o  = en_o;
  assign out_valid_o = valid_q[Depth-1];
  assign stage_valid_o = valid_q;

  if (Depth == 1) begin : g_one
    assign valid_d = in_valid_i;
  end else begin : g_many
    assign valid_d = {valid_q[Depth-2:0], in_valid_i};
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else if (en_o) begin
      valid_q <= valid_d;
    end
  end
endmodule
