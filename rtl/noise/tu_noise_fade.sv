// Fade s = 6t^5 - 15t^4 + 10t^3 = t^3 (t (6t - 15) + 10), three pipeline stages (en_i):
//   1: t2 = round_half_up(t^2), b = round_half_up(t (6t - 15)) + 10   (u24.24, u28.24)
//   2: t3 = round_half_up(t2 t)                                       (u24.24)
//   3: s  = round_half_up(t3 b)                                       (u17.16, in [0,1])
// Bit-identical to cmodel/blocks/noise/noise_fade.hpp (|s - fade| <= 0.516 ULP, monotonic).
module tu_noise_fade (
  input  logic                                clk_i,
  input  logic                                en_i,
  input  logic [tu_formats_pkg::NoiseTF-1:0]  t_i,
  output logic [tu_formats_pkg::NoiseSW-1:0]  s_o
);
  localparam int TF = tu_formats_pkg::NoiseTF;
  localparam int IF = tu_formats_pkg::NoiseFadeIF;
  localparam int BW = tu_formats_pkg::NoiseFadeBW;
  localparam int SW = tu_formats_pkg::NoiseSW;
  localparam int AW = TF + 5;  // 6t - 15 in (-15, -9]: signed, TF fraction bits

  // Stage 1.
  logic signed [AW-1:0]     a1;
  logic signed [AW+TF:0]    p1;  // t (6t - 15): signed, 2 TF fraction bits
  logic [2*TF-1:0]          tt;
  logic [IF-1:0]            t2_d, t2_q;
  logic [BW-1:0]            b_d, b_q1, b_q2;
  logic [TF-1:0]            t_q1;
  always_comb begin
    a1   = AW'({2'b0, t_i, 2'b0}) + AW'({3'b0, t_i, 1'b0}) - AW'(15 << TF);  // 4t + 2t - 15
    p1   = $signed({1'b0, t_i}) * a1;
    tt   = t_i * t_i;
    t2_d = IF'((tt + (2*TF)'(1 << (2*TF - IF - 1))) >> (2*TF - IF));
    b_d  = BW'((p1 + (AW+TF+1)'(1 << (2*TF - IF - 1))) >>> (2*TF - IF)) + BW'(10 << IF);
  end

  // Stage 2.
  logic [IF+TF-1:0] p2;
  logic [IF-1:0]    t3_d, t3_q;
  assign p2   = t2_q * t_q1;
  assign t3_d = IF'((p2 + (IF+TF)'(1 << (TF - 1))) >> TF);

  // Stage 3.
  logic [IF+BW-1:0] p3;
  logic [SW-1:0]    s_d, s_q;
  assign p3  = t3_q * b_q2;
  assign s_d = SW'((p3 + ((IF+BW)'(1) << (2*IF - TF - 1))) >> (2*IF - TF));

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      t2_q <= t2_d;
      b_q1 <= b_d;
      t_q1 <= t_i;
      t3_q <= t3_d;
      b_q2 <= b_q1;
      s_q  <= s_d;
    end
  end
  assign s_o = s_q;
endmodule
