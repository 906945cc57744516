// Iterative parallax engine (seed 002; docs/blocks/relief.md §7): one iteration per clock.
//   D = 0; loop: d = depth(T)*257 - D; stop if |d| < IpxEps, or flag nonconv at cap_i updates;
//   T -= round(d*(su, sv) / 2^16); D += round(d*sh / 2^16)           (3 multiplies, 4 adds)
// cap_i (1..63) is the per-pixel cap (the relief stage: the material's layers; the block's vectors:
// IpxCap). Outputs fract(T) (16 bits each), the update count and the non-convergence flag.
// Depth, DepthPort = 0: the same synchronous bricks ROM model as tu_pom_march (uv[14:10]);
// DepthPort = 1: the external synchronous depth RAM of tu_pom_march (d_* ports, 1-cycle read
// latency, map at base_i with log2 sides lw_i, lh_i, tu_depth_port), read in the cycles the ROM
// is, the data held in a register afterwards: the same cycles either way.
// A pixel takes iters + 3 cycles (accept, iters + 1 tests, output), no stalls; in_ready_o is high
// only when the engine holds no pixel. side_i is carried to side_o with the pixel.
`include "tu_assert.svh"
module tu_iter_parallax #(
  parameter int DepthPort = 0,
  parameter int SideW = 1
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PomUvW-1:0]   u_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   v_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   su_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   sv_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]   sh_i,
  input  logic [tu_formats_pkg::PomNW-1:0]    cap_i,
  input  logic [SideW-1:0]                    side_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  output logic                                d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] d_addr_o,
  input  logic [7:0]                          d_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [15:0]                         u_o,
  output logic [15:0]                         v_o,
  output logic [tu_formats_pkg::PomNW-1:0]    iters_o,
  output logic                                nonconv_o,
  output logic [SideW-1:0]                    side_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int TexLsb = tu_formats_pkg::PomUvF - 6;

  typedef enum logic [1:0] {Idle, Run, Done} state_e;
  state_e state_q;

  logic signed [UvW-1:0] tu_q, tv_q, su_q, sv_q, sh_q, d_acc_q;  // d_acc_q: ray depth D
  localparam int NW = tu_formats_pkg::PomNW;
  logic [NW-1:0]         i_q, cap_q;
  logic [7:0]            h;       // depth(T): ROM register or RAM data
  logic [SideW-1:0]      side_q;

  function automatic logic [7:0] bricks(input logic [4:0] x, input logic [4:0] y);
    logic [4:0] xs, xm;
    logic [3:0] dx, ym, dy, m;
    xs = x + (y[4] ? 5'd16 : 5'd0);
    xm = xs;
    dx = xm[4] ? 4'd15 - xm[3:0] : xm[3:0];
    ym = y[3:0];
    dy = (ym < 4'd8) ? ym : 4'd15 - ym;
    m  = (dx < dy) ? dx : dy;
    unique case (m)
      4'd0:    bricks = 8'd255;
      4'd1:    bricks = 8'd153;
      4'd2:    bricks = 8'd89;
      default: bricks = 8'd26;
    endcase
  endfunction

  logic signed [UvW-1:0] d, ad, nu, nv, nd;
  logic signed [63:0]    pu, pv, ph;
  logic [4:0]            ax, ay;
  logic                  conv, capped, upd, fire_in;

  assign fire_in = in_valid_i && in_ready_o;
  assign in_ready_o = (state_q == Idle);
  assign out_valid_o = (state_q == Done);

  always_comb begin
    d = $signed({16'd0, h, h}) - d_acc_q;             // h*257 - D
    ad = d[UvW-1] ? -d : d;
    conv = ad < $signed(UvW'(tu_formats_pkg::IpxEps));
    capped = (i_q == cap_q);
    upd = (state_q == Run) && !conv && !capped;
    // T - floor((d s + 2^15) / 2^16) = floor((T 2^16 - d s + 2^15 - 1) / 2^16) and
    // D + floor((d sh + 2^15) / 2^16) = floor((D 2^16 + d sh + 2^15) / 2^16): each update one
    // multiply-add (T or D inside the product's carry-save tree), no adder behind the multiplier
    // on the loop d -> T -> depth address -> h -> d (wrapped to UvW bits as before).
    pu = (64'(tu_q) <<< 16) - 64'(d) * 64'(su_q) + 64'sd32767;
    pv = (64'(tv_q) <<< 16) - 64'(d) * 64'(sv_q) + 64'sd32767;
    ph = (64'(d_acc_q) <<< 16) + 64'(d) * 64'(sh_q) + 64'sd32768;
    nu = UvW'(pu >>> 16);
    nv = UvW'(pv >>> 16);
    nd = UvW'(ph >>> 16);
    if (state_q == Idle) begin
      ax = u_i[TexLsb +: 5];
      ay = v_i[TexLsb +: 5];
    end else begin
      ax = nu[TexLsb +: 5];
      ay = nv[TexLsb +: 5];
    end
  end

  // Depth read: the first sample at acceptance, then the one of each update's new T.
  logic rd;
  assign rd = fire_in || upd;
  if (DepthPort != 0) begin : g_ram
    tu_depth_port u_port (
      .clk_i, .rst_ni, .take_i(state_q == Idle), .fire_i(fire_in), .rd_i(rd),
      .u_i, .v_i, .base_i, .lw_i, .lh_i, .nu_i(nu), .nv_i(nv),
      .d_req_o, .d_addr_o, .d_data_i, .h_o(h)
    );
    logic unused_rom;
    assign unused_rom = ^{ax, ay};
  end else begin : g_rom
    logic [7:0] h_q;  // synchronous ROM
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) h_q <= '0;
      else if (rd) h_q <= bricks(ax, ay);
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
      tu_q <= '0; tv_q <= '0; su_q <= '0; sv_q <= '0; sh_q <= '0; d_acc_q <= '0;
      i_q <= '0; cap_q <= '0; side_q <= '0;
      u_o <= '0; v_o <= '0; iters_o <= '0; nonconv_o <= 1'b0; side_o <= '0;
    end else begin
      unique case (state_q)
        Idle: if (fire_in) begin
          tu_q <= u_i; tv_q <= v_i; su_q <= su_i; sv_q <= sv_i; sh_q <= sh_i;
          d_acc_q <= '0;
          i_q <= '0;
          cap_q <= cap_i;
          side_q <= side_i;
          state_q <= Run;
        end
        Run: if (upd) begin
          tu_q <= nu;
          tv_q <= nv;
          d_acc_q <= nd;
          i_q <= i_q + 1'b1;
        end else begin
          u_o <= tu_q[15:0];
          v_o <= tv_q[15:0];
          iters_o <= i_q;
          nonconv_o <= !conv;
          side_o <= side_q;
          state_q <= Done;
        end
        Done: if (out_ready_i) state_q <= Idle;
        default: state_q <= Idle;
      endcase
    end
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, iters_o, nonconv_o, side_o})
endmodule
