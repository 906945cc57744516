// One octave of improved noise (cmodel/blocks/noise/noise_core.hpp), Dims = 3 or 2 (the z = 0
// slice: 4 corners), NoiseCoreLatency = 6 stages, all advancing on en_i:
//   1: p[X], p[X+1] -> A = p[X+cx] + Y              fade stage 1 (t^2, b) per axis
//   2: p[A+cy] + Z                                  fade stage 2 (t^3)
//   3: corner hashes p[p[A+cy] + Z + cz]            fade stage 3 (s)
//   4: gradient dots, x lerps    5: y lerps    6: z lerp (Dims = 2: register)
// Inputs per axis k: cell_i[8k +: 8] = floor(x) & 255, t_i[16k +: 16] = frac(x).
module tu_noise_core #(
  parameter int Dims = 3
) (
  input  logic                                          clk_i,
  input  logic                                          en_i,
  input  logic [Dims*tu_formats_pkg::NoiseLatW-1:0]     cell_i,
  input  logic [Dims*tu_formats_pkg::NoiseTF-1:0]       t_i,
  output logic signed [tu_formats_pkg::NoiseValW-1:0]   noise_o
);
  localparam int LW = tu_formats_pkg::NoiseLatW;
  localparam int TF = tu_formats_pkg::NoiseTF;
  localparam int SW = tu_formats_pkg::NoiseSW;
  localparam int DW = tu_formats_pkg::NoiseDW;
  localparam int VW = tu_formats_pkg::NoiseValW;
  localparam int NC = 1 << Dims;  // corners

  // ---- fade per axis (3 stages) and the local coordinate delayed to stage 4 ----
  logic [SW-1:0] s [Dims];
  logic [TF-1:0] t_q1 [Dims];
  logic [TF-1:0] t_q2 [Dims];
  logic [TF-1:0] t_q3 [Dims];
  for (genvar k = 0; k < Dims; k++) begin : g_fade
    tu_noise_fade u_fade (.clk_i, .en_i, .t_i(t_i[k*TF +: TF]), .s_o(s[k]));
  end

  // ---- hash chain through the permutation ROM ----
  logic [LW-1:0] px [2];                 // stage 1 ROM outputs p[X + cx]
  logic [LW-1:0] a_q [2];                // A = p[X + cx] + Y
  logic [LW-1:0] pa [4];                 // stage 2 ROM outputs p[A + cy]
  logic [LW-1:0] b_q [4];                // p[A + cy] + Z
  logic [LW-1:0] ph [NC];                // stage 3 ROM outputs: corner hashes
  logic [3:0]    h_q [NC];
  logic [LW-1:0] z_q1;
  logic [LW-1:0] x_cell, y_cell, z_cell;
  assign x_cell = cell_i[0 +: LW];
  assign y_cell = cell_i[LW +: LW];
  if (Dims == 3) begin : g_z3
    assign z_cell = cell_i[2*LW +: LW];
  end else begin : g_z2
    assign z_cell = '0;
  end

  for (genvar c = 0; c < 2; c++) begin : g_h1
    tu_noise_perm_rom u_rom (.idx_i(x_cell + LW'(c)), .p_o(px[c]));
  end
  for (genvar c = 0; c < 4; c++) begin : g_h2
    tu_noise_perm_rom u_rom (.idx_i(a_q[c & 1] + LW'(c >> 1)), .p_o(pa[c]));
  end
  // Corner c = cx + 2 cy + 4 cz hashes p[b[cx + 2 cy] + cz].
  for (genvar c = 0; c < NC; c++) begin : g_h3
    tu_noise_perm_rom u_rom (.idx_i(b_q[c & 3] + LW'(c >> 2)), .p_o(ph[c]));
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int c = 0; c < 2; c++) a_q[c] <= px[c] + y_cell;
      z_q1 <= z_cell;
      for (int c = 0; c < 4; c++) b_q[c] <= pa[c] + z_q1;
      for (int c = 0; c < NC; c++) h_q[c] <= ph[c][3:0];
      for (int k = 0; k < Dims; k++) begin
        t_q1[k] <= t_i[k*TF +: TF];
        t_q2[k] <= t_q1[k];
        t_q3[k] <= t_q2[k];
      end
    end
  end

  // ---- stage 4: corner offsets t, t - 1 (s17.16: {0, t}, {1, t}), gradient dots, x lerps ----
  logic signed [DW-1:0] d0 [3];  // offset from the low corner
  logic signed [DW-1:0] d1 [3];  // offset from the high corner
  always_comb begin
    for (int k = 0; k < 3; k++) begin
      d0[k] = '0;
      d1[k] = '0;
    end
    for (int k = 0; k < Dims; k++) begin
      d0[k] = {1'b0, t_q3[k]};
      d1[k] = {1'b1, t_q3[k]};
    end
  end
  logic signed [VW-1:0] dot [NC];
  for (genvar c = 0; c < NC; c++) begin : g_dot
    localparam bit Hx = (c % 2) == 1;  // corner c = cx + 2 cy + 4 cz
    localparam bit Hy = ((c / 2) % 2) == 1;
    localparam bit Hz = c >= 4;
    tu_noise_grad u_grad (.hash_i(h_q[c]), .x_i(Hx ? d1[0] : d0[0]), .y_i(Hy ? d1[1] : d0[1]),
                          .z_i(Hz ? d1[2] : d0[2]), .dot_o(dot[c]));
  end

  logic signed [VW-1:0] l1_d [NC/2];
  logic signed [VW-1:0] l1_q [NC/2];
  for (genvar j = 0; j < NC/2; j++) begin : g_lx
    tu_noise_lerp u_lerp (.s_i(s[0]), .a_i(dot[2*j]), .b_i(dot[2*j+1]), .l_o(l1_d[j]));
  end
  // Fade weights of the later axes wait for their lerp level.
  logic [SW-1:0] sy_q, sz_q1, sz_q2;
  logic signed [VW-1:0] l2_d [NC/4];
  logic signed [VW-1:0] l2_q [NC/4];
  for (genvar j = 0; j < NC/4; j++) begin : g_ly
    tu_noise_lerp u_lerp (.s_i(sy_q), .a_i(l1_q[2*j]), .b_i(l1_q[2*j+1]), .l_o(l2_d[j]));
  end
  logic signed [VW-1:0] l3_d, l3_q;
  if (Dims == 3) begin : g_lz3
    tu_noise_lerp u_lerp (.s_i(sz_q2), .a_i(l2_q[0]), .b_i(l2_q[1]), .l_o(l3_d));
    always_ff @(posedge clk_i) begin
      if (en_i) sz_q1 <= s[2];
    end
  end else begin : g_lz2
    assign l3_d = l2_q[0];
    assign sz_q1 = '0;
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int j = 0; j < NC/2; j++) l1_q[j] <= l1_d[j];
      sy_q  <= s[1];
      sz_q2 <= sz_q1;
      for (int j = 0; j < NC/4; j++) l2_q[j] <= l2_d[j];
      l3_q <= l3_d;
    end
  end
  assign noise_o = l3_q;

  // Hashes use the low 4 bits (grad(hash & 15)); Dims = 2 leaves the z weight unused.
  logic unused;
  always_comb begin
    unused = ^sz_q2;
    for (int c = 0; c < NC; c++) unused = unused ^ (^ph[c][LW-1:4]);
  end
endmodule
