// EWA texel walk, accumulation and normalisation (B5 steps 4-5 of ewa::fx::walk), bit-exact with
// cmodel/blocks/ewa/ewa_fx.cpp (docs/blocks/ewa.md "RTL"). One texel per clock:
//   P0 issue   (x, y) row-major over the box; Q, xi, eta by first/second differences along x and,
//              at each row start, along y (exact integers: the same values as the C model's direct
//              row starts)
//   P1         inside = Q < 1; Q code (u16.14, floor), xi, eta codes (s16.14, floor); texel address
//   P1..P5     weight: formula (tu_gauss_weight, 3 + 1 pad) | 1-D table (3 + 1) | 2-D table (4),
//              selected at run time by wsrc; texel read issued at P4 (1-cycle RAM)
//   P5         w = inside ? weight : 0; acc_c += w texel_c, wsum += w, inside count += (w > 0)
// then normalisation (tu_ewa_normalise): wsum leading-one normalised to EwaNrmW bits, the
// reciprocal core, channel = min(255, round_half_up(acc_c R 2^-(RecipOutF + p))) with the products
// registered as carry-save pairs (tu_ewa_norm_tail); wsum = 0 -> the nearest texel
// at level L (flag kNoWeight).
// Border weights (HasClip, a pixel with clip_i; docs/blocks/ewa.md "Border weights"): at P5 the
// texel's Q, xi, eta (delayed from P0), the frame k = d(xi, eta) / 2^PosF and the weight enter
// tu_ewa_border (ClipVariant); its weight replaces P5's, the texel read is issued BorderLat
// clocks later to meet it, and the drain grows by BorderLat.
// Cycles per pixel from the record hand-over (no back-pressure): 1 + box + 5 (+ BorderLat) + 6,
// output valid in the last (wsum = 0: 1 + box + 5 (+ BorderLat) + 1 + 2; B1-guard record: 1 + 2,
// the single texel).
`include "tu_assert.svh"
module tu_ewa_walk #(
  parameter int HasClip     = 0,  // tu_ewa_border in (a pixel's clip_i then selects it)
  parameter int ClipVariant = 0   // its clip volume: 0 mm_p1, 1 mm_p3 Horner, 2 mm_p3 Estrin
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
  input  logic [2*tu_formats_pkg::WrapW-1:0]       wrap_i,  // {v, u} Wrap* codes (tu_texel_addr)
  input  logic [1:0]                               wsrc_i,
  input  logic                                     clip_i,   // border weights for this pixel
  output logic                                     tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]      tex_addr_o,
  input  logic [31:0]                              tex_data_i,
  output logic                                     out_valid_o,
  input  logic                                     out_ready_i,
  output logic [31:0]                              rgba_o,
  output logic [3:0]                               level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     inside_o,
  output logic [4:0]                               flags_o
);
  localparam int XiW  = tu_formats_pkg::EwaXiW;
  localparam int PosF = tu_formats_pkg::EwaPosF;
  localparam int QF   = 2 * (tu_formats_pkg::EwaKF + PosF);
  localparam int GQW  = tu_formats_pkg::GaussQW;
  localparam int GXW  = tu_formats_pkg::GaussXiW;
  localparam int WW   = tu_formats_pkg::GaussSqW;     // weight codes (u17.16)
  localparam int WsW  = tu_formats_pkg::EwaWsumW;
  localparam int AcW  = tu_formats_pkg::EwaAccW;
  localparam int NW   = tu_formats_pkg::EwaCountW;
  localparam int AW   = tu_formats_pkg::TexAddrW;
  localparam int KW   = tu_formats_pkg::EwaKW;
  localparam int ClipLat = ClipVariant == 1 ? tu_formats_pkg::ClipHornerLatency
                         : ClipVariant == 2 ? tu_formats_pkg::ClipEstrinLatency
                                            : tu_formats_pkg::ClipP1Latency;
  // tu_ewa_border's latency (its header): S1, S2, the roots, S27, the division, S40, clip, last
  localparam int BorderLat = 1 + 1 + tu_formats_pkg::EwaRootW + 1 + tu_formats_pkg::ClipInF + 1 + ClipLat + 1;
  localparam int Drain = tu_formats_pkg::EwaDrainCycles;
  localparam int NormCycles = tu_formats_pkg::EwaNormCycles;
  localparam int AddrDly = HasClip != 0 ? 4 + BorderLat : 4;  // texel address delay line

  typedef enum logic [2:0] {WIdle, WWalk, WDrain, WNear, WNear2, WNorm, WOut} state_e;
  state_e st_q;
  logic [5:0] cnt_q;
  logic       clip_q;  // this pixel's border weights (HasClip only)
  logic [5:0] drain_last;
  assign drain_last = 6'(Drain - 1) + (clip_q ? 6'(BorderLat) : 6'd0);

  // ---- record
  logic [3:0]          lev_q;
  logic [4:0]          fl_q;
  logic                guard_q;
  logic signed [31:0]  x0_q, x1_q, y1_q;
  logic signed [31:0]  nx_q, ny_q;  // the nearest texel (cu + 32) >> PosF, (cv + 32) >> PosF
  logic [NW-1:0]       box_q;
  logic signed [XiW-1:0] dxi_q, deta_q, dxiy_q, detay_q;
  logic signed [63:0]  ddq_q, ddqy_q, dqy_q;
  logic [2*tu_formats_pkg::WrapW-1:0] wrap_q;
  // the texel address's level part (tu_texel_level), registered with the record
  logic [3:0]          wl_d, hl_d, wl_q, hl_q;
  logic [14:0]         wm_d, hm_d, wm_q, hm_q;
  logic [AW-1:0]       lb_d, bd_d, lb_q, bd_q;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i, .wl_o(wl_d), .hl_o(hl_d), .wmask_o(wm_d), .hmask_o(hm_d),
    .lbase_o(lb_d), .border_o(bd_d));
  logic [1:0]          wsrc_q;
  logic signed [KW-1:0] kxu_q, kxv_q, kyu_q, kyv_q;  // the frame (border distance)
  // ---- walk state: current texel and row start
  logic signed [31:0]    x_q, y_q;
  logic signed [63:0]    q_q, dq_q, qr_q, dqr_q, er_q;
  logic signed [XiW-1:0] xi_q, eta_q, xir_q, etar_q;

  assign rec_ready_o = st_q == WIdle;
  logic issue, row_end, last;
  assign issue   = st_q == WWalk;
  assign row_end = x_q == x1_q;
  assign last    = row_end && y_q == y1_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= WIdle;
    else begin
      unique case (st_q)
        WIdle:  if (rec_valid_i) st_q <= guard_i ? WNear : WWalk;
        WWalk:  if (last) st_q <= WDrain;
        WDrain: if (cnt_q == drain_last) st_q <= WNorm;
        WNear:  st_q <= WNear2;
        WNear2: st_q <= WOut;
        // the last accumulation lands at the end of the drain: wsum is final in WNorm's first clock
        WNorm:  if (cnt_q == '0 && wsum_q == '0) st_q <= WNear;
                else if (cnt_q == 6'(NormCycles - 1)) st_q <= WOut;
        WOut:   if (out_ready_i) st_q <= WIdle;
        default: st_q <= WIdle;
      endcase
    end
  end
  // near_q = (st_q == WNear), registered on its own: it selects the nearest texel's address for
  // tex_addr_o (the nearest texel's coordinates are loaded into x_q, y_q, so that the texel
  // address has no coordinate select)
  logic near_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) near_q <= 1'b0;
    else near_q <= (st_q == WIdle && rec_valid_i && guard_i) ||
                   (st_q == WNorm && cnt_q == '0 && wsum_q == '0);
  end
  always_ff @(posedge clk_i) begin
    if (st_q != WDrain && st_q != WNorm) cnt_q <= '0;
    else if (st_q == WDrain && cnt_q == drain_last) cnt_q <= '0;
    else cnt_q <= cnt_q + 6'd1;
  end

  always_ff @(posedge clk_i) begin
    if (st_q == WIdle && rec_valid_i) begin
      lev_q <= level_i;   fl_q <= flags_i;      guard_q <= guard_i;
      x0_q <= x0_i;       x1_q <= x1_i;      y1_q <= y1_i;
      nx_q <= (cu_i + 32'sd32) >>> PosF;  ny_q <= (cv_i + 32'sd32) >>> PosF;  box_q <= box_i;
      dxi_q <= dxi_i;     deta_q <= deta_i;  dxiy_q <= dxiy_i;  detay_q <= detay_i;
      ddq_q <= ddq_i;     ddqy_q <= ddqy_i;  dqy_q <= dqy_i;
      wl_q <= wl_d;       hl_q <= hl_d;      wm_q <= wm_d;      hm_q <= hm_d;
      lb_q <= lb_d;       bd_q <= bd_d;      wrap_q <= wrap_i;
      wsrc_q <= wsrc_i;   clip_q <= HasClip != 0 && clip_i;
      kxu_q <= KW'(dxi_i >>> PosF);   kyu_q <= KW'(deta_i >>> PosF);
      kxv_q <= KW'(dxiy_i >>> PosF);  kyv_q <= KW'(detay_i >>> PosF);
      // a guard record reads only the nearest texel: x_q, y_q hold it from the start
      x_q <= guard_i ? (cu_i + 32'sd32) >>> PosF : x0_i;
      y_q <= guard_i ? (cv_i + 32'sd32) >>> PosF : y0_i;
      q_q <= q0_i;        dq_q <= dq0_i;     xi_q <= xi0_i;     eta_q <= eta0_i;
      qr_q <= q0_i;       dqr_q <= dq0_i;    er_q <= ey0_i;     xir_q <= xi0_i;    etar_q <= eta0_i;
    end else if (issue && !last) begin
      if (!row_end) begin  // Heckbert along x
        x_q   <= x_q + 32'sd1;
        q_q   <= q_q + dq_q;
        dq_q  <= dq_q + ddq_q;
        xi_q  <= xi_q + dxi_q;
        eta_q <= eta_q + deta_q;
      end else begin       // next row: second differences along y
        x_q    <= x0_q;
        y_q    <= y_q + 32'sd1;
        q_q    <= qr_q + er_q;
        qr_q   <= qr_q + er_q;
        er_q   <= er_q + ddqy_q;
        dq_q   <= dqr_q + dqy_q;
        dqr_q  <= dqr_q + dqy_q;
        xi_q   <= xir_q + dxiy_q;
        xir_q  <= xir_q + dxiy_q;
        eta_q  <= etar_q + detay_q;
        etar_q <= etar_q + detay_q;
      end
    end else if (st_q == WNorm && cnt_q == '0 && wsum_q == '0) begin  // -> WNear: the nearest texel
      x_q <= nx_q;
      y_q <= ny_q;
    end
  end

  // ---- P1: weight-unit inputs and the texel address
  logic                  v1_q, in1_q;
  logic [GQW-1:0]        qc1_q, qcf1_q;  // Q for the 1-D table; its copy for the formula unit
  logic [GXW-1:0]        xic1_q, etac1_q;
  logic [AW-1:0]         addr, addr_q [AddrDly];
  logic                  in_q [2:5];
  tu_texel_addr_xy #(.CoordW(32)) u_addr (
    .wl_i(wl_q), .hl_i(hl_q), .wmask_i(wm_q), .hmask_i(hm_q), .lbase_i(lb_q), .border_i(bd_q),
    .wrap_i(wrap_q), .x_i(x_q), .y_i(y_q),
    .addr_o(addr)
  );
  always_ff @(posedge clk_i) begin
    v1_q    <= issue;
    in1_q   <= issue && q_q < (64'sd1 <<< QF);
    xic1_q  <= GXW'(xi_q >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
    etac1_q <= GXW'(eta_q >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
    addr_q[0] <= addr;
    for (int i = 1; i < AddrDly; i++) addr_q[i] <= addr_q[i-1];
    in_q[2] <= in1_q;
    for (int i = 3; i <= 5; i++) in_q[i] <= in_q[i-1];
  end
  // Q for the 1-D table and the formula unit's own copy (its squarer alone on it): keep on both,
  // or Yosys merges the two identical registers back into one driving both units
  (* keep *) always_ff @(posedge clk_i) qc1_q  <= GQW'(q_q >>> (QF - tu_formats_pkg::GaussQF));
  (* keep *) always_ff @(posedge clk_i) qcf1_q <= GQW'(q_q >>> (QF - tu_formats_pkg::GaussQF));
  // the nearest-texel read (WNear) bypasses the delay line
  assign tex_req_o  = 1'b1;
  assign tex_addr_o = near_q ? addr : clip_q ? addr_q[AddrDly-1] : addr_q[3];

  // ---- weights (all three sources run; the shorter pipelines are padded to 4)
  logic [WW-1:0] w_f, w_f_q;
  logic [tu_formats_pkg::WtabEntryW-1:0] w_1, w_1_q, w_2;
  logic [5:0] hs_unused;
  tu_gauss_weight u_wf (
    .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[0]), .q_i(qcf1_q),
    .out_valid_o(hs_unused[1]), .out_ready_i(1'b1), .w_o(w_f));
  tu_weight_table_1d #(.Log2N(8)) u_w1 (
    .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[2]), .q_i(qc1_q),
    .out_valid_o(hs_unused[3]), .out_ready_i(1'b1), .w_o(w_1));
  tu_weight_table_2d #(.Log2N(5)) u_w2 (
    .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[4]), .xi_i(xic1_q), .eta_i(etac1_q),
    .out_valid_o(hs_unused[5]), .out_ready_i(1'b1), .w_o(w_2));
  always_ff @(posedge clk_i) begin
    w_f_q <= w_f;
    w_1_q <= w_1;
  end
  logic [WW-1:0] w5;
  always_comb begin
    unique case (wsrc_q)
      tu_formats_pkg::WsrcTable1d: w5 = WW'(w_1_q);
      tu_formats_pkg::WsrcTable2d: w5 = WW'(w_2);
      default: w5 = w_f_q;
    endcase
    if (!in_q[5]) w5 = '0;
  end

  // ---- border weights: P5 -> P5 + BorderLat (clip_q), else P5's weight. Only a clip pixel's
  // texels enter valid: a plain pixel's drain ends before its texels would leave the pipeline.
  logic [WW-1:0] wacc;
  if (HasClip != 0) begin : g_border
    localparam int QdW = tu_formats_pkg::EwaQW + 2 * XiW;
    logic [QdW-1:0] qd5;
    logic           v5, bvalid;
    logic [WW-1:0]  bw;
    logic [tu_formats_pkg::ClipInW-1:0] bd_unused;
    logic [1:0]     bzone_unused;
    logic           bready_unused;
    logic [3:0]     vd_q;
    always_ff @(posedge clk_i) vd_q <= {vd_q[2:0], v1_q};
    assign v5 = vd_q[3];
    tu_brdf_delay #(.W(QdW), .Depth(5)) u_qdly (
      .clk_i, .en_i(1'b1), .d_i({q_q[tu_formats_pkg::EwaQW-1:0], xi_q, eta_q}), .q_o(qd5));
    tu_ewa_border #(.ClipVariant(ClipVariant)) u_border (
      .clk_i, .rst_ni, .in_valid_i(v5 && clip_q), .in_ready_o(bready_unused),
      .q_i(qd5[QdW-1 -: tu_formats_pkg::EwaQW]), .xi_i(qd5[2*XiW-1:XiW]), .eta_i(qd5[XiW-1:0]),
      .kxu_i(kxu_q), .kxv_i(kxv_q), .kyu_i(kyu_q), .kyv_i(kyv_q), .w_i(w5),
      .out_valid_o(bvalid), .out_ready_i(1'b1), .zone_o(bzone_unused), .d_o(bd_unused), .w_o(bw));
    assign wacc = !clip_q ? w5 : bvalid ? bw : '0;
    logic unused_border;
    assign unused_border = ^{bd_unused, bzone_unused, bready_unused, q_q[63]};
  end else begin : g_no_border
    assign wacc = w5;
    logic unused_border;
    assign unused_border = ^{clip_i, kxu_q, kxv_q, kyu_q, kyv_q};
  end

  // ---- P5: accumulate
  logic [AcW-1:0] acc_q [4];
  logic [WsW-1:0] wsum_q;
  logic [NW-1:0]  ins_q;
  always_ff @(posedge clk_i) begin
    if (st_q == WIdle) begin
      for (int c = 0; c < 4; c++) acc_q[c] <= '0;
      wsum_q <= '0;
      ins_q  <= '0;
    end else if (st_q == WWalk || st_q == WDrain) begin
      for (int c = 0; c < 4; c++) acc_q[c] <= acc_q[c] + AcW'(wacc) * AcW'(tex_data_i[8*c +: 8]);
      wsum_q <= wsum_q + WsW'(wacc);
      ins_q  <= ins_q + NW'(wacc != '0);
    end
  end

  // ---- normalisation (tu_ewa_normalise: load at WNorm's first clock, the sums held; rgba_d in
  // its last, NormCycles - 1 clocks later)
  logic [31:0] rgba_d;
  tu_ewa_normalise #(.AccW(AcW), .WsumW(WsW)) u_norm (
    .clk_i, .load_i(st_q == WNorm && cnt_q == 6'd0), .wsum_i(wsum_q),
    .acc_i({acc_q[3], acc_q[2], acc_q[1], acc_q[0]}), .rgba_o(rgba_d));

  always_ff @(posedge clk_i) begin
    if (st_q == WNorm && cnt_q == 6'(NormCycles - 1)) rgba_o <= rgba_d;
    if (st_q == WNear2) rgba_o <= tex_data_i;
  end
  assign out_valid_o = st_q == WOut;
  assign level_o     = lev_q;
  assign visited_o   = box_q;
  assign inside_o    = ins_q;
  assign flags_o     = fl_q | (5'(wsum_q == '0 && !guard_q) << tu_formats_pkg::EwaFlagNoWeight);

  logic unused;
  assign unused = ^{hs_unused, x0_q[0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o})
endmodule
