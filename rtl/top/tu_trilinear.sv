// Trilinear filter (the trilinear engine of tu_texture_unit), exactly tex::trilinear(t, lod, u, v):
// l = lod >> TexLodF, f = its TexLodF-bit fraction; when l reaches the top level (max(lw, lh)) or
// the pixel is a B1-guard pixel, one bilinear pass (level top / the guard's texel); otherwise
// tu_bilinear at l and then at l + 1, and per channel round_half_up(a (1 - f) + b f) with TexLodF
// fraction bits. One pixel in flight: accepted at t, output valid at t + 15 (one pass: t + 8),
// accepts again the clock after its output is taken (ewa::stream_cycles).
`include "tu_assert.svh"
module tu_trilinear (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                in_valid_i,
  output logic                                in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0] u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0] v_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]  lod_i,    // GL rule (tu_ellipse tlod_o): TexLodF fraction bits, in [0, top]
  input  logic                                guard_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,
  input  logic [3:0]                          lw_i,
  input  logic [3:0]                          lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_i,   // {v, u} Wrap* codes (tu_texel_addr)
  output logic                                tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0] tex_addr_o,
  input  logic [31:0]                         tex_data_i,
  output logic                                out_valid_o,
  input  logic                                out_ready_i,
  output logic [31:0]                         rgba_o,
  output logic [3:0]                          level_o    // floor(lod): the finer level blended
);
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int LF = tu_formats_pkg::TexLodF;

  typedef enum logic [2:0] {Idle, IssueA, WaitA, IssueB, WaitB, Out} state_e;
  state_e state_q;
  logic [UW-1:0]                       u_q, v_q;
  logic                                guard_q, single_q;
  logic [2*tu_formats_pkg::WrapW-1:0]   wrap_q;
  logic [tu_formats_pkg::TexAddrW-1:0] base_q;
  logic [3:0]                          lw_q, lh_q, lev_q;
  logic [3:0]                          levb_q;  // the pass's level: lev_q, then lev_q + 1
  logic [LF-1:0]                       f_q;
  logic [31:0]                         a_q;

  // The lod's integer part: EllLodW - TexLodF = 4 bits (clamped to the top level upstream).
  logic [3:0] l_in, top_in;
  assign l_in   = lod_i[LF +: 4];
  assign top_in = lw_i > lh_i ? lw_i : lh_i;

  logic       b_in_valid, b_in_ready, b_out_valid, b_out_ready;
  logic [31:0] b_rgba;
  assign b_in_valid  = state_q == IssueA || state_q == IssueB;
  assign b_out_ready = state_q == WaitA || state_q == WaitB;
  tu_bilinear u_bil (
    .clk_i, .rst_ni, .in_valid_i(b_in_valid), .in_ready_o(b_in_ready),
    .u_i(u_q), .v_i(v_q), .guard_i(guard_q), .level_i(levb_q),
    .base_i(base_q), .lw_i(lw_q), .lh_i(lh_q), .wrap_i(wrap_q),
    .tex_req_o, .tex_addr_o, .tex_data_i,
    .out_valid_o(b_out_valid), .out_ready_i(b_out_ready), .rgba_o(b_rgba)
  );

  // a (1 - f) + b f, rounded half up, per channel.
  logic [31:0] blend;
  logic [LF:0] g;  // 1 - f
  assign g = (LF+1)'(1 << LF) - (LF+1)'(f_q);
  always_comb begin
    for (int c = 0; c < 4; c++) begin
      /* verilator lint_off UNUSEDSIGNAL */
      logic [8+LF:0] s;  // < 2^(8+LF): the rounded channel is s[LF +: 8]
      /* verilator lint_on UNUSEDSIGNAL */
      s = (9+LF)'(a_q[8*c +: 8]) * (9+LF)'(g) + (9+LF)'(b_rgba[8*c +: 8]) * (9+LF)'(f_q) + (9+LF)'(1 << (LF - 1));
      blend[8*c +: 8] = s[LF +: 8];
    end
  end

  assign in_ready_o  = state_q == Idle;
  assign out_valid_o = state_q == Out;
  assign level_o     = lev_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= Idle;
    end else begin
      unique case (state_q)
        Idle:    if (in_valid_i) state_q <= IssueA;
        IssueA:  if (b_in_ready) state_q <= WaitA;
        WaitA:   if (b_out_valid) state_q <= single_q ? Out : IssueB;
        IssueB:  if (b_in_ready) state_q <= WaitB;
        WaitB:   if (b_out_valid) state_q <= Out;
        Out:     if (out_ready_i) state_q <= Idle;
        default: state_q <= Idle;
      endcase
    end
  end
  always_ff @(posedge clk_i) begin
    if (state_q == Idle && in_valid_i) begin
      u_q      <= u_i;
      v_q      <= v_i;
      guard_q  <= guard_i;
      base_q   <= base_i;
      lw_q     <= lw_i;
      lh_q     <= lh_i;
      wrap_q   <= wrap_i;
      single_q <= guard_i || l_in >= top_in;
      lev_q    <= l_in >= top_in ? top_in : l_in;
      levb_q   <= l_in >= top_in ? top_in : l_in;
      f_q      <= lod_i[LF-1:0];
    end
    if (state_q == WaitA && b_out_valid) a_q <= b_rgba;
    if (state_q == WaitA) levb_q <= lev_q + 4'd1;  // (a register: no adder before u_bil's level)
    if (b_out_valid && (state_q == WaitA ? single_q : state_q == WaitB))
      rgba_o <= state_q == WaitA ? b_rgba : blend;
  end

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o})
endmodule
