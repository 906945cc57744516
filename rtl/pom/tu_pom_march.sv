// POM march engine (docs/blocks/relief.md §6): one layer step per clock.
// Per pixel: T = (u, v), step dT = (du, dv) (uv: PomUvW bits, PomUvF fraction), N layers.
//   h_0 = depth(T); while 255*i < h_i*N: T -= dT, h = depth(T), i++      (exact integer rule)
//   out: T_k, k, a = 255k - h_k*N, den = a + h_{k-1}*N - 255(k-1)   (k = 0: a = den = 0)
// Depth map, DepthPort = 0: a synchronous 8-bit ROM model (nearest, REPEAT: texel = uv[15:10] of
// a 64x64 map) holding the procedural bricks map pom::map_bricks(64) (flat faces 26, bevels
// 153 / 89, mortar 255); that map repeats every 32 texels, so the ROM is addressed by uv[14:10].
// DepthPort = 1: an external synchronous RAM (1-cycle read latency) holding any power-of-two map
// of 2^lw x 2^lh bytes at `base` (given with the pixel): address = base + (ty << lw) + tx,
// tx = floor(u * 2^lw) mod 2^lw (pom::tex_nearest). The read data is used in the cycle after the
// request and kept in a register afterwards, so a RAM whose output changes (shared port) is fine.
// Same schedule either way.
// The address of T_{i+1} = T_i - dT is issued every Run cycle, so the sample is ready on the
// next cycle. The result moves to the output registers in the pixel's last compare cycle, and the
// next pixel is accepted in that same cycle (its first depth address replaces the unused next
// one), so a stream of pixels takes k + 1 cycles per pixel (k + 1 compares) without stalls;
// one pixel alone: accepted in cycle 0, output in cycle k + 2.
`include "tu_assert.svh"
module tu_pom_march #(
  parameter int SideW = 1,     // carried with the pixel (the unit's dT and flags)
  parameter int DepthPort = 0  // 0: bricks ROM; 1: external depth RAM (d_* ports)
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   du_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   dv_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    n_i,
  input  logic [SideW-1:0]                    side_i,
  // depth map of the pixel (DepthPort = 1 only): byte address of texel (0, 0), log2 sides
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  output logic                                d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] d_addr_o,
  input  logic [7:0]                          d_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [tu_formats_pkg::PomUvW-1:0]   u_o,
  output logic [tu_formats_pkg::PomUvW-1:0]   v_o,
  output logic [tu_formats_pkg::PomNW-1:0]    steps_o,
  output logic [15:0]                         a_o,
  output logic [15:0]                         den_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int NW = tu_formats_pkg::PomNW;
  localparam int TexLsb = tu_formats_pkg::PomUvF - 6;

  typedef enum logic {Idle, Run} state_e;
  state_e state_q;

  logic [UvW-1:0] tu_q, tv_q, du_q, dv_q;
  logic [NW-1:0]  n_q, i_q;
  logic [7:0]     h, hp_q;    // h: depth(T_i) (ROM register or RAM data); hp_q: depth(T_{i-1})
  logic           out_valid_q;
  logic [SideW-1:0] side_q;

  // Depth ROM (bricks 64x64), combinational part.
  function automatic logic [7:0] bricks(input logic [4:0] x, input logic [4:0] y);
    logic [4:0] xs;
    logic [4:0] xm, dx;
    logic [3:0] ym, dy, m;
    xs = x + (y[4] ? 5'd16 : 5'd0);
    xm = xs;
    dx = (xm < 5'd16) ? xm : 5'd31 - xm;
    ym = y[3:0];
    dy = (ym < 4'd8) ? ym : 4'd15 - ym;
    m  = (dx[3:0] < dy && dx[4] == 1'b0) ? dx[3:0] : dy;
    unique case (m)
      4'd0:    bricks = 8'd255;
      4'd1:    bricks = 8'd153;
      4'd2:    bricks = 8'd89;
      default: bricks = 8'd26;
    endcase
  endfunction

  logic [UvW-1:0] nu, nv;         // next T
  logic           go;             // continue marching
  logic           finish;         // last compare of the pixel in Run
  logic           out_free;       // the output registers can take a result this cycle
  logic           take_in;        // accept a pixel (Idle, or the previous pixel's last compare)
  logic [15:0]    lhs, rhs, rhs_p;   // 255*i, h*N, h_prev*N (< 2^14)
  logic           fire_in;
  logic           rd;             // a depth read is issued this cycle

  assign out_free    = !out_valid_q || out_ready_i;
  assign finish      = (state_q == Run) && !go;
  assign take_in     = (state_q == Idle) || (finish && out_free);
  assign in_ready_o  = take_in;
  assign fire_in     = in_valid_i && take_in;
  assign out_valid_o = out_valid_q;

  always_comb begin
    nu = tu_q - du_q;
    nv = tv_q - dv_q;
    lhs = 16'(8'd255 * i_q);
    rhs = 16'(h * n_q);
    rhs_p = 16'(hp_q * n_q);
    go = lhs < rhs;
  end

  assign rd = fire_in || (state_q == Run && go);

  if (DepthPort != 0) begin : g_ram
    tu_depth_port u_port (
      .clk_i, .rst_ni, .take_i(take_in), .fire_i(fire_in), .rd_i(rd),
      .u_i, .v_i, .base_i, .lw_i, .lh_i, .nu_i(nu), .nv_i(nv),
      .d_req_o, .d_addr_o, .d_data_i, .h_o(h)
    );
  end else begin : g_rom
    // synchronous ROM: the address of this cycle is read at the edge (kept while stalled).
    // Both candidate addresses are looked up in parallel, the new pixel's first T and the next T,
    // and the compare (take_in) selects between the two 8-bit depths: the address mux used to sit
    // between the compare and the ROM, i_q -> h_q in one clock, the block's critical path.
    logic [7:0] h_q, h_in, h_nx;
    assign h_in = bricks(u_i[TexLsb +: 5], v_i[TexLsb +: 5]);
    assign h_nx = bricks(nu[TexLsb +: 5], nv[TexLsb +: 5]);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) h_q <= '0;
      else if (rd) h_q <= take_in ? h_in : h_nx;
    end
    assign h = h_q;
    assign d_req_o  = 1'b0;
    assign d_addr_o = '0;
    logic unused_ram;
    assign unused_ram = ^{base_i, lw_i, lh_i, d_data_i};
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= Idle;
      tu_q <= '0; tv_q <= '0; du_q <= '0; dv_q <= '0;
      n_q <= '0; i_q <= '0; hp_q <= '0;
      out_valid_q <= 1'b0;
      side_q <= '0; side_o <= '0;
      u_o <= '0; v_o <= '0; steps_o <= '0; a_o <= '0; den_o <= '0;
    end else begin
      // output registers
      if (finish && out_free) begin
        u_o <= tu_q;
        v_o <= tv_q;
        side_o <= side_q;
        steps_o <= i_q;
        if (i_q == '0) begin
          a_o <= '0;
          den_o <= '0;
        end else begin
          a_o <= lhs - rhs;
          // (lhs - rhs) + (rhs_p - (lhs - 255)): lhs cancels (mod 2^16), and with it the i_q path
          den_o <= rhs_p - rhs + 16'd255;
        end
        out_valid_q <= 1'b1;
      end else if (out_ready_i) begin
        out_valid_q <= 1'b0;
      end
      // march state
      if (fire_in) begin
        tu_q <= u_i; tv_q <= v_i; du_q <= du_i; dv_q <= dv_i; n_q <= n_i; side_q <= side_i;
        i_q <= '0;
        state_q <= Run;
      end else if (state_q == Run && go) begin
        hp_q <= h;
        tu_q <= nu;
        tv_q <= nv;
        i_q <= i_q + 1'b1;
      end else if (finish && out_free) begin
        state_q <= Idle;
      end
    end
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, steps_o, a_o, den_o, side_o})
endmodule
