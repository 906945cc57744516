// tu_clip_fold: p = sat_[1, 2^16-1](round_half_up(acc, 2^-16)); v = neg ? 2^16 - p : p.
module tu_clip_fold (
  input  logic signed [tu_formats_pkg::ClipAccW-1:0] acc_i,
  input  logic                                       neg_i,
  output logic [tu_formats_pkg::ClipOutW-1:0]        v_o
);
  localparam int AccW = tu_formats_pkg::ClipAccW;
  localparam int Sh   = tu_formats_pkg::ClipCoefF - tu_formats_pkg::ClipOutF;
  localparam int OutW = tu_formats_pkg::ClipOutW;
  logic signed [AccW:0] rnd;
  logic [OutW-1:0]      p;
  assign rnd = ($signed({acc_i[AccW-1], acc_i}) + $signed((AccW+1)'(1 << (Sh - 1)))) >>> Sh;
  always_comb begin
    if (rnd < (AccW+1)'(1)) begin
      p = OutW'(1);
    end else if (rnd > (AccW+1)'({OutW{1'b1}})) begin
      p = '1;
    end else begin
      p = OutW'(rnd);
    end
  end
  assign v_o = neg_i ? OutW'((OutW+1)'(1) << OutW) - p : p;
endmodule
