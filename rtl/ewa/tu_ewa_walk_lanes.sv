// EWA multi-texel walk (issue 23, docs/blocks/ewa.md "Multi-texel walk"): four texels per clock as
// a 2 x 2 block, bit-exact with ewa::fx::walk_lanes and so with the sequential walk (tu_ewa_walk,
// ewa::fx::walk): the same texel set (the set-up's box), the same exact sums.
//   P0     block (bx, by), bx, by even, row-major over the box's aligned blocks; lane l at
//          (bx + l[0], by + l[1]), masked outside the box. Per lane Q, xi, eta step two texels
//          along x (Q += D, D += 4 ddQ, D = Q(x + 2) - Q(x)) and, at a block-row start, two rows
//          (Q += 2 e + ddQy, e += 2 ddQy, D += 4 dQy): exact integers, the set-up's values at the
//          aligned corner (tu_ewa_setup Align) spread to the lanes by their differences
//   P1     per lane: inside = Q < 1, Q / xi / eta codes, texel address, bank {y' & 1, x' & 1} of
//          the wrapped coordinate (tu_ewa_bank); bank ports: a lane reads the port of its bank
//          (lanes on one texel share it: broadcast), border texels the lowest free port
//   P1..P5 weights per lane (formula 3 + 1, 1-D table 3 + 1, 2-D table 4; wsrc per pixel)
//   R      the bank ports' reads (P4; with HasClip P4 + BorderLat, data at the accumulate stage)
//   A      (P5, or P5 + BorderLat with HasClip: every pixel's weights pass the border pipeline's
//          depth, its own border weights if clip_i, so pixels stay in order) the K-input sums:
//          acc_c += sum_l w_l texel_lc (< 2^26 per clock), wsum, inside count; a pixel's first block
//          restarts the sums, its last hands them to the normaliser
//   N0..N5 normalisation as tu_ewa_walk's (mantissa, the reciprocal core to y in 3 stages, the
//          products' carry-save pairs, carry chain + shift + saturate: tu_ewa_norm_tail), pipelined:
//          one pixel per clock; wsum = 0 or a B1-guard record: the nearest texel at L (the lane
//          on it, captured at A) instead
// The walker takes the next record in the clock it issues the current pixel's last block, so the
// drain and normalisation overlap the next pixel: f = blocks clocks per pixel; output valid at
// last issue + 12 (+ BorderLat with HasClip). At most OutDepth pixels between hand-over and
// output (credits: the output FIFO never overflows under back-pressure). Cycle model:
// ewa::StreamModel with EngineParams::lanes = 4 (cmodel/blocks/ewa/ewa_cycles.hpp).
`include "tu_assert.svh"
module tu_ewa_walk_lanes #(
  parameter int HasClip     = 0,
  parameter int ClipVariant = 0,
  parameter int OutDepth    = 8   // pixels between hand-over and output (a power of two >= 2)
) (
  input  logic                                     clk_i,
  input  logic                                     rst_ni,
  input  logic                                     rec_valid_i,
  output logic                                     rec_ready_o,
  input  logic [3:0]                               level_i,
  input  logic [4:0]                               flags_i,
  input  logic                                     guard_i,  // B1 guard: texel (0, 0) of level_i
  input  logic signed [31:0]                       x0_i,
  input  logic signed [31:0]                       x1_i,
  input  logic signed [31:0]                       y0_i,
  input  logic signed [31:0]                       y1_i,
  input  logic [tu_formats_pkg::EwaCountW-1:0]     box_i,
  input  logic signed [31:0]                       cu_i,
  input  logic signed [31:0]                       cv_i,
  // start values at the aligned corner (x0 & ~1, y0 & ~1) and their differences (tu_ewa_setup)
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] xi0_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] eta0_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] dxi_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] deta_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] dxiy_i,
  input  logic signed [tu_formats_pkg::EwaXiW-1:0] detay_i,
  input  logic signed [63:0]                       q0_i,
  input  logic signed [63:0]                       dq0_i,
  input  logic signed [63:0]                       ddq_i,
  input  logic signed [63:0]                       ey0_i,
  input  logic signed [63:0]                       ddqy_i,
  input  logic signed [63:0]                       dqy_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]      base_i,
  input  logic [3:0]                               lw_i,
  input  logic [3:0]                               lh_i,
  input  logic [2*tu_formats_pkg::WrapW-1:0]       wrap_i,
  input  logic [1:0]                               wsrc_i,
  input  logic                                     clip_i,
  // four bank ports (1-cycle read latency), port b = bank b
  output logic [3:0]                               tex_req_o,
  output logic [4*tu_formats_pkg::TexAddrW-1:0]    tex_addr_o,
  input  logic [4*32-1:0]                          tex_data_i,
  output logic                                     out_valid_o,
  input  logic                                     out_ready_i,
  output logic [31:0]                              rgba_o,
  output logic [3:0]                               level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     inside_o,
  output logic [4:0]                               flags_o
);
  localparam int L    = 4;
  localparam int XiW  = tu_formats_pkg::EwaXiW;
  localparam int PosF = tu_formats_pkg::EwaPosF;
  localparam int QF   = 2 * (tu_formats_pkg::EwaKF + PosF);
  localparam int GQW  = tu_formats_pkg::GaussQW;
  localparam int GXW  = tu_formats_pkg::GaussXiW;
  localparam int WW   = tu_formats_pkg::GaussSqW;
  localparam int WsW  = tu_formats_pkg::EwaWsumW;
  localparam int AcW  = tu_formats_pkg::EwaAccW;
  localparam int NrW  = tu_formats_pkg::EwaNrmW;
  localparam int MW   = tu_formats_pkg::RecipMantW;
  localparam int NW   = tu_formats_pkg::EwaCountW;
  localparam int AW   = tu_formats_pkg::TexAddrW;
  localparam int KW   = tu_formats_pkg::EwaKW;
  localparam int WrW  = tu_formats_pkg::WrapW;
  localparam int ClipLat = ClipVariant == 1 ? tu_formats_pkg::ClipHornerLatency
                         : ClipVariant == 2 ? tu_formats_pkg::ClipEstrinLatency
                                            : tu_formats_pkg::ClipP1Latency;
  localparam int BorderLat = 1 + 1 + tu_formats_pkg::EwaRootW + 1 + tu_formats_pkg::ClipInF + 1 + ClipLat + 1;
  localparam int BL   = HasClip != 0 ? BorderLat : 0;
  localparam int RD   = 3 + BL;                     // P1 -> read stage R
  localparam int CntW = $clog2(OutDepth + 1);
  localparam int BsW  = WW + 8 + 2;                 // one clock's sum of 4 products w texel
  `TU_ASSERT_PARAM(g_out_depth, OutDepth >= 2 && (OutDepth & (OutDepth - 1)) == 0,
                   "OutDepth must be a power of two >= 2")

  // ---- P0: the pixel being walked
  logic                  busy_q, first_q, guard_q, clip_q;
  logic [3:0]            lev_q, lw_q, lh_q;
  logic [1:0]            wsrc_q;
  logic [2*WrW-1:0]      wrap_q;
  // the texel address's level part (tu_texel_level), registered with the record
  logic [3:0]            wl_d, hl_d, wl_q, hl_q;
  logic [14:0]           wm_d, hm_d, wm_q, hm_q;
  logic [AW-1:0]         lb_d, bd_d, lb_q, bd_q;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i, .wl_o(wl_d), .hl_o(hl_d), .wmask_o(wm_d), .hmask_o(hm_d),
    .lbase_o(lb_d), .border_o(bd_d));
  logic signed [31:0]    x0_q, x1_q, y0_q, y1_q, xa0_q, xa1_q, ya1_q, nx_q, ny_q, bx_q, by_q;
  logic signed [63:0]    dd4_q, ddqy_q, ddqy2_q, dqy4_q;
  logic signed [XiW-1:0] dxi2_q, deta2_q, dxiy2_q, detay2_q;
  logic signed [KW-1:0]  kxu_q, kxv_q, kyu_q, kyv_q;
  logic signed [63:0]    q_q [L], d_q [L], qr_q [L], dr_q [L], er_q [L];
  logic signed [XiW-1:0] xi_q [L], eta_q [L], xir_q [L], etar_q [L];

  logic            row_end, blk_last, load, pop;
  logic [CntW-1:0] cnt_q;
  assign row_end     = bx_q == xa1_q;
  assign blk_last    = busy_q && row_end && by_q == ya1_q;
  assign rec_ready_o = cnt_q < CntW'(OutDepth) && (!busy_q || blk_last);
  assign load        = rec_valid_i && rec_ready_o;

  // lane start values from the corner's: lane 1 one texel right, 2 one row down, 3 both
  logic signed [63:0]    q0l [L], d0l [L], e0l [L];
  logic signed [XiW-1:0] xi0l [L], eta0l [L];
  always_comb begin
    q0l[0] = q0_i;
    q0l[1] = q0_i + dq0_i;
    q0l[2] = q0_i + ey0_i;
    q0l[3] = q0_i + ey0_i + dq0_i + dqy_i;
    d0l[0] = (dq0_i <<< 1) + ddq_i;  // D = 2 dQ + ddQ, dQ the lane's one-texel difference
    d0l[1] = d0l[0] + (ddq_i <<< 1);
    d0l[2] = d0l[0] + (dqy_i <<< 1);
    d0l[3] = d0l[2] + (ddq_i <<< 1);
    e0l[0] = ey0_i;
    e0l[1] = ey0_i + dqy_i;
    e0l[2] = ey0_i + ddqy_i;
    e0l[3] = ey0_i + dqy_i + ddqy_i;
    xi0l[0] = xi0_i;
    xi0l[1] = xi0_i + dxi_i;
    xi0l[2] = xi0_i + dxiy_i;
    xi0l[3] = xi0_i + dxi_i + dxiy_i;
    eta0l[0] = eta0_i;
    eta0l[1] = eta0_i + deta_i;
    eta0l[2] = eta0_i + detay_i;
    eta0l[3] = eta0_i + deta_i + detay_i;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      cnt_q  <= '0;
    end else begin
      if (load) busy_q <= 1'b1;
      else if (blk_last) busy_q <= 1'b0;
      cnt_q <= cnt_q + CntW'(load) - CntW'(pop);
    end
  end

  always_ff @(posedge clk_i) begin
    if (load) begin
      first_q <= 1'b1;
      guard_q <= guard_i;
      clip_q  <= HasClip != 0 && clip_i && !guard_i;
      lev_q   <= level_i;  lw_q <= lw_i;  lh_q <= lh_i;  wrap_q <= wrap_i;
      wl_q    <= wl_d;  hl_q <= hl_d;  wm_q <= wm_d;  hm_q <= hm_d;  lb_q <= lb_d;  bd_q <= bd_d;
      wsrc_q  <= wsrc_i;
      // a guard record (stale box): the single texel (0, 0), the nearest texel of cu = cv = 0
      x0_q  <= guard_i ? '0 : x0_i;
      x1_q  <= guard_i ? '0 : x1_i;
      y0_q  <= guard_i ? '0 : y0_i;
      y1_q  <= guard_i ? '0 : y1_i;
      xa0_q <= guard_i ? '0 : x0_i & ~32'sd1;
      xa1_q <= guard_i ? '0 : x1_i & ~32'sd1;
      ya1_q <= guard_i ? '0 : y1_i & ~32'sd1;
      bx_q  <= guard_i ? '0 : x0_i & ~32'sd1;
      by_q  <= guard_i ? '0 : y0_i & ~32'sd1;
      nx_q  <= (cu_i + 32'sd32) >>> PosF;  // the nearest texel (ewa::fx::finish)
      ny_q  <= (cv_i + 32'sd32) >>> PosF;
      dd4_q   <= ddq_i <<< 2;
      ddqy_q  <= ddqy_i;
      ddqy2_q <= ddqy_i <<< 1;
      dqy4_q  <= dqy_i <<< 2;
      dxi2_q  <= dxi_i <<< 1;   deta2_q  <= deta_i <<< 1;
      dxiy2_q <= dxiy_i <<< 1;  detay2_q <= detay_i <<< 1;
      kxu_q <= KW'(dxi_i >>> PosF);   kyu_q <= KW'(deta_i >>> PosF);
      kxv_q <= KW'(dxiy_i >>> PosF);  kyv_q <= KW'(detay_i >>> PosF);
      for (int l = 0; l < L; l++) begin
        q_q[l]  <= q0l[l];   qr_q[l] <= q0l[l];
        d_q[l]  <= d0l[l];   dr_q[l] <= d0l[l];
        er_q[l] <= e0l[l];
        xi_q[l] <= xi0l[l];  xir_q[l] <= xi0l[l];
        eta_q[l] <= eta0l[l];  etar_q[l] <= eta0l[l];
      end
    end else if (busy_q) begin
      first_q <= 1'b0;
      if (!row_end) begin  // two texels along x
        bx_q <= bx_q + 32'sd2;
        for (int l = 0; l < L; l++) begin
          q_q[l]   <= q_q[l] + d_q[l];
          d_q[l]   <= d_q[l] + dd4_q;
          xi_q[l]  <= xi_q[l] + dxi2_q;
          eta_q[l] <= eta_q[l] + deta2_q;
        end
      end else if (!blk_last) begin  // two rows down
        bx_q <= xa0_q;
        by_q <= by_q + 32'sd2;
        for (int l = 0; l < L; l++) begin
          q_q[l]    <= qr_q[l] + (er_q[l] <<< 1) + ddqy_q;
          qr_q[l]   <= qr_q[l] + (er_q[l] <<< 1) + ddqy_q;
          er_q[l]   <= er_q[l] + ddqy2_q;
          d_q[l]    <= dr_q[l] + dqy4_q;
          dr_q[l]   <= dr_q[l] + dqy4_q;
          xi_q[l]   <= xir_q[l] + dxiy2_q;
          xir_q[l]  <= xir_q[l] + dxiy2_q;
          eta_q[l]  <= etar_q[l] + detay2_q;
          etar_q[l] <= etar_q[l] + detay2_q;
        end
      end
    end
  end

  // ---- P0 -> P1: per lane inside, codes, address, bank
  logic signed [31:0] xl [L], yl [L];
  logic [L-1:0]       inbox;
  logic [AW-1:0]      addr0 [L];
  logic [1:0]         bank0 [L];
  logic [L-1:0]       oob0;
  for (genvar l = 0; l < L; l++) begin : g_lane_addr
    assign xl[l] = bx_q + 32'(l % 2);
    assign yl[l] = by_q + 32'(l / 2);
    assign inbox[l] = xl[l] >= x0_q && xl[l] <= x1_q && yl[l] >= y0_q && yl[l] <= y1_q;
    tu_texel_addr_xy #(.CoordW(32)) u_addr (
      .wl_i(wl_q), .hl_i(hl_q), .wmask_i(wm_q), .hmask_i(hm_q), .lbase_i(lb_q), .border_i(bd_q),
      .wrap_i(wrap_q), .x_i(xl[l]), .y_i(yl[l]), .addr_o(addr0[l]));
    tu_ewa_bank #(.CoordW(32)) u_bank (
      .lw_i(lw_q), .lh_i(lh_q), .wrap_i(wrap_q), .level_i(lev_q), .x_i(xl[l]), .y_i(yl[l]),
      .bank_o(bank0[l]), .oob_o(oob0[l]));
  end

  logic                 v1_q, first1_q, last1_q, guard1_q, clip1_q;
  logic [1:0]           wsrc1_q;
  logic [L-1:0]         act1_q, in1_q, near1_q, oob1_q;
  logic [GQW-1:0]       qc1_q [L];
  logic [GXW-1:0]       xic1_q [L], etac1_q [L];
  logic [AW-1:0]        addr1_q [L];
  logic [1:0]           bank1_q [L];
  always_ff @(posedge clk_i) begin
    v1_q     <= busy_q;
    first1_q <= first_q;
    last1_q  <= blk_last;
    guard1_q <= guard_q;
    clip1_q  <= clip_q;
    wsrc1_q  <= wsrc_q;
    for (int l = 0; l < L; l++) begin
      act1_q[l]  <= busy_q && inbox[l];
      in1_q[l]   <= busy_q && inbox[l] && q_q[l] < (64'sd1 <<< QF);
      near1_q[l] <= busy_q && inbox[l] && xl[l] == nx_q && yl[l] == ny_q;
      oob1_q[l]  <= oob0[l];
      qc1_q[l]   <= GQW'(q_q[l] >>> (QF - tu_formats_pkg::GaussQF));
      xic1_q[l]  <= GXW'(xi_q[l] >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
      etac1_q[l] <= GXW'(eta_q[l] >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
      addr1_q[l] <= addr0[l];
      bank1_q[l] <= bank0[l];
    end
  end

  // ---- P1: bank ports. Lanes in the level read their bank's port (one texel per bank: the wrap
  // property above; lanes on one texel share the read); border lanes (all the border word) read
  // the lowest port no lane in the level uses (there is one: each border lane frees a bank).
  logic [3:0]    used, preq;
  logic [1:0]    free, port [L];
  logic [AW-1:0] paddr [4];
  logic          any_oob;
  always_comb begin
    used = '0;
    any_oob = 1'b0;
    for (int l = 0; l < L; l++) begin
      if (act1_q[l] && !oob1_q[l]) used[bank1_q[l]] = 1'b1;
      if (act1_q[l] && oob1_q[l]) any_oob = 1'b1;
    end
    free = 2'd3;
    for (int b = 3; b >= 0; b--) if (!used[b]) free = 2'(b);
    for (int b = 0; b < 4; b++) paddr[b] = '0;
    for (int l = L - 1; l >= 0; l--) begin
      port[l] = oob1_q[l] ? free : bank1_q[l];
      if (act1_q[l]) paddr[port[l]] = addr1_q[l];
    end
    preq = used;
    if (any_oob) preq[free] = 1'b1;
  end
`ifndef YOSYS
  // every lane of a port reads the port's address: no bank conflict (simulation check; an alias
  // of rst_ni, as tu_assert.svh: read directly, rst_ni would be used both sync and async)
  logic chk_on;
  assign chk_on = rst_ni;
  always @(posedge clk_i) begin  // (not always_ff: a simulation check, as tu_assert.svh's)
    for (int l = 0; l < L; l++)
      if (chk_on && v1_q && act1_q[l] && paddr[port[l]] != addr1_q[l])
        $error("%m: bank conflict: lane %0d, port %0d", l, port[l]);
  end
`endif

  // ---- P1 -> R -> A: the read bundle (token, lanes' flags and ports, the ports' requests)
  localparam int TokW = 5 + 4 * L;          // v first last guard clip | act near | port (2 bits)
  localparam int RbW  = TokW + 4 + 4 * AW;  // | preq | paddr
  logic [RbW-1:0]  rb_d, rb_r;
  logic [TokW-1:0] tok_a_q;
  always_comb begin
    rb_d = {v1_q, first1_q, last1_q, guard1_q, clip1_q, act1_q, near1_q,
            port[3], port[2], port[1], port[0], preq, paddr[3], paddr[2], paddr[1], paddr[0]};
  end
  tu_brdf_delay #(.W(RbW), .Depth(RD)) u_rb (.clk_i, .en_i(1'b1), .d_i(rb_d), .q_o(rb_r));
  assign tex_req_o  = rb_r[4*AW +: 4];
  assign tex_addr_o = rb_r[4*AW-1:0];
  always_ff @(posedge clk_i) tok_a_q <= rb_r[RbW-1 -: TokW];
  logic         va, firsta, lasta, guarda, clipa;
  logic [L-1:0] acta, neara;
  logic [1:0]   porta [L];
  assign {va, firsta, lasta, guarda, clipa, acta, neara, porta[3], porta[2], porta[1], porta[0]} = tok_a_q;

  // ---- P1..P5: weights per lane (all three sources run; the shorter pipelines padded to 4)
  logic [1:0]   wsrc5;
  logic [L-1:0] in5;
  tu_brdf_delay #(.W(2 + L), .Depth(4)) u_w5d (.clk_i, .en_i(1'b1), .d_i({wsrc1_q, in1_q}), .q_o({wsrc5, in5}));
  logic [WW-1:0] w5 [L];
  logic [5:0]    hs_unused [L];
  for (genvar l = 0; l < L; l++) begin : g_lane_w
    logic [WW-1:0] w_f, w_f_q;
    logic [tu_formats_pkg::WtabEntryW-1:0] w_1, w_1_q, w_2;
    tu_gauss_weight u_wf (
      .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[l][0]), .q_i(qc1_q[l]),
      .out_valid_o(hs_unused[l][1]), .out_ready_i(1'b1), .w_o(w_f));
    tu_weight_table_1d #(.Log2N(8)) u_w1 (
      .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[l][2]), .q_i(qc1_q[l]),
      .out_valid_o(hs_unused[l][3]), .out_ready_i(1'b1), .w_o(w_1));
    tu_weight_table_2d #(.Log2N(5)) u_w2 (
      .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[l][4]), .xi_i(xic1_q[l]), .eta_i(etac1_q[l]),
      .out_valid_o(hs_unused[l][5]), .out_ready_i(1'b1), .w_o(w_2));
    always_ff @(posedge clk_i) begin
      w_f_q <= w_f;
      w_1_q <= w_1;
    end
    always_comb begin
      unique case (wsrc5)
        tu_formats_pkg::WsrcTable1d: w5[l] = WW'(w_1_q);
        tu_formats_pkg::WsrcTable2d: w5[l] = WW'(w_2);
        default: w5[l] = w_f_q;
      endcase
      if (!in5[l]) w5[l] = '0;
    end
  end

  // ---- weights at A: P5's, or (HasClip) through the border pipeline's depth: the border weight
  // for a clip pixel, the P5 weight delayed for the others
  logic [WW-1:0] wacc [L];
  if (HasClip != 0) begin : g_border
    localparam int QdW = tu_formats_pkg::EwaQW + 2 * XiW;
    logic [4*KW-1:0] k5;
    logic [1:0]      vc5;
    logic [L*WW-1:0] w5d;
    tu_brdf_delay #(.W(4 * KW), .Depth(5)) u_kd (
      .clk_i, .en_i(1'b1), .d_i({kxu_q, kxv_q, kyu_q, kyv_q}), .q_o(k5));
    tu_brdf_delay #(.W(2), .Depth(4)) u_vd (.clk_i, .en_i(1'b1), .d_i({v1_q, clip1_q}), .q_o(vc5));
    tu_brdf_delay #(.W(L * WW), .Depth(BL)) u_wd (
      .clk_i, .en_i(1'b1), .d_i({w5[3], w5[2], w5[1], w5[0]}), .q_o(w5d));
    for (genvar l = 0; l < L; l++) begin : g_lane_b
      logic [QdW-1:0] qd5;
      logic           bvalid, bready_unused;
      logic [WW-1:0]  bw;
      logic [tu_formats_pkg::ClipInW-1:0] bd_unused;
      logic [1:0]     bzone_unused;
      tu_brdf_delay #(.W(QdW), .Depth(5)) u_qdly (
        .clk_i, .en_i(1'b1), .d_i({q_q[l][tu_formats_pkg::EwaQW-1:0], xi_q[l], eta_q[l]}), .q_o(qd5));
      tu_ewa_border #(.ClipVariant(ClipVariant)) u_border (
        .clk_i, .rst_ni, .in_valid_i(vc5[1] && vc5[0]), .in_ready_o(bready_unused),
        .q_i(qd5[QdW-1 -: tu_formats_pkg::EwaQW]), .xi_i(qd5[2*XiW-1:XiW]), .eta_i(qd5[XiW-1:0]),
        .kxu_i(k5[4*KW-1 -: KW]), .kxv_i(k5[3*KW-1 -: KW]), .kyu_i(k5[2*KW-1 -: KW]), .kyv_i(k5[KW-1:0]),
        .w_i(w5[l]), .out_valid_o(bvalid), .out_ready_i(1'b1), .zone_o(bzone_unused), .d_o(bd_unused), .w_o(bw));
      assign wacc[l] = !clipa ? w5d[l*WW +: WW] : bvalid ? bw : '0;
      logic unused_b;
      assign unused_b = ^{bd_unused, bzone_unused, bready_unused, q_q[l][63]};
    end
  end else begin : g_no_border
    for (genvar l = 0; l < L; l++) begin : g_lane_nb
      assign wacc[l] = w5[l];
      logic unused_b;
      assign unused_b = ^{q_q[l][63]};
    end
    logic unused_nb;
    assign unused_nb = ^{clipa, kxu_q, kxv_q, kyu_q, kyv_q};
  end

  // ---- A: the K-input sums
  logic [WW-1:0]  wl [L];
  logic [31:0]    dl [L];
  logic [BsW-1:0] bsum [4];
  logic [WsW-1:0] wsum_q, wsum_new;
  logic [AcW-1:0] acc_q [4], acc_new [4];
  logic [NW-1:0]  ins_q, ins_new;
  logic [31:0]    near_q, near_new;
  always_comb begin
    for (int l = 0; l < L; l++) begin
      wl[l] = va && acta[l] && !guarda ? wacc[l] : '0;
      dl[l] = tex_data_i[32*porta[l] +: 32];
    end
    for (int c = 0; c < 4; c++) begin
      bsum[c] = '0;
      for (int l = 0; l < L; l++) bsum[c] = bsum[c] + BsW'(wl[l]) * BsW'(dl[l][8*c +: 8]);
      acc_new[c] = (firsta ? '0 : acc_q[c]) + AcW'(bsum[c]);
    end
    wsum_new = firsta ? '0 : wsum_q;
    ins_new  = firsta ? '0 : ins_q;
    near_new = firsta ? '0 : near_q;
    for (int l = 0; l < L; l++) begin
      wsum_new = wsum_new + WsW'(wl[l]);
      ins_new  = ins_new + NW'(wl[l] != '0);
      if (neara[l] && acta[l]) near_new = dl[l];
    end
  end
  logic           n0v_q, n0g_q;
  logic [AcW-1:0] n0acc_q [4];
  logic [WsW-1:0] n0ws_q;
  logic [NW-1:0]  n0ins_q;
  logic [31:0]    n0near_q;
  always_ff @(posedge clk_i) begin
    if (va) begin
      for (int c = 0; c < 4; c++) acc_q[c] <= acc_new[c];
      wsum_q <= wsum_new;
      ins_q  <= ins_new;
      near_q <= near_new;
    end
    n0v_q <= va && lasta;
    n0g_q <= guarda;
    for (int c = 0; c < 4; c++) n0acc_q[c] <= acc_new[c];
    n0ws_q   <= wsum_new;
    n0ins_q  <= ins_new;
    n0near_q <= near_new;
  end

  // ---- N0..N5: normalisation, one pixel per clock
  logic [6:0]     p_d;
  logic [NrW-1:0] m_d;
  always_comb begin
    p_d = '0;
    for (int i = 0; i < WsW; i++) if (n0ws_q[i]) p_d = 7'(i);
    m_d = (p_d >= 7'(NrW - 1)) ? NrW'(n0ws_q >> (p_d - 7'(NrW - 1))) : NrW'(n0ws_q << (7'(NrW - 1) - p_d));
  end
  localparam int NdW = 1 + NW + 32 + 1 + 1;  // v ins near guard nowt
  localparam int NaW = 4 * AcW;               // acc: into tu_ewa_norm_tail at N3 (p at N2)
  logic [MW-1:0]  mant_q;
  logic [NdW-1:0] n1_q, n5;
  logic [NaW-1:0] na1_q, na3;
  logic [6:0]     np1_q, np2_q;
  always_ff @(posedge clk_i) begin
    mant_q <= MW'(m_d) << (MW - NrW);  // recip::eval: the msb of a positive code at bit MW-1
    n1_q   <= {n0v_q, n0ins_q, n0near_q, n0g_q, n0ws_q == '0};
    na1_q  <= {n0acc_q[3], n0acc_q[2], n0acc_q[1], n0acc_q[0]};
    np1_q  <= p_d;
    np2_q  <= np1_q;
  end
  // N1..N3 the reciprocal core up to its unrounded y (N4); N3 the sums pre-shifted, N4 the
  // products as carry-save pairs, N5 their carry chain, shift and saturation (tu_ewa_norm_tail)
  logic signed [tu_formats_pkg::RecipC0W+1:0] y4;
  tu_recip_core_y u_core (.clk_i, .en_i(1'b1), .m_i(mant_q), .y_o(y4));
  tu_brdf_delay #(.W(NdW), .Depth(4)) u_nd (.clk_i, .en_i(1'b1), .d_i(n1_q), .q_o(n5));
  tu_brdf_delay #(.W(NaW), .Depth(2)) u_na (.clk_i, .en_i(1'b1), .d_i(na1_q), .q_o(na3));
  logic           v5n, g5n, nowt5;
  logic [NW-1:0]  ins5;
  logic [31:0]    near5, rgba_d;
  assign {v5n, ins5, near5, g5n, nowt5} = n5;
  tu_ewa_norm_tail u_tail (.clk_i, .p_i(np2_q), .acc_i(na3), .y_i(y4), .rgba_o(rgba_d));

  // ---- output: results in order (OutDepth credits: neither FIFO overflows)
  localparam int OfW = 32 + NW + 1;
  localparam int MfW = 4 + 5 + NW;
  logic [OfW-1:0] of_data;
  logic [MfW-1:0] mf_data;
  logic           of_valid, mf_valid, of_ready_unused, mf_ready_unused;
  tu_fifo #(.Width(OfW), .Depth(OutDepth)) u_of (
    .clk_i, .rst_ni, .in_valid_i(v5n), .in_ready_o(of_ready_unused),
    .in_data_i({g5n || nowt5 ? near5 : rgba_d, ins5, nowt5 && !g5n}),
    .out_valid_o(of_valid), .out_ready_i(pop), .out_data_o(of_data));
  tu_fifo #(.Width(MfW), .Depth(OutDepth)) u_mf (
    .clk_i, .rst_ni, .in_valid_i(load), .in_ready_o(mf_ready_unused), .in_data_i({level_i, flags_i, box_i}),
    .out_valid_o(mf_valid), .out_ready_i(pop), .out_data_o(mf_data));
  assign out_valid_o = of_valid;
  assign pop         = of_valid && out_ready_i;
  assign rgba_o      = of_data[OfW-1 -: 32];
  assign inside_o    = of_data[NW:1];
  assign level_o     = mf_data[MfW-1 -: 4];
  assign visited_o   = mf_data[NW-1:0];
  assign flags_o     = mf_data[NW +: 5] | (5'(of_data[0]) << tu_formats_pkg::EwaFlagNoWeight);

  logic unused;
  assign unused = ^{hs_unused[0], hs_unused[1], hs_unused[2], hs_unused[3], of_ready_unused, mf_ready_unused,
                    mf_valid};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o})
endmodule
