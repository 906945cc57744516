// Texel address (combinational): level-L texel (x, y), any integers, wrapped like
// tex::Texture::fetch (repeat: modulo the power-of-two level size; clamp: to [0, size-1]), at
// base + levelbase(L) + y * width_L + x. Level L of a 2^lw x 2^lh texture is
// 2^max(0, lw-L) x 2^max(0, lh-L); levels are stored one after another from level 0, so
// levelbase(L) = sum_{k<L} 2^(max(0,lw-k) + max(0,lh-k)).
module tu_texel_addr #(
  parameter int CoordW = 32
) (
  input  logic [tu_formats_pkg::TexAddrW-1:0] base_i,     // texture base (word address)
  input  logic [3:0]                          lw_i,       // log2 width of level 0
  input  logic [3:0]                          lh_i,       // log2 height of level 0
  input  logic                                clamp_i,    // 0: repeat, 1: clamp
  input  logic [3:0]                          level_i,
  input  logic signed [CoordW-1:0]            x_i,
  input  logic signed [CoordW-1:0]            y_i,
  output logic [tu_formats_pkg::TexAddrW-1:0] addr_o
);
  localparam int AW = tu_formats_pkg::TexAddrW;
  logic [3:0]    wl, hl;  // log2 size of level L
  logic [AW-1:0] lbase, xw, yw, wmask, hmask;
  always_comb begin
    wl = (lw_i > level_i) ? lw_i - level_i : 4'd0;
    hl = (lh_i > level_i) ? lh_i - level_i : 4'd0;
    lbase = '0;
    for (int k = 0; k < tu_formats_pkg::TexMaxLevels; k++) begin
      if (4'(k) < level_i) begin
        lbase = lbase + (AW'(1) << ((lw_i > 4'(k) ? 32'(lw_i) - 32'(k) : 0) +
                                    (lh_i > 4'(k) ? 32'(lh_i) - 32'(k) : 0)));
      end
    end
    wmask = (AW'(1) << wl) - AW'(1);
    hmask = (AW'(1) << hl) - AW'(1);
    if (clamp_i) begin
      xw = x_i < 0 ? '0 : (x_i > $signed(CoordW'(wmask))) ? wmask : AW'(x_i);
      yw = y_i < 0 ? '0 : (y_i > $signed(CoordW'(hmask))) ? hmask : AW'(y_i);
    end else begin
      xw = AW'(x_i) & wmask;
      yw = AW'(y_i) & hmask;
    end
    addr_o = base_i + lbase + (yw << wl) + xw;
  end
endmodule
