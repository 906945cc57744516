// Noise unit of the texture unit (procedural materials, cmodel/blocks/noise/noise_proc.hpp
// proc_value_fx + proc_color_fx; docs/blocks/noise.md §5): the colour of a pixel from the fBm or
// smoke of Perlin noise at B1's (u, v) with footprint-limited octave weights from B2's lrho.
// Pipelined (one pixel per clock, Octaves noise cores), NoiseUnitLatency stages under global stall:
//   1     x = wrap32(round(u freq) + sx), y likewise (s32.16); w_i = clamp(1 - lrho - lfreq - i, 0, 1)
//   2..7  tu_noise_core per octave i at 2^i (x, y, z)
//   8     acc = sum_i round(w_i n_i (+ (1 - w_i) E|n| for smoke's |n_i|)) 2^(NoiseOctaves-1-i), exact
//   9     fbm: acc C_K + 1/2; smoke: clamp((2 acc C_K - thr) gain); colour c0 + value (c1 - c0)
// A B1-guard pixel has no footprint: every weight 0 (all 1 without the limit). Octaves i >= noct
// add nothing. Dims = 2 leaves the z axis out (materials without time: z = 0, the same bits).
`include "tu_records.svh"
module tu_noise_unit #(
  parameter int Dims    = 3,
  parameter int Octaves = tu_formats_pkg::NoiseOctaves,  // noise cores: the largest noct served
  parameter int SideW   = 1
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

  logic en;
  logic [Lat-1:0] stage_valid;
  tu_pipe_valid #(.Depth(Lat)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  tu_proc_t pr;
  assign pr = proc_i;

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
  assign x_d = coord(u_i, pr.freq, pr.sx[0 +: PtW]);
  assign y_d = coord(v_i, pr.freq, pr.sy[0 +: PtW]);
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
  // bundle, LSB first: side, c0, c1, gain, thr, mabs, norm, smoke, weights, used
  localparam int NmW = tu_formats_pkg::NoiseNormW;
  localparam int GnW = tu_formats_pkg::NoiseGainW;
  localparam int OC0 = SideW, OC1 = OC0 + 24, OGn = OC1 + 24, OThr = OGn + GnW, OMabs = OThr + OW;
  localparam int ONorm = OMabs + VW, OSmoke = ONorm + NmW, OW8 = OSmoke + 1, OUsed = OW8 + K * WW;
  localparam int BW = OUsed + K;
  logic [BW-1:0] bk_d, bk_q [CL+2];
  logic [K*WW-1:0] w_flat;
  always_comb begin
    for (int i = 0; i < K; i++) w_flat[i*WW +: WW] = w_d[i];
  end
  assign bk_d = {used_d, w_flat, pr.smoke, pr.norm, pr.mabs, pr.thr, pr.gain, pr.c1, pr.c0, side_i};
  always_ff @(posedge clk_i) begin
    if (en) begin
      bk_q[0] <= bk_d;
      for (int s = 1; s < CL + 2; s++) bk_q[s] <= bk_q[s-1];
    end
  end

  // ---- stages 2..7: one noise core per octave ----
  logic signed [VW-1:0] n [K];
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

  // ---- stage 8: the weighted octave sum (bundle at stage 7 = bk_q[CL]) ----
  logic [BW-1:0] b7;
  assign b7 = bk_q[CL];
  localparam int PW = VW + WW + 2;  // w |n| + (1 - w) m before the drop
  logic signed [AccW-1:0] acc_d, acc_q;
  always_comb begin
    acc_d = '0;
    for (int i = 0; i < K; i++) begin
      logic signed [VW-1:0] a;
      logic signed [PW-1:0] prod;
      logic [WW-1:0] wi;
      wi   = b7[OW8 + i*WW +: WW];
      a    = b7[OSmoke] && n[i] < 0 ? -n[i] : n[i];
      prod = PW'(a) * $signed({1'b0, wi});
      if (b7[OSmoke]) prod = prod + PW'($signed(b7[OMabs +: VW])) * $signed({1'b0, WW'(One) - wi});
      prod = (prod + PW'(1 << (LogF - 1))) >>> LogF;
      if (!b7[OUsed + i]) prod = '0;  // an octave the material does not use adds nothing
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
  assign rgba_o = rgba_q;
  assign side_o = side_q;

  // Fields each stage does not read; the z axis without Dims = 3; valid bits live in u_ctrl.
  logic unused;
  always_comb begin
    unused = ^stage_valid ^ pr.on ^ (^pr.sx[CW-1:PtW]) ^ (^pr.sy[CW-1:PtW]) ^ (^pr.z[CW-1:PtW]) ^
             (^b7[0 +: OMabs]) ^ (^b7[ONorm +: NmW]) ^ (^b8[OMabs +: VW]) ^ (^b8[OW8 +: BW - OW8]);
    if (Dims < 3) unused = unused ^ (^pt_q[2]);
  end
endmodule
