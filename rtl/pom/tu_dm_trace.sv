// Distance-map tracer (docs/blocks/relief.md §13.5, §13.8; C model dm::trace with the finish,
// relief::shift_uv_fx): sphere tracing through the 3-D distance map, then the linear + binary
// finish against the depth map, one map or depth read per clock through the depth port.
//   set-up  (DmSetupCycles clocks) L2 = (|Pu|^2 + |Pv|^2 + S^2) << 2 lw (exact, DmL2W bits);
//           lambda = ceil(sqrt(L2)) (digit-by-digit, DmSetupBits root bits per clock);
//           K = floor(2^44 / lambda) (restoring division, DmSetupBits quotient bits per clock);
//           meanwhile dl = floor(2^DmDF / layers) (the finish's layer step).
//   trace   D = 0; read map[tx, ty, min(floor(D layers), layers - 1)] at x = T - round(D P);
//           code 0, or cap_i steps, or D >= 1 (clamped, the `bottom` clock reads nothing): stop;
//           else D += floor(code K / 2^DmKF).
//   finish  depth(x) read at D: at or below (255 D >= depth 2^DmDF) -> done; else up to DmFinish
//           linear steps of dl, then DmBisect bisection steps between the last point above and
//           the first at or below; the result is the point at or below (or the last linear one).
// Map layout (dbase_i): voxel (x, y, k) of a 2^lw-sided map at dbase + (k << 2 lw) + (y << lw) + x;
// the depth map (hbase_i) at hbase + (y << lw) + x (square). The read data arrives the next clock
// (synchronous RAM); each clock of the trace and the finish evaluates the previous read and issues
// the next, so a pixel takes DmSetupCycles + 2 + steps_o clocks in Run: accept (Idle), Run, output
// (Done), like tu_iter_parallax (in_ready_o only in Idle). steps_o = map steps + finish reads
// (< 2^PomNW for cap_i <= DmCapMax); u_o, v_o = fract(x) at the result.
`include "tu_assert.svh"
module tu_dm_trace #(
  parameter int SideW = 1
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PomUvW-1:0]    u_i,       // T, PomUvF bits, inside one repeat
  input  logic [tu_formats_pkg::PomUvW-1:0]    v_i,
  input  logic [tu_formats_pkg::PomUvW-1:0]    pu_i,      // P = pom::parallax (tu_pom_setup)
  input  logic [tu_formats_pkg::PomUvW-1:0]    pv_i,
  input  logic [tu_formats_pkg::PomSW-1:0]     s_i,
  input  logic [tu_formats_pkg::PomNW-1:0]     cap_i,
  input  logic [tu_formats_pkg::DmLayersW-1:0] layers_i,  // map layers 1..255
  input  logic [tu_formats_pkg::TexAddrW-1:0]  hbase_i,   // depth map
  input  logic [tu_formats_pkg::TexAddrW-1:0]  dbase_i,   // distance map
  input  logic [3:0]                           lw_i,      // log2 side of both (square)
  input  logic [SideW-1:0]                     side_i,
  output logic                                 d_req_o,
  output logic [tu_formats_pkg::TexAddrW-1:0]  d_addr_o,
  input  logic [7:0]                           d_data_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [15:0]                          u_o,
  output logic [15:0]                          v_o,
  output logic [tu_formats_pkg::PomNW-1:0]     steps_o,
  output logic [SideW-1:0]                     side_o
);
  localparam int UvW = tu_formats_pkg::PomUvW;
  localparam int UF  = tu_formats_pkg::PomUvF;
  localparam int DF  = tu_formats_pkg::DmDF;
  localparam int DW  = tu_formats_pkg::DmDW;
  localparam int KW  = tu_formats_pkg::DmKW;
  localparam int KF  = tu_formats_pkg::DmKF;
  localparam int NW  = tu_formats_pkg::PomNW;
  localparam int LyW = tu_formats_pkg::DmLayersW;
  localparam int AW  = tu_formats_pkg::TexAddrW;
  localparam int L2W = tu_formats_pkg::DmL2W;
  localparam int B   = tu_formats_pkg::DmSetupBits;
  localparam int It  = 32 / B;  // clocks of the square root and of each division
  localparam logic [DW-1:0] DOne = DW'(1) << DF;
  // K's numerator 2^44 = 2^(DF + UF - DmQF + KF): its bits above the 32 quotient bits
  localparam logic [35:0] KRem0 = 36'(1) << (DF + UF - tu_formats_pkg::DmQF + KF - 32);

  typedef enum logic [1:0] {Idle, Run, Done} state_e;
  typedef enum logic [2:0] {PhL2, PhSq, PhDiv, PhTr0, PhTr, PhF0, PhLin, PhBis} phase_e;
  state_e state_q;
  phase_e ph_q;

  logic signed [UvW-1:0] tu_q, tv_q, pu_q, pv_q;
  logic [tu_formats_pkg::PomSW-1:0] s_q;
  logic [NW-1:0]  cap_q, steps_q, fst_q;
  logic [LyW-1:0] lay_q;
  logic [AW-1:0]  hbase_q, dbase_q;
  logic [3:0]     lw_q, cnt_q;
  logic [SideW-1:0] side_q;
  // set-up: square root (radicand shift register, remainder, root), the two divisions
  logic [L2W-1:0] x_q;
  logic [35:0]    rem_q, krem_q;
  logic [31:0]    root_q, k_q, dlq_q, num_q;
  logic [32:0]    lam_q;
  logic [9:0]     dlr_q;
  // trace and finish: D of the pending read, the bisection's interval, counters
  logic [DW-1:0]  rdd_q, lo_q, hi_q;
  logic           bottom_q;

  logic fire_in;
  assign in_ready_o  = (state_q == Idle);
  assign out_valid_o = (state_q == Done);
  assign fire_in     = in_valid_i && in_ready_o;

  // ---- set-up arithmetic ---------------------------------------------------------------------
  logic [UvW-1:0] apu, apv;
  logic [L2W-1:0] l2;
  logic [35:0]    sq_rem, sq_trial, kr, lam_x;
  logic [31:0]    sq_root, kq, dq, nq;
  logic [L2W-1:0] sq_x;
  logic [9:0]     dr;
  logic [32:0]    lam;
  always_comb begin
    apu = pu_q[UvW-1] ? UvW'(-pu_q) : UvW'(pu_q);
    apv = pv_q[UvW-1] ? UvW'(-pv_q) : UvW'(pv_q);
    l2 = (L2W'(apu) * L2W'(apu) + L2W'(apv) * L2W'(apv) + L2W'(s_q) * L2W'(s_q)) << {lw_q, 1'b0};
    // B digits of the square root: rem = 4 rem + next two radicand bits, trial = 4 root + 1
    sq_rem = rem_q;
    sq_root = root_q;
    sq_x = x_q;
    for (int j = 0; j < B; j++) begin
      sq_rem = {sq_rem[33:0], sq_x[L2W-1 -: 2]};
      sq_x = sq_x << 2;
      sq_trial = {2'b00, sq_root, 2'b01};
      sq_root = sq_root << 1;
      if (sq_rem >= sq_trial) begin
        sq_rem = sq_rem - sq_trial;
        sq_root[0] = 1'b1;
      end
    end
    lam = {1'b0, sq_root} + 33'(sq_rem != 36'd0);  // ceil: the last clock's root and remainder
    // B quotient bits of 2^44 / lambda (the numerator's low 32 bits are 0)
    lam_x = 36'(lam_q);
    kr = krem_q;
    kq = k_q;
    for (int j = 0; j < B; j++) begin
      kr = {kr[34:0], 1'b0};
      kq = kq << 1;
      if (kr >= lam_x) begin
        kr = kr - lam_x;
        kq[0] = 1'b1;
      end
    end
    // B quotient bits of 2^DF / layers (numerator bits MSB first from num_q)
    dr = dlr_q;
    dq = dlq_q;
    nq = num_q;
    for (int j = 0; j < B; j++) begin
      dr = {dr[8:0], nq[31]};
      nq = nq << 1;
      dq = dq << 1;
      if (dr >= 10'(lay_q)) begin
        dr = dr - 10'(lay_q);
        dq[0] = 1'b1;
      end
    end
  end

  // ---- trace and finish: evaluate the last read, choose the next --------------------------------
  logic [DW-1:0]  dl, mid, res_d, rd_d, pos_d, nlin;
  logic [36:0]    ck;
  logic [29:0]    ntr;
  logic           below, stop_tr, rd, rd_map, fin;
  always_comb begin
    dl = DW'(dlq_q);  // floor(2^DF / layers) <= 2^DF
    ck = 37'(d_data_i) * 37'(k_q[KW-1:0]);
    ntr = 30'(rdd_q) + 30'(ck >> KF);
    below = (33'(rdd_q) * 33'd255) >= (33'(d_data_i) << DF);
    nlin = (26'(rdd_q) + 26'(dl) >= 26'(DOne)) ? DOne : rdd_q + dl;
    stop_tr = bottom_q || d_data_i == 8'd0 || steps_q == cap_q;
    mid = DW'((26'(lo_q) + 26'(rdd_q)) >> 1);
    rd = 1'b0;
    rd_map = 1'b0;
    rd_d = rdd_q;
    fin = 1'b0;
    res_d = rdd_q;
    if (state_q == Run) begin
      unique case (ph_q)
        PhTr0: begin rd = 1'b1; rd_map = 1'b1; rd_d = '0; end
        PhTr: begin
          if (stop_tr) rd = 1'b1;                            // depth at D
          else if (ntr < 30'(DOne)) begin rd = 1'b1; rd_map = 1'b1; rd_d = DW'(ntr); end
        end
        PhF0: begin
          if (below) fin = 1'b1;
          else begin rd = 1'b1; rd_d = nlin; end
        end
        PhLin: begin
          if (below) begin rd = 1'b1; rd_d = mid; end
          else if (rdd_q == DOne || cnt_q == 4'(tu_formats_pkg::DmFinish)) fin = 1'b1;
          else begin rd = 1'b1; rd_d = nlin; end
        end
        PhBis: begin
          // below: the new interval is [lo, mid], else [mid, hi]
          res_d = below ? rdd_q : hi_q;
          if (cnt_q == 4'(tu_formats_pkg::DmBisect)) fin = 1'b1;
          else begin
            rd = 1'b1;
            rd_d = below ? DW'((26'(lo_q) + 26'(rdd_q)) >> 1) : DW'((26'(rdd_q) + 26'(hi_q)) >> 1);
          end
        end
        default: ;
      endcase
    end
  end

  // ---- position x = T - round_half_up(D P / 2^DF), addresses --------------------------------------
  logic signed [63:0]    mu, mv;
  logic signed [UvW-1:0] xu, xv;
  logic [15:0]           tx, ty;
  logic [32:0]           lk_full;
  logic [LyW-1:0]        lk;
  always_comb begin
    pos_d = fin ? res_d : rd_d;
    mu = 64'(pos_d) * 64'(pu_q) + (64'sd1 <<< (DF - 1));
    mv = 64'(pos_d) * 64'(pv_q) + (64'sd1 <<< (DF - 1));
    xu = tu_q - UvW'(mu >>> DF);
    xv = tv_q - UvW'(mv >>> DF);
    tx = 16'(xu >> (5'(UF) - 5'(lw_q))) & ((16'd1 << lw_q) - 16'd1);
    ty = 16'(xv >> (5'(UF) - 5'(lw_q))) & ((16'd1 << lw_q) - 16'd1);
    lk_full = 33'(pos_d) * 33'(lay_q);
    lk = (lk_full[32:DF] >= 9'(lay_q)) ? lay_q - 1'b1 : LyW'(lk_full[32:DF]);
    d_addr_o = (rd_map ? dbase_q + (AW'(lk) << {lw_q, 1'b0}) : hbase_q) + (AW'(ty) << lw_q) + AW'(tx);
  end
  assign d_req_o = rd;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= Idle; ph_q <= PhL2;
      tu_q <= '0; tv_q <= '0; pu_q <= '0; pv_q <= '0; s_q <= '0;
      cap_q <= '0; steps_q <= '0; fst_q <= '0; lay_q <= '0; hbase_q <= '0; dbase_q <= '0;
      lw_q <= '0; cnt_q <= '0; side_q <= '0;
      x_q <= '0; rem_q <= '0; krem_q <= '0; root_q <= '0; k_q <= '0; dlq_q <= '0; num_q <= '0;
      lam_q <= '0; dlr_q <= '0; rdd_q <= '0; lo_q <= '0; hi_q <= '0; bottom_q <= 1'b0;
      u_o <= '0; v_o <= '0; steps_o <= '0; side_o <= '0;
    end else begin
      unique case (state_q)
        Idle: if (fire_in) begin
          tu_q <= u_i; tv_q <= v_i; pu_q <= pu_i; pv_q <= pv_i; s_q <= s_i;
          cap_q <= cap_i; lay_q <= layers_i; hbase_q <= hbase_i; dbase_q <= dbase_i; lw_q <= lw_i;
          side_q <= side_i;
          ph_q <= PhL2;
          state_q <= Run;
        end
        Run: begin
          rdd_q <= rd_d;
          unique case (ph_q)
            PhL2: begin
              x_q <= l2; rem_q <= '0; root_q <= '0;
              dlr_q <= '0; dlq_q <= '0; num_q <= 32'(DOne);
              cnt_q <= '0;
              ph_q <= PhSq;
            end
            PhSq: begin
              x_q <= sq_x; rem_q <= sq_rem; root_q <= sq_root;
              dlr_q <= dr; dlq_q <= dq; num_q <= nq;
              cnt_q <= cnt_q + 1'b1;
              if (cnt_q == 4'(It - 1)) begin
                lam_q <= lam; krem_q <= KRem0; k_q <= '0; cnt_q <= '0;
                ph_q <= PhDiv;
              end
            end
            PhDiv: begin
              krem_q <= kr; k_q <= kq;
              cnt_q <= cnt_q + 1'b1;
              if (cnt_q == 4'(It - 1)) ph_q <= PhTr0;
            end
            PhTr0: begin
              steps_q <= '0; fst_q <= '0; bottom_q <= 1'b0;
              ph_q <= PhTr;
            end
            PhTr: begin
              if (stop_tr) begin
                fst_q <= NW'(1);
                ph_q <= PhF0;
              end else begin
                steps_q <= steps_q + 1'b1;
                if (ntr >= 30'(DOne)) begin
                  rdd_q <= DOne;
                  bottom_q <= 1'b1;
                end
              end
            end
            PhF0: if (!below) begin
              lo_q <= rdd_q; cnt_q <= 4'd1; fst_q <= fst_q + 1'b1;
              ph_q <= PhLin;
            end
            PhLin: begin
              if (below) begin
                hi_q <= rdd_q; cnt_q <= 4'd1; fst_q <= fst_q + 1'b1;
                ph_q <= PhBis;
              end else if (!fin) begin
                lo_q <= rdd_q; cnt_q <= cnt_q + 1'b1; fst_q <= fst_q + 1'b1;
              end
            end
            PhBis: begin
              if (below) hi_q <= rdd_q;
              else lo_q <= rdd_q;
              if (!fin) begin
                cnt_q <= cnt_q + 1'b1; fst_q <= fst_q + 1'b1;
              end
            end
            default: ;
          endcase
          if (fin) begin
            u_o <= xu[15:0];
            v_o <= xv[15:0];
            steps_o <= steps_q + fst_q;
            side_o <= side_q;
            state_q <= Done;
          end
        end
        Done: if (out_ready_i) state_q <= Idle;
        default: state_q <= Idle;
      endcase
    end
  end

  logic unused;
  assign unused = ^{kr[35:34], krem_q, lam_x[35:33], dr[9], rem_q[35:34], sq_trial, k_q[31:KW],
                    apu[31:23], apv[31:23], ck[36:29], lk_full[23:0]};

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i, {u_o, v_o, steps_o, side_o})
endmodule
