// Object-space pipeline (seed 003 §5), per-sample datapath: grid indices -> pixel position ->
// four bilinear splat weights, II = 1, latency PerspLatency + 1 (9). Bit-exact with
// objspace::splat_fx (cmodel/blocks/objspace, docs/blocks/objspace.md):
//   S1      : p_u = A i + B j + C, p_v = D i + E j + F, q = G i + H j + I, modulo 2^W like the
//             C model's persp::Unit::direct (six products of a signed coefficient and an
//             unsigned 12-bit grid index; exact whenever the value fits its format)
//   S2..S8  : B1's per-pixel back end (tu_persp_pixel): guard, reciprocal, two multiplies,
//             round half up to s32.8 pixels, saturate
//   S9      : x = floor(px), y = floor(py) (the top bits), fx, fy = the PerspUvF low bits;
//             w00 = (1 - fx)(1 - fy), w10 = fx (1 - fy), w01 = (1 - fx) fy, w11 = fx fy, exact
//             u17.16 products (sum exactly 2^16); guarded samples: x = y = 0, weights 0.
// The coefficients are one tile's constants (held for the tile's samples by the caller).
`include "tu_assert.svh"
module tu_objspace_sample (
  input  logic                                            clk_i,
  input  logic                                            rst_ni,
  input  logic                                            in_valid_i,
  output logic                                            in_ready_o,
  input  logic [tu_formats_pkg::PerspPW-1:0]              a_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]              b_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]              c_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]              d_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]              e_i,
  input  logic [tu_formats_pkg::PerspPW-1:0]              f_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]              g_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]              h_i,
  input  logic [tu_formats_pkg::PerspQW-1:0]              i_i,
  input  logic [tu_formats_pkg::PerspXyW-1:0]             gi_i,   // grid column i
  input  logic [tu_formats_pkg::PerspXyW-1:0]             gj_i,   // grid row j
  output logic                                            out_valid_o,
  input  logic                                            out_ready_i,
  output logic [tu_formats_pkg::PerspUvW-tu_formats_pkg::PerspUvF-1:0] x_o,
  output logic [tu_formats_pkg::PerspUvW-tu_formats_pkg::PerspUvF-1:0] y_o,
  output logic [tu_formats_pkg::ObjSplatWW-1:0]           w00_o,
  output logic [tu_formats_pkg::ObjSplatWW-1:0]           w10_o,
  output logic [tu_formats_pkg::ObjSplatWW-1:0]           w01_o,
  output logic [tu_formats_pkg::ObjSplatWW-1:0]           w11_o,
  output logic                                            guard_o
);
  localparam int PW = tu_formats_pkg::PerspPW;
  localparam int QW = tu_formats_pkg::PerspQW;
  localparam int XW = tu_formats_pkg::PerspXyW;
  localparam int UW = tu_formats_pkg::PerspUvW;
  localparam int UF = tu_formats_pkg::PerspUvF;
  localparam int IW = UW - UF;                    // integer pixel part
  localparam int WW = tu_formats_pkg::ObjSplatWW;
  localparam int FW = UF + 1;                     // fraction and its complement: 0..2^UF
  localparam int Depth = tu_formats_pkg::PerspLatency + 1;  // S1, S2..S8 (B1), S9

  logic             en;
  logic [Depth-1:0] stage_valid;

  tu_pipe_valid #(.Depth(Depth)) u_ctrl (
    .clk_i, .rst_ni, .in_valid_i, .in_ready_o, .out_valid_o, .out_ready_i,
    .en_o(en), .stage_valid_o(stage_valid)
  );

  // ---- S1: the tile's projective map at (i, j), modulo 2^W (as the C model's wrap)
  logic signed [XW:0] gi_s, gj_s;
  assign gi_s = $signed({1'b0, gi_i});
  assign gj_s = $signed({1'b0, gj_i});
  logic [PW-1:0] pu_d, pv_d, pu_q1, pv_q1;
  logic [QW-1:0] q_d, q_q1;
  assign pu_d = PW'($signed(a_i) * gi_s) + PW'($signed(b_i) * gj_s) + c_i;
  assign pv_d = PW'($signed(d_i) * gi_s) + PW'($signed(e_i) * gj_s) + f_i;
  assign q_d  = QW'($signed(g_i) * gi_s) + QW'($signed(h_i) * gj_s) + i_i;
  always_ff @(posedge clk_i) begin
    if (en) begin
      pu_q1 <= pu_d;
      pv_q1 <= pv_d;
      q_q1  <= q_d;
    end
  end

  // ---- S2..S8: B1's per-pixel back end
  logic [UW-1:0] px, py;
  logic          guard;
  tu_persp_pixel u_pixel (
    .clk_i, .en_i(en), .pu_i(pu_q1), .pv_i(pv_q1), .q_i(q_q1), .u_o(px), .v_o(py), .flag_o(guard)
  );

  // ---- S9: floor, fractions, four exact weight products
  localparam logic [FW-1:0] One = FW'(1) << UF;
  logic [FW-1:0] fx, fy, cx, cy;  // f and 1 - f in units of 2^-UF
  assign fx = FW'(px[UF-1:0]);
  assign fy = FW'(py[UF-1:0]);
  assign cx = One - fx;
  assign cy = One - fy;
  logic [IW-1:0] x_q, y_q;
  logic [WW-1:0] w00_q, w10_q, w01_q, w11_q;
  logic          guard_q;
  always_ff @(posedge clk_i) begin
    if (en) begin
      x_q     <= guard ? '0 : px[UW-1:UF];
      y_q     <= guard ? '0 : py[UW-1:UF];
      w00_q   <= guard ? '0 : WW'(cx * cy);
      w10_q   <= guard ? '0 : WW'(fx * cy);
      w01_q   <= guard ? '0 : WW'(cx * fy);
      w11_q   <= guard ? '0 : WW'(fx * fy);
      guard_q <= guard;
    end
  end
  assign x_o     = x_q;
  assign y_o     = y_q;
  assign w00_o   = w00_q;
  assign w10_o   = w10_q;
  assign w01_o   = w01_q;
  assign w11_o   = w11_q;
  assign guard_o = guard_q;

  logic unused;
  assign unused = ^stage_valid;

  // valid/ready protocol checks (rtl/common/tu_assert.svh)
  `TU_ASSERT_HANDSHAKE(OutHandshake, out_valid_o, out_ready_i,
                       {x_o, y_o, w00_o, w10_o, w01_o, w11_o, guard_o})
endmodule
