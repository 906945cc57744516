// Nearest-texel filter at level L (the nearest engine of tu_texture_unit: the material's base
// level), exactly tex::nearest(t, L, u, v): texel (floor(u / 2^L), floor(v / 2^L)) of level L,
// wrapped like the texture; a
// B1-guard pixel: texel (0, 0) of the 1x1 top level (the texture's mean, as render_cmodel).
// One read (1-cycle latency): accepted at t, output valid at t + 3, accepts again the clock after
// its output is taken (ewa::stream_cycles).
`include "tu_assert.svh"
module tu_nearest (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0] u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0] v_i,
  input  logic                                guard_i,
  input  logic [3:0]                          level_i,  // L (TexUvF + L < 32)
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_i,   // {v, u} Wrap* codes (tu_texel_addr)
  output logic                                tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] tex_addr_o,
  input  logic [31:0]                         tex_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [31:0]                         rgba_o
);
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int F  = tu_formats_pkg::TexUvF;
  logic [1:0]                          st_q;  // 0 idle, 1 read, 2 data, 3 output
  logic signed [UW-1:0]                x_q, y_q;
  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_q;
  assign in_ready_o  = st_q == 2'd0;
  assign out_valid_o = st_q == 2'd3;
  assign tex_req_o   = st_q == 2'd1;
  // texel address: the level part (tu_texel_level) from the pixel's ports, registered with the
  // texel (x, y); only the wraps, the shift and one add (tu_texel_addr_xy) lie before tex_addr_o
  logic [3:0]                          wl_d, hl_d, wl_q, hl_q;
  logic [14:0]                         wm_d, hm_d, wm_q, hm_q;
  logic [tu_formats_pkg::TexAddrW-1:0] lb_d, bd_d, lb_q, bd_q;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i(guard_i ? (lw_i > lh_i ? lw_i : lh_i) : level_i),
    .wl_o(wl_d), .hl_o(hl_d), .wmask_o(wm_d), .hmask_o(hm_d), .lbase_o(lb_d), .border_o(bd_d));
  tu_texel_addr_xy #(.CoordW(UW)) u_addr (
    .wl_i(wl_q), .hl_i(hl_q), .wmask_i(wm_q), .hmask_i(hm_q), .lbase_i(lb_q), .border_i(bd_q),
    .wrap_i(wrap_q), .x_i(x_q), .y_i(y_q), .addr_o(tex_addr_o)
  );
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= 2'd0;
    else if (st_q == 2'd0) st_q <= in_valid_i ? 2'd1 : 2'd0;
    else if (st_q == 2'd3) st_q <= out_ready_i ? 2'd0 : 2'd3;
    else st_q <= st_q + 2'd1;
  end
  always_ff @(posedge clk_i) begin
    if (in_valid_i && in_ready_o) begin
      if (guard_i) begin  // (if/else: an unsigned '0 in a ?: would make >>> logical)
        x_q <= '0;
        y_q <= '0;
      end else begin
        x_q <= $signed(u_i) >>> (F + 32'(level_i));
        y_q <= $signed(v_i) >>> (F + 32'(level_i));
      end
      wl_q    <= wl_d;
      hl_q    <= hl_d;
      wm_q    <= wm_d;
      hm_q    <= hm_d;
      lb_q    <= lb_d;
      bd_q    <= bd_d;
      wrap_q  <= wrap_i;
    end
    if (st_q == 2'd2) rgba_o <= tex_data_i;
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o})
endmodule
