// The sampler's level-of-detail step, exactly tex::trilinear_lod (texture/trilinear_lod.hpp):
//   lam = (l >> (EllLogF - TexLodF)) + bias - base, clamped to [min lod, max lod] (min wins when
//   above max), lam <= 0: magnification (level base), lam >= top - base: the top level alone;
//   lod = base + lam (u12.8). base and top are the material's level range (tex::level_range,
//   base <= top <= 15, set by the driver). Combinational: tu_ellipse runs it on the GL log2 rho
//   (trilinear) and on the clamped minor axis (the EWA's level).
module tu_lod_rule (
  input  logic signed [31:0]                     l_i,      // log2 rho, s(EllLogW).EllLogF, sign-extended
  input  logic [tu_formats_pkg::TexLodBiasW-1:0] bias_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]     minlod_i,
  input  logic [tu_formats_pkg::EllLodW-1:0]     maxlod_i,
  input  logic [3:0]                             base_i,
  input  logic [3:0]                             top_i,
  output logic [tu_formats_pkg::EllLodW-1:0]     lod_o,
  output logic [2:0]                             flags_o   // tex::TriFlag {sat, clamp, magnify}
);
  logic signed [31:0] lam, lo, hi, basec, span;
  always_comb begin
    lo    = $signed(32'(minlod_i));
    hi    = $signed(32'(maxlod_i));
    basec = $signed(32'(base_i)) <<< tu_formats_pkg::TexLodF;
    span  = ($signed(32'(top_i)) <<< tu_formats_pkg::TexLodF) - basec;
    lam   = (l_i >>> (tu_formats_pkg::EllLogF - tu_formats_pkg::TexLodF)) +
            32'($signed(bias_i)) - basec;
    flags_o = '0;
    // the clamp flag: min lod > 0 raised lambda, or max lod lowered it (as the C model)
    flags_o[1] = (lam < lo && lo > 0) || lam > hi;
    if (lam < lo || lam > hi) lam = (lam < lo || lo > hi) ? lo : hi;
    if (lam <= 0) begin
      flags_o[0] = 1'b1;
      lam = 0;
    end else if (lam >= span) begin
      flags_o[2] = 1'b1;
      lam = span;
    end
    lod_o = tu_formats_pkg::EllLodW'(lam + basec);
  end
endmodule
