// Noise unit of the texture unit (procedural materials, cmodel/blocks/noise/noise_proc.hpp
// proc_value_fx + proc_color_fx; docs/blocks/noise.md §5): the colour of a pixel from the fBm,
// smoke or water of Perlin noise at B1's (u, v) with footprint-limited octave weights from B2's lrho.
// Pipelined (one octave sum per clock, Octaves noise cores), NoiseUnitLatency stages under global stall:
//   1     x = wrap32(round(u freq) + sx), y likewise (s32.16); w_i = clamp(1 - lrho - lfreq - i, 0, 1)
//   2..7  tu_noise_core per octave i at 2^i (x, y, z)
//   8     acc = sum_i round(w_i n_i (+ (1 - w_i) E|n| for smoke's |n_i|)) 2^(NoiseOctaves-1-i), exact
//   9     fbm: acc C_K + 1/2; smoke: clamp((2 acc C_K - thr) gain); colour c0 + value (c1 - c0)
// Water (HasWater): a pixel issues WaterPasses sums on three clocks, at (x, y), (x + h, y) and
// (x, y + h), h = 2^-8 cells (it is accepted with the last); after stage 8 (NoiseWaterLatency in all):
//   W1    g = sat(-a (P1 - P0)), sat(-a (P2 - P0))        s31.19, saturated (guard)
//   W2    |n|^2 = gx^2 + gy^2 + 1 (exact, 62 bits), n.L (exact, signed 48 bits)
//   W3..  |n| = floor sqrt (tu_isqrt_pipe, 31 stages), value = floor((n.L + |n|/2) / |n|)
//         (tu_udiv_pipe, WaterQuoW stages), 0 when n.L <= 0, clamp to 1; colour as fbm, alpha 255
// Water and the other kinds take turns (one kind in flight at a time), so outputs stay in order.
// Serial = 1 (the octave-serial scheme, NoiseScheme): one noise core for the Octaves octaves of a
// sum, octave o issued on its own clock (the code shifted left by o) and accumulated at stage 8 as
// it leaves the core: Octaves clocks per sum (water: WaterPasses Octaves), the same bits.
// A B1-guard pixel has no footprint: every weight 0 (all 1 without the limit). Octaves i >= noct
// add nothing. Dims = 2 leaves the z axis out (materials without time: z = 0, the same bits).
`include "tu_records.svh"
module tu_noise_unit #(
  parameter int Dims    = 3,
  parameter int Octaves = tu_formats_pkg::NoiseOctaves,  // noise cores: the largest noct served
  parameter int SideW   = 1,
  parameter int HasWater = 1,  // the water back-end (0: a water material is not served)
  parameter int Serial   = 0   // 1: octave-serial (one core, Octaves clocks per sum)
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 in_valid_i,
  output logic                                 in_ready_o,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  u_i,
  input  logic [tu_formats_pkg::PerspUvW-1:0]  v_i,
  input  logic                                 guard_i,
  input  logic [tu_formats_pkg::EllLogW-1:0]   lrho_i,
  input  logic [tu_formats_pkg::ProcW-1:0]     proc_i,   // tu_proc_t
  input  logic [SideW-1:0]                     side_i,
  output logic                                 out_valid_o,
  input  logic                                 out_ready_i,
  output logic [31:0]                          rgba_o,   // {a, b, g, r}
  output logic [SideW-1:0]                     side_o
);
  localparam int UW   = tu_formats_pkg::PerspUvW;
  localparam int CW   = tu_formats_pkg::NoiseCoordW;
  localparam int LW   = tu_formats_pkg::NoiseLatW;
  localparam int TF   = tu_formats_pkg::NoiseTF;
  localparam int VW   = tu_formats_pkg::NoiseValW;
  localparam int K    = tu_formats_pkg::NoiseOctaves;
  localparam int AccW = tu_formats_pkg::NoiseAccW;
  localparam int LogF = tu_formats_pkg::EllLogF;
  localparam int LogW = tu_formats_pkg::EllLogW;
  localparam int WW   = tu_formats_pkg::NoiseWeightW;
  localparam int OW   = tu_formats_pkg::NoiseOutW;
  localparam int NormF = tu_formats_pkg::NoiseNormF;
  localparam int GainF = tu_formats_pkg::NoiseGainF;
  localparam int Lat  = tu_formats_pkg::NoiseUnitLatency;
  localparam int CL   = tu_formats_pkg::NoiseCoreLatency;
  localparam int Drop = tu_formats_pkg::TexUvF + tu_formats_pkg::NoiseFreqF - TF;  // noise_proc.cpp kCoordDrop
  localparam int AccF = TF + K - 1;
  localparam int One  = 1 << LogF;  // weight 1

  tu_proc_t pr;
  assign pr = proc_i;

  // ---- valid and pass tags under global stall (every stage advances when the output is free) ----
  localparam int FL = Lat - 1;                                        // stages 1..8: coords, cores, sum
  localparam int WL = tu_formats_pkg::NoiseWaterLatency - FL;         // water stages after the sum
  localparam int Passes = tu_formats_pkg::WaterPasses;
  localparam int Slots  = Serial != 0 ? Octaves : 1;  // issue clocks per sum
  localparam int OctW   = $clog2(K);
  logic en, out_fbm_q;
  logic [FL-1:0] fv_q, fw_q;   // front stage valid, and holding a water pass
  logic [1:0]    fp_q [FL];    // its pass
  logic [OctW-1:0] fo_q [FL];  // its octave (octave-serial)
  logic [WL-1:0] wv_q;         // water stage valid
  logic [1:0]    pass_q;       // pass of the water pixel at the input
  logic [OctW-1:0] slot_q;     // octave of the sum at the input (octave-serial)
  logic          in_water, fbm_busy, water_busy, blocked, issue, last_pass, last_slot, done;
  assign en          = !(out_fbm_q || wv_q[WL-1]) || out_ready_i;
  assign out_valid_o = out_fbm_q || wv_q[WL-1];
  assign in_water    = HasWater != 0 && pr.water;
  assign fbm_busy    = (|(fv_q & ~fw_q)) || out_fbm_q;
  assign water_busy  = (|(fv_q & fw_q)) || (|wv_q);
  assign blocked     = in_water ? fbm_busy : water_busy;
  assign issue       = in_valid_i && !blocked;
  assign last_pass   = !in_water || pass_q == 2'(Passes - 1);
  assign last_slot   = slot_q == OctW'(Slots - 1);
  assign in_ready_o  = en && !blocked && last_pass && last_slot;
  // a complete octave sum leaves stage 8 (octave-serial: its last octave)
  assign done        = fv_q[FL-1] && fo_q[FL-1] == OctW'(Slots - 1);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fv_q      <= '0;
      fw_q      <= '0;
      out_fbm_q <= 1'b0;
      wv_q      <= '0;
      pass_q    <= '0;
      slot_q    <= '0;
      for (int s = 0; s < FL; s++) fp_q[s] <= '0;
      for (int s = 0; s < FL; s++) fo_q[s] <= '0;
    end else if (en) begin
      fv_q      <= {fv_q[FL-2:0], issue};
      fw_q      <= {fw_q[FL-2:0], in_water};
      fp_q[0]   <= pass_q;
      fo_q[0]   <= slot_q;
      for (int s = 1; s < FL; s++) fp_q[s] <= fp_q[s-1];
      for (int s = 1; s < FL; s++) fo_q[s] <= fo_q[s-1];
      out_fbm_q <= done && !fw_q[FL-1];
      wv_q      <= {wv_q[WL-2:0], done && fw_q[FL-1] && fp_q[FL-1] == 2'(Passes - 1)};
      if (issue) begin
        slot_q <= last_slot ? '0 : slot_q + 1'b1;
        if (last_slot) pass_q <= last_pass ? '0 : pass_q + 2'd1;
      end
    end
  end

  // ---- stage 1: noise point and octave weights ----
  // x = ((u freq + 2^(Drop-1)) mod 2^64) >> Drop, + sx, modulo 2^32: the bits kept depend on the
  // low Drop + 32 bits of the product only (the wraps are multiples of the 256-cell period).
  // Only the lattice index and the fraction (PtW bits) reach the cores.
  localparam int PtW = LW + TF;
  function automatic logic [PtW-1:0] coord(input logic [UW-1:0] uv, input logic [tu_formats_pkg::NoiseFreqW-1:0] freq,
                                           input logic [PtW-1:0] shift);
    logic signed [Drop+PtW-1:0] a, f, p;
    a = (Drop+PtW)'($signed(uv));
    f = (Drop+PtW)'(freq);
    p = a * f + (Drop+PtW)'(1 << (Drop - 1));
    coord = PtW'(p >> Drop) + shift;
  endfunction
  logic [PtW-1:0] x_d, y_d;
  logic [PtW-1:0] pt_q [3];  // x, y, z
  // water passes 1 and 2: one finite-difference step h along x, then along y
  localparam logic [PtW-1:0] Step = PtW'(1) << tu_formats_pkg::WaterStepCode;
  assign x_d = coord(u_i, pr.freq, pr.sx[0 +: PtW]) + (in_water && pass_q == 2'd1 ? Step : '0);
  assign y_d = coord(v_i, pr.freq, pr.sy[0 +: PtW]) + (in_water && pass_q == 2'd2 ? Step : '0);
  localparam int NyW = LogW + 3;
  logic signed [NyW-1:0] nyquist;  // log2(1 / (2 rho)) + 2 - bias, EllLogF bits
  assign nyquist = NyW'(One) - NyW'($signed(lrho_i)) - NyW'($signed(pr.lfreq));
  logic [WW-1:0] w_d [K];
  logic [K-1:0]  used_d;  // octave i < noct on a core
  always_comb begin
    for (int i = 0; i < K; i++) begin
      logic signed [NyW-1:0] room;
      room = nyquist - NyW'(i * One);
      used_d[i] = i < Octaves && 3'(i) < pr.noct;
      if (!used_d[i]) w_d[i] = '0;
      else if (!pr.limit) w_d[i] = WW'(One);
      else if (guard_i || room < 0) w_d[i] = '0;  // guard: a footprint wider than every octave
      else if (room > NyW'(One)) w_d[i] = WW'(One);
      else w_d[i] = WW'(room);
    end
  end
  always_ff @(posedge clk_i) begin
    if (en) begin
      pt_q[0] <= x_d;
      pt_q[1] <= y_d;
      pt_q[2] <= pr.z[0 +: PtW];
    end
  end

  // ---- the back-end constants and the side data, delayed beside the cores ----
  // bundle, LSB first: side, c0, c1, gain, thr, mabs, norm, smoke, weights, used, water's amp, light
  localparam int NmW = tu_formats_pkg::NoiseNormW;
  localparam int GnW = tu_formats_pkg::NoiseGainW;
  localparam int AmW = tu_formats_pkg::WaterAmpW;
  localparam int LtW = tu_formats_pkg::WaterLightW;
  localparam int OC0 = SideW, OC1 = OC0 + 24, OGn = OC1 + 24, OThr = OGn + GnW, OMabs = OThr + OW;
  localparam int ONorm = OMabs + VW, OSmoke = ONorm + NmW, OW8 = OSmoke + 1, OUsed = OW8 + K * WW;
  localparam int OAmp = OUsed + K, OLt = OAmp + AmW;
  localparam int BW = OLt + 3 * LtW;
  logic [BW-1:0] bk_d, bk_q [CL+2];
  logic [K*WW-1:0] w_flat;
  always_comb begin
    for (int i = 0; i < K; i++) w_flat[i*WW +: WW] = w_d[i];
  end
  assign bk_d = {pr.lz, pr.ly, pr.lx, pr.amp, used_d, w_flat, pr.smoke, pr.norm, pr.mabs, pr.thr, pr.gain, pr.c1, pr.c0, side_i};
  always_ff @(posedge clk_i) begin
    if (en) begin
      bk_q[0] <= bk_d;
      for (int s = 1; s < CL + 2; s++) bk_q[s] <= bk_q[s-1];
    end
  end

  // ---- stages 2..7: one noise core per octave (octave-serial: one core, the octave's shift) ----
  logic signed [VW-1:0] n [K];
  if (Serial != 0) begin : g_serial
    logic [Dims*LW-1:0] lattice;
    logic [Dims*TF-1:0] t;
    for (genvar k = 0; k < Dims; k++) begin : g_axis
      logic [PtW-1:0] low;  // lattice index and fraction of 2^o x
      assign low = pt_q[k] << fo_q[0];
      assign lattice[k*LW +: LW] = low[TF +: LW];
      assign t[k*TF +: TF] = low[0 +: TF];
    end
    tu_noise_core #(.Dims(Dims)) u_core (.clk_i, .en_i(en), .cell_i(lattice), .t_i(t), .noise_o(n[0]));
    for (genvar i = 1; i < K; i++) begin : g_none
      assign n[i] = '0;
    end
  end else begin : g_pipe
  for (genvar i = 0; i < K; i++) begin : g_oct
    if (i < Octaves) begin : g_core
      logic [Dims*LW-1:0] lattice;
      logic [Dims*TF-1:0] t;
      for (genvar k = 0; k < Dims; k++) begin : g_axis
        logic [PtW-1:0] low;  // lattice index and fraction of 2^i x
        assign low = pt_q[k] << i;
        assign lattice[k*LW +: LW] = low[TF +: LW];
        assign t[k*TF +: TF] = low[0 +: TF];
      end
      tu_noise_core #(.Dims(Dims)) u_core (.clk_i, .en_i(en), .cell_i(lattice), .t_i(t), .noise_o(n[i]));
    end else begin : g_none
      assign n[i] = '0;
    end
  end
  end

  // ---- stage 8: the weighted octave sum (bundle at stage 7 = bk_q[CL]) ----
  logic [BW-1:0] b7;
  assign b7 = bk_q[CL];
  localparam int PW = VW + WW + 2;  // w |n| + (1 - w) m before the drop
  logic signed [AccW-1:0] acc_d, acc_q;
  logic [OctW-1:0] o7;  // octave-serial: the octave at stage 7 (its core output n[0])
  assign o7 = fo_q[CL];
  always_comb begin
    // octave-serial: the running sum of the sample's earlier octaves (0 at its first)
    acc_d = Serial != 0 && o7 != '0 ? acc_q : '0;
    for (int i = 0; i < K; i++) begin
      logic signed [VW-1:0] ni, a;
      logic signed [PW-1:0] prod;
      logic [WW-1:0] wi;
      logic on;
      // pipelined: octave i on core i; octave-serial: octave o7 on the one core (term i = o7)
      ni   = Serial != 0 ? n[0] : n[i];
      on   = Serial == 0 || OctW'(i) == o7;
      wi   = b7[OW8 + i*WW +: WW];
      a    = b7[OSmoke] && ni < 0 ? -ni : ni;
      prod = PW'(a) * $signed({1'b0, wi});
      if (b7[OSmoke]) prod = prod + PW'($signed(b7[OMabs +: VW])) * $signed({1'b0, WW'(One) - wi});
      prod = (prod + PW'(1 << (LogF - 1))) >>> LogF;
      if (!b7[OUsed + i] || !on) prod = '0;  // an octave the material does not use adds nothing
      acc_d = acc_d + (AccW'(prod) <<< (K - 1 - i));
    end
  end
  always_ff @(posedge clk_i) begin
    if (en) acc_q <= acc_d;
  end

  // ---- stage 9: value and colour (bundle at stage 8 = bk_q[CL+1]) ----
  logic [BW-1:0] b8;
  assign b8 = bk_q[CL + 1];
  localparam int ProdF = AccF + NormF;
  localparam int QW = AccW + NmW + 2;
  logic signed [QW-1:0] prod_n, q;
  logic [OW-1:0] turb, value;
  logic signed [OW+1:0] dthr;
  logic signed [OW+GnW+2-1:0] dg;
  always_comb begin
    prod_n = QW'(acc_q) * $signed({2'b0, b8[ONorm +: NmW]});
    if (!b8[OSmoke]) begin
      // fbm: acc C_K + 1/2, round half up (noise_fbm.cpp normalise_code)
      q = (prod_n + (QW'(1) <<< (ProdF - 1)) + (QW'(1) <<< (ProdF - TF - 1))) >>> (ProdF - TF);
      turb = '0;
      dthr = '0;
      dg = '0;
    end else begin
      // smoke: turbulence 2 acc C_K (one bit less dropped), then the opacity mapping
      q = (prod_n + (QW'(1) <<< (ProdF - TF - 2))) >>> (ProdF - TF - 1);
      turb = q < 0 ? '0 : q > QW'(1 << TF) ? OW'(1 << TF) : OW'(q);
      dthr = $signed({2'b0, turb}) - $signed({2'b0, b8[OThr +: OW]});
      dg = (OW+GnW+2)'(dthr) * $signed({2'b0, b8[OGn +: GnW]}) + (OW+GnW+2)'(1 << (GainF - 1));
      q = QW'(dg) >>> GainF;
    end
    value = q < 0 ? '0 : q > QW'(1 << TF) ? OW'(1 << TF) : OW'(q);
  end
  // colour: (c0 2^16 + value (c1 - c0) + 2^15) >> 16 per channel; alpha 255 or smoke's value
  function automatic logic [7:0] mix(input logic [7:0] c0, input logic [7:0] c1, input logic [OW-1:0] val);
    logic signed [9:0]       dc;
    logic signed [TF+10-1:0] m;
    dc = $signed({2'b0, c1}) - $signed({2'b0, c0});
    m = $signed({2'b0, c0, TF'(0)}) + $signed({1'b0, val}) * (TF+10)'(dc) + (TF+10)'(1 << (TF - 1));
    mix = 8'(m >>> TF);  // between c0 and c1: the bits above are 0
  endfunction
  logic [31:0] rgba_d, rgba_q;
  logic [SideW-1:0] side_q;
  always_comb begin
    for (int c = 0; c < 3; c++) rgba_d[8*c +: 8] = mix(b8[OC0 + 8*c +: 8], b8[OC1 + 8*c +: 8], value);
    rgba_d[31:24] = b8[OSmoke] ? mix(8'd0, 8'd255, value) : 8'd255;
  end
  always_ff @(posedge clk_i) begin
    if (en) begin
      rgba_q <= rgba_d;
      side_q <= b8[0 +: SideW];
    end
  end

  // ---- water: slopes, normal, Lambert (bundle at stage 8 = b8, the last pass's) ----
  localparam int SlW = tu_formats_pkg::WaterSlopeW;
  localparam logic signed [SlW-1:0] SlMax = {1'b0, {(SlW-1){1'b1}}};
  // g = sat(-a dP): a u13, dP s24, |a dP| < 2^36; saturated to +-SlMax (guard, noise_proc.cpp)
  function automatic logic signed [SlW-1:0] slope(input logic signed [AccW:0] dp, input logic [AmW-1:0] amp);
    logic signed [AccW+AmW+1:0] g;
    g = -((AccW+AmW+2)'(dp) * $signed({1'b0, amp}));
    slope = g > (AccW+AmW+2)'(SlMax) ? SlMax : g < -(AccW+AmW+2)'(SlMax) ? -SlMax : SlW'(g);
  endfunction
  logic [31:0]      rgbw_q;
  logic [SideW-1:0] sidew_q;
  if (HasWater != 0) begin : g_water
    localparam int SqW  = 2 * SlW;               // |n|^2 < 2^62: the root has SlW bits
    localparam int DotW = SlW + LtW - 1;         // |n.L| <= |n| |L| < 2^46.6: signed 48 bits
    localparam int QuW  = tu_formats_pkg::WaterQuoW;
    localparam int SlF  = tu_formats_pkg::WaterSlopeF;
    localparam int CSW  = SideW + 48;            // side, c0, c1 beside the water stages
    logic signed [AccW-1:0] p0_q, p1_q;
    always_ff @(posedge clk_i) begin
      if (en && done && fw_q[FL-1] && fp_q[FL-1] == 2'd0) p0_q <= acc_q;
      if (en && done && fw_q[FL-1] && fp_q[FL-1] == 2'd1) p1_q <= acc_q;
    end
    // W1: g = sat(-a dP) (slope below)
    logic signed [SlW-1:0] gx_q, gy_q;
    logic signed [LtW-1:0] l_q [3];
    logic [CSW-1:0]        cs_q [WL-1];
    always_ff @(posedge clk_i) begin
      if (en) begin
        gx_q <= slope((AccW+1)'(p1_q) - (AccW+1)'(p0_q), b8[OAmp +: AmW]);
        gy_q <= slope((AccW+1)'(acc_q) - (AccW+1)'(p0_q), b8[OAmp +: AmW]);
        for (int c = 0; c < 3; c++) l_q[c] <= b8[OLt + c*LtW +: LtW];
        cs_q[0] <= b8[0 +: CSW];
        for (int s = 1; s < WL - 1; s++) cs_q[s] <= cs_q[s-1];
      end
    end
    // W2: |n|^2 and n.L, exact
    localparam logic [SqW-1:0] OneSq = SqW'(1) << (2 * SlF);
    logic [SqW-1:0]         sq_q;
    logic signed [DotW-1:0] dot_q;
    always_ff @(posedge clk_i) begin
      if (en) begin
        sq_q  <= SqW'(SqW'(gx_q) * SqW'(gx_q)) + SqW'(SqW'(gy_q) * SqW'(gy_q)) + OneSq;
        dot_q <= DotW'(gx_q) * DotW'(l_q[0]) + DotW'(gy_q) * DotW'(l_q[1]) + (DotW'(l_q[2]) <<< SlF);
      end
    end
    // W3..: |n| = floor sqrt(|n|^2), n.L beside it
    logic [SlW-1:0] len;
    tu_isqrt_pipe #(.InW(SqW)) u_sqrt (.clk_i, .en_i(en), .x_i(sq_q), .r_o(len));
    logic signed [DotW-1:0] dotd_q [SlW];
    always_ff @(posedge clk_i) begin
      if (en) begin
        dotd_q[0] <= dot_q;
        for (int s = 1; s < SlW; s++) dotd_q[s] <= dotd_q[s-1];
      end
    end
    // value = floor((n.L + floor(|n| / 2)) / |n|) < 2^QuW (n.L <= |n| |L|, |L| <= 2^16 + 1)
    logic           pos;
    logic [QuW-1:0] quo;
    logic [SlW-1:0] half;
    assign half = len >> 1;
    logic           pos_q [QuW];
    assign pos = dotd_q[SlW-1] > 0;
    tu_udiv_pipe #(.NW(DotW - 1), .DW(SlW), .QW(QuW)) u_div (
      .clk_i, .en_i(en), .n_i(pos ? (DotW-1)'(dotd_q[SlW-1]) + (DotW-1)'(half) : '0), .d_i(len), .q_o(quo)
    );
    always_ff @(posedge clk_i) begin
      if (en) begin
        pos_q[0] <= pos;
        for (int s = 1; s < QuW; s++) pos_q[s] <= pos_q[s-1];
      end
    end
    logic [OW-1:0] wval;
    assign wval = !pos_q[QuW-1] ? '0 : quo > QuW'(1 << TF) ? OW'(1 << TF) : OW'(quo);
    logic [CSW-1:0] cs;
    assign cs = cs_q[WL-2];
    always_ff @(posedge clk_i) begin
      if (en) begin
        for (int c = 0; c < 3; c++) rgbw_q[8*c +: 8] <= mix(cs[OC0 + 8*c +: 8], cs[OC1 + 8*c +: 8], wval);
        rgbw_q[31:24] <= 8'd255;
        sidew_q <= cs[0 +: SideW];
      end
    end
  end else begin : g_no_water
    assign rgbw_q  = '0;
    assign sidew_q = '0;
  end
  assign rgba_o = wv_q[WL-1] ? rgbw_q : rgba_q;
  assign side_o = wv_q[WL-1] ? sidew_q : side_q;

  // Fields each stage does not read; the z axis without Dims = 3; valid bits live in u_ctrl.
  logic unused;
  always_comb begin
    unused = pr.on ^ (^pr.sx[CW-1:PtW]) ^ (^pr.sy[CW-1:PtW]) ^ (^pr.z[CW-1:PtW]) ^
             (^b7[0 +: OMabs]) ^ (^b7[ONorm +: NmW]) ^ (^b8[OMabs +: VW]) ^ (^b8[OW8 +: BW - OW8]);
    if (Dims < 3) unused = unused ^ (^pt_q[2]);
  end
endmodule
