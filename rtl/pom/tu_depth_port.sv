// Depth-map port of the relief engines (tu_pom_march, tu_iter_parallax; DepthPort = 1): an
// external synchronous RAM with a 1-cycle read latency holding any power-of-two map of 2^lw x 2^lh
// bytes at `base`: address = base + (ty << lw) + tx, tx = floor(u * 2^lw) mod 2^lw, ty likewise
// (pom::tex_nearest: NEAREST, REPEAT; lw, lh <= 15 < PomUvF).
// take_i: the address is the new pixel's (u_i, v_i with its map base_i, lw_i, lh_i), else the
// current pixel's next T (nu_i, nv_i) in its map, registered when fire_i accepts a pixel. rd_i
// issues the read; h_o is its data in the next cycle, held in a register afterwards (a shared RAM
// may change its output meanwhile).
module tu_depth_port (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                take_i,
  input  logic                                fire_i,
  input  logic                                rd_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   nu_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   nv_i,
  output logic                                d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] d_addr_o,
  input  logic [7:0]                          d_data_i,
  output logic [7:0]                          h_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int AW = tu_formats_pkg::TexAddrW;
  logic [AW-1:0]  base_q, base_a;
  logic [3:0]     lw_q, lh_q, lw_a, lh_a;
  logic [UvW-1:0] ua, va;
  logic [15:0]    tx, ty;
  logic           rd_q;    // d_data_i answers last cycle's read
  logic [7:0]     hold_q;  // the last read's data, while no new read is issued
  always_comb begin
    if (take_i) begin
      ua = u_i; va = v_i; base_a = base_i; lw_a = lw_i; lh_a = lh_i;
    end else begin
      ua = nu_i; va = nv_i; base_a = base_q; lw_a = lw_q; lh_a = lh_q;
    end
    // bits [PomUvF-1 : PomUvF-lw] of u
    tx = 16'(ua >> (5'(tu_formats_pkg::PomUvF) - 5'(lw_a))) & ((16'd1 << lw_a) - 16'd1);
    ty = 16'(va >> (5'(tu_formats_pkg::PomUvF) - 5'(lh_a))) & ((16'd1 << lh_a) - 16'd1);
  end
  assign d_req_o  = rd_i;
  assign d_addr_o = base_a + (AW'(ty) << lw_a) + AW'(tx);
  assign h_o      = rd_q ? d_data_i : hold_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      base_q <= '0; lw_q <= '0; lh_q <= '0; rd_q <= 1'b0; hold_q <= '0;
    end else begin
      rd_q <= rd_i;
      hold_q <= h_o;
      if (fire_i) begin
        base_q <= base_i; lw_q <= lw_i; lh_q <= lh_i;
      end
    end
  end
endmodule
