// Visibility walker of the AF-with-parallax-visibility engine (tu_afvis; docs/blocks/afvis.md §5),
// bit-exact with afvis::walk (cmodel/blocks/afvis/afvis.cpp). It takes tu_ewa_setup's record and
// walks the box row by row:
//   scan   one texel per clock, Q / xi / eta by the same differences as tu_ewa_walk, the weight
//          units (formula, 1-D, 2-D table, selected by wsrc) 5 clocks deep; a texel with w > 0
//          enters the row buffer (its x - x0 and w; 2^AfvRowLog2 entries, a row holds fewer)
//   row    after the drain (5) and one clock: the row rule over the buffer (rule_i 0: every
//          texel, 1: the seed's rule, forward until the first occluded texel, then backward from
//          the row's last texel until the next occluded one)
//   trace  per traced texel the integer box-field DDA of afvis::trace, one depth read per clock:
//          T0 the texel centre (PomUvF codes, repeat) and its depth d0 read; T1 the first crossing
//          (n_u |Pv| <= n_v |Pu|: along u) and its cell read; then each clock the tests of the
//          last crossing on its cell's data (visible: d0 <= dmin + bias, P = 0, the ray within
//          bias of the map's top, or AfvStepMax cells entered; occluded: entered more than bias
//          below the cell's top) while the next crossing's cell is read. A trace takes steps + 2
//          clocks (visible) or steps + 1 (occluded); a visible texel's colour is read at its
//          decision and accumulated (w c, w) the next clock.
//   finish one clock, then tu_afvis_norm (EwaNormCycles) or, with no visible texel, the level's
//          texel nearest the centre (flag NoWeight) as tu_ewa_walk.
// Clocks from the hand-over to output valid: afvis::Out::clocks (the cycle model).
`include "tu_assert.svh"
module tu_afvis_walk (
  input  logic                                     clk_i,
  input  logic                                     rst_ni,
  input  logic                                     rec_valid_i,
  output logic                                     rec_ready_o,
  input  logic [3:0]                               level_i,
  input  logic [4:0]                               flags_i,
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
  input  logic [2*tu_formats_pkg::WrapW-1:0]       wrap_i,
  input  logic [1:0]                               wsrc_i,
  // the relief: P (pom::parallax, PomUvF codes), the depth map (also the trace's cells), its
  // smallest code, the bias (depth codes) and the rule
  input  logic signed [tu_formats_pkg::PomUvW-1:0] pu_i,
  input  logic signed [tu_formats_pkg::PomUvW-1:0] pv_i,
  input  logic [tu_formats_pkg::TexAddrW-1:0]      hbase_i,
  input  logic [3:0]                               hlw_i,
  input  logic [3:0]                               hlh_i,
  input  logic [7:0]                               dmin_i,
  input  logic [7:0]                               bias_i,
  input  logic                                     rule_i,
  output logic                                     tex_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]      tex_addr_o,
  input  logic [31:0]                              tex_data_i,
  output logic                                     d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]      d_addr_o,
  input  logic [7:0]                               d_data_i,
  output logic                                     out_valid_o,
  input  logic                                     out_ready_i,
  output logic [31:0]                              rgba_o,
  output logic [3:0]                               level_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     visited_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     inside_o,
  output logic [4:0]                               flags_o,
  output logic [tu_formats_pkg::EwaCountW-1:0]     kept_o,    // visible texels accumulated
  output logic [tu_formats_pkg::EwaCountW-1:0]     traced_o,
  output logic [23:0]                              steps_o    // depth reads of the traces
);
  localparam int XiW  = tu_formats_pkg::EwaXiW;
  localparam int PosF = tu_formats_pkg::EwaPosF;
  localparam int QF   = 2 * (tu_formats_pkg::EwaKF + PosF);
  localparam int GQW  = tu_formats_pkg::GaussQW;
  localparam int GXW  = tu_formats_pkg::GaussXiW;
  localparam int WW   = tu_formats_pkg::GaussSqW;
  localparam int WsW  = tu_formats_pkg::EwaWsumW;
  localparam int AcW  = tu_formats_pkg::EwaAccW;
  localparam int NW   = tu_formats_pkg::EwaCountW;
  localparam int AW   = tu_formats_pkg::TexAddrW;
  localparam int UvF  = tu_formats_pkg::PomUvF;
  localparam int PW   = tu_formats_pkg::AfvPW;
  localparam int DW   = tu_formats_pkg::AfvDistW;
  localparam int CrW  = tu_formats_pkg::AfvCrossW;
  localparam int SW   = tu_formats_pkg::AfvStepW;
  localparam int RL   = tu_formats_pkg::AfvRowLog2;
  localparam int TW   = 34;  // depth tests: 11-bit signed x u22 and 255 n (< 2^31), with headroom
  localparam int Drain = tu_formats_pkg::EwaDrainCycles;
  localparam int NormCycles = tu_formats_pkg::EwaNormCycles;
  localparam int BW = RL + WW;  // row-buffer entry: {x - x0, w}

  typedef enum logic [3:0] {AIdle, AScan, ADrain, ARow, ATrace, AFin, ANorm, ANear, ANear2, AOut} state_e;
  state_e st_q;
  logic [2:0] cnt_q;

  // ---- record (latched at the hand-over)
  logic [3:0]          lev_q;
  logic [4:0]          fl_q;
  logic signed [31:0]  x0_q, x1_q, y1_q;
  logic signed [31:0]  nx_q, ny_q;  // the nearest texel (cu + 32) >> PosF, (cv + 32) >> PosF
  logic [NW-1:0]       box_q;
  logic signed [XiW-1:0] dxi_q, deta_q, dxiy_q, detay_q;
  logic signed [63:0]  ddq_q, ddqy_q, dqy_q;
  logic [AW-1:0]       hbase_q;
  logic [3:0]          lw_q, lh_q, hlw_q, hlh_q;
  logic [2*tu_formats_pkg::WrapW-1:0] wrap_q;
  // the texel address's level part (tu_texel_level), registered with the record
  logic [3:0]          wl_d, hl_d, wl_q, hl_q;
  logic [14:0]         wm_d, hm_d, wm_q, hm_q;
  logic [AW-1:0]       lb_d, bd_d, lb_q, bd_q;
  tu_texel_level u_level (
    .base_i, .lw_i, .lh_i, .level_i, .wl_o(wl_d), .hl_o(hl_d), .wmask_o(wm_d), .hmask_o(hm_d),
    .lbase_o(lb_d), .border_o(bd_d));
  logic [1:0]          wsrc_q;
  logic [PW-1:0]       au_q, av_q;      // |Pu|, |Pv|
  logic                su_q, sv_q, pz_q;  // Pu > 0, Pv > 0, P = 0
  logic [7:0]          dmin_q, bias_q;
  logic                rule_q;
  // ---- scan state
  logic signed [31:0]    x_q, y_q, ty_q;
  logic signed [63:0]    q_q, dq_q, qr_q, dqr_q, er_q;
  logic signed [XiW-1:0] xi_q, eta_q, xir_q, etar_q;
  logic                  last_row_q;

  assign rec_ready_o = st_q == AIdle;
  logic issue, row_end;
  assign issue   = st_q == AScan;
  assign row_end = x_q == x1_q;

  logic [PW-1:0] pu_abs, pv_abs;
  assign pu_abs = PW'(pu_i[tu_formats_pkg::PomUvW-1] ? -pu_i : pu_i);
  assign pv_abs = PW'(pv_i[tu_formats_pkg::PomUvW-1] ? -pv_i : pv_i);

  always_ff @(posedge clk_i) begin
    if (st_q == AIdle && rec_valid_i) begin
      lev_q <= level_i;   fl_q <= flags_i;
      x0_q <= x0_i;       x1_q <= x1_i;      y1_q <= y1_i;
      nx_q <= (cu_i + 32'sd32) >>> PosF;  ny_q <= (cv_i + 32'sd32) >>> PosF;  box_q <= box_i;
      dxi_q <= dxi_i;     deta_q <= deta_i;  dxiy_q <= dxiy_i;  detay_q <= detay_i;
      ddq_q <= ddq_i;     ddqy_q <= ddqy_i;  dqy_q <= dqy_i;
      lw_q <= lw_i;       lh_q <= lh_i;      wrap_q <= wrap_i;
      wl_q <= wl_d;       hl_q <= hl_d;      wm_q <= wm_d;      hm_q <= hm_d;
      lb_q <= lb_d;       bd_q <= bd_d;
      wsrc_q <= wsrc_i;
      au_q <= pu_abs;     av_q <= pv_abs;
      su_q <= !pu_i[tu_formats_pkg::PomUvW-1] && pu_i != '0;
      sv_q <= !pv_i[tu_formats_pkg::PomUvW-1] && pv_i != '0;
      pz_q <= pu_i == '0 && pv_i == '0;
      hbase_q <= hbase_i; hlw_q <= hlw_i;    hlh_q <= hlh_i;
      dmin_q <= dmin_i;   bias_q <= bias_i;  rule_q <= rule_i;
      x_q <= x0_i;        y_q <= y0_i;
      q_q <= q0_i;        dq_q <= dq0_i;     xi_q <= xi0_i;     eta_q <= eta0_i;
      qr_q <= q0_i;       dqr_q <= dq0_i;    er_q <= ey0_i;     xir_q <= xi0_i;    etar_q <= eta0_i;
    end else if (issue) begin
      if (!row_end) begin  // Heckbert along x
        x_q   <= x_q + 32'sd1;
        q_q   <= q_q + dq_q;
        dq_q  <= dq_q + ddq_q;
        xi_q  <= xi_q + dxi_q;
        eta_q <= eta_q + deta_q;
      end else begin       // next row: second differences along y (the scan waits for the traces)
        x_q    <= x0_q;
        y_q    <= y_q + 32'sd1;
        ty_q   <= y_q;
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
    end
  end

  // ---- scan pipeline: P1 weight-unit inputs, weights at P5 (as tu_ewa_walk)
  logic           v1_q, in1_q;
  logic [GQW-1:0] qc1_q;
  logic [GXW-1:0] xic1_q, etac1_q;
  logic           in_q [2:5];
  logic [RL-1:0]  dx_q [1:5];
  always_ff @(posedge clk_i) begin
    v1_q    <= issue;
    in1_q   <= issue && q_q < (64'sd1 <<< QF);
    qc1_q   <= GQW'(q_q >>> (QF - tu_formats_pkg::GaussQF));
    xic1_q  <= GXW'(xi_q >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
    etac1_q <= GXW'(eta_q >>> (tu_formats_pkg::EwaKF + PosF - tu_formats_pkg::GaussXiF));
    dx_q[1] <= RL'(x_q - x0_q);
    for (int i = 2; i <= 5; i++) dx_q[i] <= dx_q[i-1];
    in_q[2] <= in1_q;
    for (int i = 3; i <= 5; i++) in_q[i] <= in_q[i-1];
  end
  logic [WW-1:0] w_f, w_f_q;
  logic [tu_formats_pkg::WtabEntryW-1:0] w_1, w_1_q, w_2;
  logic [5:0] hs_unused;
  tu_gauss_weight u_wf (
    .clk_i, .rst_ni, .in_valid_i(v1_q), .in_ready_o(hs_unused[0]), .q_i(qc1_q),
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

  // ---- row buffer: the row's texels with w > 0 in walk order (synchronous read)
  logic [BW-1:0] rowbuf_q [1 << RL];
  logic [RL:0]   nb_q;
  logic [RL-1:0] rd_addr;
  logic [BW-1:0] rd_q;
  logic          row_clear;  // the row's traces are done: the next row starts filling
  always_ff @(posedge clk_i) begin
    if (w5 != '0) rowbuf_q[nb_q[RL-1:0]] <= {dx_q[5], w5};
    rd_q <= rowbuf_q[rd_addr];
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) nb_q <= '0;
    else if (st_q == AIdle || row_clear) nb_q <= '0;
    else if (w5 != '0) nb_q <= nb_q + 1'b1;
  end

  // ---- trace: the texel's centre, the DDA and the tests
  localparam logic [1:0] T0 = 2'd0, T1 = 2'd1, TE = 2'd2;
  logic [1:0]    tph_q;
  logic [RL-1:0] k_q, a_q;   // texel being traced; the row rule's first occluded texel
  logic          fwd_q;
  logic signed [31:0] tx_q;  // its x at the level
  logic [WW-1:0] tw_q;       // its weight
  logic [15:0]   i_q, j_q;   // cell indices (mod 2^16; the address masks them to the map)
  logic [DW-1:0] nu_q, nv_q; // ray length to the next boundary along u, v
  logic [DW-1:0] n_q;        // the last crossing's distance and |P| component
  logic [PW-1:0] a_q2;
  logic [SW-1:0] e_q;        // cells entered before the last crossing
  logic [7:0]    d0_q;

  // centre code of texel x at level L in repeats, PomUvF bits, modulo one repeat
  function automatic logic [15:0] centre(input logic signed [31:0] x, input logic [3:0] lev,
                                         input logic [3:0] l);
    logic [5:0] by;
    by = 6'(lev) + 6'(UvF - 1) - 6'(l);
    centre = 16'(({x, 1'b1}) << by);
  endfunction
  logic [4:0]  cul, cvl;         // cell sides in uv codes: 2^(PomUvF - log2 side)
  logic [16:0] cw, ch;
  logic [15:0] mw, mh;           // map index masks
  logic [15:0] cwm, chm;         // offset masks inside a cell
  assign cul = 5'(UvF) - 5'(hlw_q);
  assign cvl = 5'(UvF) - 5'(hlh_q);
  assign cw  = 17'd1 << cul;
  assign ch  = 17'd1 << cvl;
  assign cwm = 16'(cw - 17'd1);
  assign chm = 16'(ch - 17'd1);
  assign mw  = 16'((17'd1 << hlw_q) - 17'd1);
  assign mh  = 16'((17'd1 << hlh_q) - 17'd1);
  function automatic logic [AW-1:0] cell_addr(input logic [AW-1:0] b, input logic [3:0] l,
                                              input logic [15:0] i, input logic [15:0] j,
                                              input logic [15:0] mi, input logic [15:0] mj);
    logic [15:0] ii, jj;
    ii = i & mi;
    jj = j & mj;
    cell_addr = b + (AW'(jj) << l) + AW'(ii);
  endfunction

  // T0: the texel from the buffer
  logic signed [31:0] t0_x;
  logic [15:0] t0_cu, t0_cv, t0_i, t0_j;
  logic [15:0] t0_ou, t0_ov;
  logic [DW-1:0] t0_nu, t0_nv;
  assign t0_x  = x0_q + 32'(rd_q[BW-1 -: RL]);
  assign t0_cu = centre(t0_x, lev_q, lw_q);
  assign t0_cv = centre(ty_q, lev_q, lh_q);
  assign t0_i  = t0_cu >> cul;
  assign t0_j  = t0_cv >> cvl;
  assign t0_ou = t0_cu & cwm;
  assign t0_ov = t0_cv & chm;
  assign t0_nu = su_q ? DW'(cw) - DW'(t0_ou) : DW'(t0_ou);
  assign t0_nv = sv_q ? DW'(ch) - DW'(t0_ov) : DW'(t0_ov);

  // the next crossing from (i, j, nu, nv): along u iff n_u |Pv| <= n_v |Pu| (an axis with P = 0
  // never crosses)
  logic [CrW-1:0] cr_u, cr_v;
  logic           along_u;
  logic [15:0]    x_i, x_j;
  logic [DW-1:0]  x_nu, x_nv;
  assign cr_u    = CrW'(nu_q) * CrW'(av_q);
  assign cr_v    = CrW'(nv_q) * CrW'(au_q);
  assign along_u = av_q == '0 || (au_q != '0 && cr_u <= cr_v);
  assign x_i  = along_u ? (su_q ? i_q + 16'd1 : i_q - 16'd1) : i_q;
  assign x_j  = along_u ? j_q : (sv_q ? j_q + 16'd1 : j_q - 16'd1);
  assign x_nu = along_u ? nu_q + DW'(cw) : nu_q;
  assign x_nv = along_u ? nv_q : nv_q + DW'(ch);

  // TE: the tests of the last crossing on its cell's data
  logic signed [10:0] reach, toph;
  logic signed [TW-1:0] n255, t_reach, t_occl;
  logic early, vis_reach, capped, occl, decide, visible;
  always_comb begin
    reach     = 11'(d0_q) - 11'(dmin_q) - 11'(bias_q);
    toph      = 11'(d0_q) - 11'(bias_q) - 11'(d_data_i);
    n255      = TW'({n_q, 8'd0}) - TW'(n_q);
    t_reach   = TW'(reach) * $signed(TW'(a_q2));
    t_occl    = TW'(toph) * $signed(TW'(a_q2));
    early     = reach <= 11'sd0 || pz_q;
    vis_reach = t_reach <= n255;
    capped    = e_q == SW'(tu_formats_pkg::AfvStepMax);
    occl      = t_occl > n255;
    visible   = early || vis_reach || capped;
    decide    = tph_q == TE && (visible || occl);
  end
  logic [SW:0] t_steps;  // this trace's depth reads
  assign t_steps = early ? (SW+1)'(1) : visible ? (SW+1)'(e_q) + (SW+1)'(1) : (SW+1)'(e_q) + (SW+1)'(2);

  // the row rule: after a decision, the next texel or the row's end
  logic          row_done;
  logic [RL-1:0] nk;
  logic [RL-1:0] last_k;
  assign last_k = RL'(nb_q - 1'b1);
  always_comb begin
    row_done = 1'b0;
    nk = k_q + 1'b1;
    if (st_q == ARow) nk = '0;
    else if (!rule_q || fwd_q) begin
      if (k_q == last_k) row_done = 1'b1;
      else if (rule_q && !visible) nk = last_k;  // the first occluded texel: backward from the end
    end else begin
      nk = k_q - 1'b1;
      if (!visible || nk == a_q) row_done = 1'b1;
    end
  end
  assign rd_addr = nk;
  assign row_clear = (st_q == ARow && nb_q == '0) || (decide && row_done);

  always_ff @(posedge clk_i) begin
    if (st_q == ARow) begin
      k_q <= '0;
      fwd_q <= 1'b1;
      tph_q <= T0;
    end else if (st_q == ATrace) begin
      unique case (tph_q)
        T0: begin
          tx_q <= t0_x;
          tw_q <= rd_q[WW-1:0];
          i_q  <= t0_i;
          j_q  <= t0_j;
          nu_q <= t0_nu;
          nv_q <= t0_nv;
          tph_q <= T1;
        end
        default: begin
          if (tph_q == T1) d0_q <= d_data_i;
          if (tph_q == T1 || !decide) begin  // cross into the next cell (read it)
            i_q  <= x_i;
            j_q  <= x_j;
            nu_q <= x_nu;
            nv_q <= x_nv;
            n_q  <= along_u ? nu_q : nv_q;
            a_q2 <= along_u ? au_q : av_q;
            e_q  <= tph_q == T1 ? '0 : e_q + 1'b1;
            tph_q <= TE;
          end else begin                    // decided: the next texel
            k_q  <= nk;
            tph_q <= T0;
            if (rule_q && fwd_q && !visible) begin
              a_q <= k_q;
              fwd_q <= 1'b0;
            end
          end
        end
      endcase
    end
  end
  // depth reads: the centre at T0, a cell at T1 and at every undecided test clock
  assign d_req_o  = st_q == ATrace && (tph_q == T0 || tph_q == T1 || !decide);
  assign d_addr_o = tph_q == T0 ? cell_addr(hbase_q, hlw_q, t0_i, t0_j, mw, mh)
                                : cell_addr(hbase_q, hlw_q, x_i, x_j, mw, mh);

  // ---- FSM
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) st_q <= AIdle;
    else begin
      unique case (st_q)
        AIdle:  if (rec_valid_i) st_q <= AScan;
        AScan:  if (row_end) st_q <= ADrain;
        ADrain: if (cnt_q == 3'(Drain - 1)) st_q <= ARow;
        ARow:   if (nb_q == '0) st_q <= last_row_q ? AFin : AScan;
                else st_q <= ATrace;
        ATrace: if (decide && row_done) st_q <= last_row_q ? AFin : AScan;
        AFin:   st_q <= ANorm;
        ANorm:  if (cnt_q == '0 && wsum_q == '0) st_q <= ANear;
                else if (cnt_q == 3'(NormCycles - 1)) st_q <= AOut;
        ANear:  st_q <= ANear2;
        ANear2: st_q <= AOut;
        AOut:   if (out_ready_i) st_q <= AIdle;
        default: st_q <= AIdle;
      endcase
    end
  end
  always_ff @(posedge clk_i) begin
    if (st_q != ADrain && st_q != ANorm) cnt_q <= '0;
    else if (st_q == ADrain && cnt_q == 3'(Drain - 1)) cnt_q <= '0;
    else cnt_q <= cnt_q + 3'd1;
    if (st_q == AIdle) last_row_q <= 1'b0;
    else if (issue && row_end && y_q == y1_q) last_row_q <= 1'b1;
  end

  // ---- texel reads: a visible texel at its decision, the nearest texel in ANear
  // (the level part, tu_texel_level, registered with the record: wl_q ... bd_q)
  logic [AW-1:0] addr;
  tu_texel_addr_xy #(.CoordW(32)) u_addr (
    .wl_i(wl_q), .hl_i(hl_q), .wmask_i(wm_q), .hmask_i(hm_q), .lbase_i(lb_q), .border_i(bd_q),
    .wrap_i(wrap_q), .x_i(st_q == ANear ? nx_q : tx_q), .y_i(st_q == ANear ? ny_q : ty_q),
    .addr_o(addr)
  );
  assign tex_req_o  = 1'b1;
  assign tex_addr_o = addr;

  // ---- accumulate (the clock after the decision), counters
  logic           acc_v_q;
  logic [WW-1:0]  acc_w_q;
  logic [AcW-1:0] acc_q [4];
  logic [WsW-1:0] wsum_q;
  logic [NW-1:0]  ins_q, kept_q, traced_q;
  logic [23:0]    steps_q;
  always_ff @(posedge clk_i) begin
    acc_v_q <= decide && visible;
    acc_w_q <= tw_q;
    if (st_q == AIdle) begin
      for (int c = 0; c < 4; c++) acc_q[c] <= '0;
      wsum_q <= '0;
      ins_q <= '0;
      kept_q <= '0;
      traced_q <= '0;
      steps_q <= '0;
    end else begin
      if (acc_v_q) begin
        for (int c = 0; c < 4; c++) acc_q[c] <= acc_q[c] + AcW'(acc_w_q) * AcW'(tex_data_i[8*c +: 8]);
        wsum_q <= wsum_q + WsW'(acc_w_q);
      end
      if (w5 != '0) ins_q <= ins_q + 1'b1;
      if (decide) begin
        traced_q <= traced_q + 1'b1;
        kept_q   <= kept_q + NW'(visible);
        steps_q  <= steps_q + 24'(t_steps);
      end
    end
  end

  // ---- normalisation and output
  logic [31:0] rgba_d;
  tu_afvis_norm u_norm (
    .clk_i, .load_i(st_q == ANorm && cnt_q == 3'd0), .wsum_i(wsum_q),
    .acc_i({acc_q[3], acc_q[2], acc_q[1], acc_q[0]}), .rgba_o(rgba_d));
  always_ff @(posedge clk_i) begin
    if (st_q == ANorm && cnt_q == 3'(NormCycles - 1)) rgba_o <= rgba_d;
    if (st_q == ANear2) rgba_o <= tex_data_i;
  end
  assign out_valid_o = st_q == AOut;
  assign level_o     = lev_q;
  assign visited_o   = box_q;
  assign inside_o    = ins_q;
  assign flags_o     = fl_q | (5'(wsum_q == '0) << tu_formats_pkg::EwaFlagNoWeight);
  assign kept_o      = kept_q;
  assign traced_o    = traced_q;
  assign steps_o     = steps_q;

  logic unused;
  assign unused = ^{hs_unused, x0_q[0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {rgba_o, level_o, visited_o, inside_o, flags_o, kept_o, traced_o, steps_o})
endmodule
