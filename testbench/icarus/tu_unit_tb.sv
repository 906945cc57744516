// The texture-unit top (rtl/top/tu_texture_unit.sv, or its gate-level netlist: the same module
// name and ports) under Icarus Verilog 11 on a scene's spans, without C++ at simulation time: the
// stimulus of testbench/icarus/tu_unit_stimulus.cpp (spans.txt: one span a line, hex fields;
// texels.hex: the texel RAM image; expect.txt: the C-model pixels, one per covered pixel in span
// order). The texel RAM is a synchronous-read RAM on tex_* (1-cycle latency; the read register
// holds when not enabled; words past the image read 0: testbench/cosim/sync_read_ram.hpp); the
// depth RAM reads 0, and no view or shade word is offered (a unit without relief and shading).
// Spans go in with valid/ready and random bubbles, pixels come out under random back-pressure
// (+stall percent each, one $urandom draw per side per cycle whatever happens, so that two runs
// with the same +seed see the same stalls); every pixel is compared with expect.txt (x, y, rgba,
// texels visited, B2 flags; inside count and filter flags 0: the texture path's engines) and written to
// +log (every output port, hex) so that two runs (RTL, netlist) can be compared bit for bit.
// Prints "tu_unit_tb: PASS S spans, N pixels, 0 mismatches, C cycles" (C: the first edge a span
// can be taken to the last pixel's, as testbench/cosim/harness.hpp counts) and $finish, or "tu_unit_tb: FAIL ..." and $fatal.
// Plusargs: +dir=STIMULUS_DIR +texwords=N (words in texels.hex) +log=FILE +stall=P (30) +seed=S (1)
//           +progress (a line every 1000 cycles)
module tu_unit_tb;
  localparam integer PW = tu_formats_pkg::PerspPW, QW = tu_formats_pkg::PerspQW, XW = tu_formats_pkg::PerspXyW;
  localparam integer NW = tu_formats_pkg::EllNxW, AW = tu_formats_pkg::TexAddrW;
  localparam integer TPW = tu_unit_cfg_pkg::HasBc1 != 0 ? 64 : tu_unit_cfg_pkg::TexelW;  // texel port
  localparam integer MaxPix = 1 << 16;
  localparam integer HangCycles = 20000;

  reg clk = 1'b0, rst_n = 1'b0;
  always #5 clk = ~clk;

  // ---- span ports ----
  reg [PW-1:0] a, b, c, d, e, f;
  reg [QW-1:0] g, h, i;
  reg [XW-1:0] x0, x1, y;
  reg [NW-1:0] kux, kvx, kuy, kvy, m, nn;
  reg [tu_formats_pkg::EllDetW-1:0] dm;
  reg [tu_formats_pkg::EllDetExpW-1:0] dexp;
  reg [tu_formats_pkg::EllAnisoW-1:0] laniso;
  reg [tu_formats_pkg::EllMaxLodW-1:0] maxlod;
  reg [tu_formats_pkg::TexLodBiasW-1:0] lbias;
  reg [tu_formats_pkg::EllLodW-1:0] lminlod, lmaxlod;
  reg [3:0] lbase, ltop, tlw, tlh;
  reg [AW-1:0] tbase;
  reg [2*tu_formats_pkg::WrapW-1:0] twrap;
  reg [tu_formats_pkg::TexFmtW-1:0] tfmt;
  reg tsrgb, clip;
  reg [1:0] wsrc;
  reg [tu_formats_pkg::EwaCountW-1:0] cap;
  reg [tu_formats_pkg::EngineW-1:0] filt;
  reg [tu_formats_pkg::FelProbeW-1:0] fnmax;

  reg in_valid = 1'b0, out_ready = 1'b0;
  wire in_ready, out_valid;
  wire tex_req;
  wire [AW-1:0] tex_addr;
  reg [TPW-1:0] tex_data = 0;
  wire [XW-1:0] x_o, y_o;
  wire [31:0] rgba_o;
  wire [3:0] level_o;
  wire [tu_formats_pkg::EwaCountW-1:0] visited_o, inside_o;
  wire [4:0] flags_o, eflags_o;
  wire [1:0] pflags_o;
  wire [tu_formats_pkg::PomNW-1:0] rn_o, rsteps_o;
  wire [2:0] rflags_o;
  wire d_req, a_req, view_ready, shade_ready;
  wire [AW-1:0] d_addr, a_addr;
  wire texk_req;
  wire [AW-1:0] texk_addr;

  tu_texture_unit u_dut (
    .clk_i(clk), .rst_ni(rst_n), .in_valid_i(in_valid), .in_ready_o(in_ready),
    .a_i(a), .b_i(b), .c_i(c), .d_i(d), .e_i(e), .f_i(f), .g_i(g), .h_i(h), .i_i(i),
    .x0_i(x0), .x1_i(x1), .y_i(y), .kux_i(kux), .kvx_i(kvx), .kuy_i(kuy), .kvy_i(kvy), .m_i(m), .nn_i(nn),
    .dm_i(dm), .dexp_i(dexp), .laniso_i(laniso), .maxlod_i(maxlod), .lbias_i(lbias), .lminlod_i(lminlod),
    .lmaxlod_i(lmaxlod), .lbase_i(lbase), .ltop_i(ltop), .tbase_i(tbase), .tlw_i(tlw), .tlh_i(tlh),
    .twrap_i(twrap), .tfmt_i(tfmt), .tsrgb_i(tsrgb), .wsrc_i(wsrc), .cap_i(cap), .filt_i(filt),
    .fnmax_i(fnmax), .clip_i(clip),
    .rel_i(1'b0), .radapt_i(1'b0), .riter_i(1'b0), .rlayers_i('0), .rscale_i('0), .hbase_i('0),
    .hlw_i(4'd0), .hlh_i(4'd0), .rdm_i(1'b0), .dlayers_i('0), .dbase_i('0),
    .afv_i(1'b0), .admin_i(8'd0), .abias_i(8'd0), .arule_i(1'b0), .proc_i('0),
    .view_valid_i(1'b0), .view_ready_o(view_ready), .view_ok_i(1'b0), .vx_i('0), .vy_i('0), .vz_i('0), .vc_i('0),
    .d_req_o(d_req), .d_addr_o(d_addr), .d_data_i(8'd0), .a_req_o(a_req), .a_addr_o(a_addr), .a_data_i(8'd0),
    .shade_valid_i(1'b0), .shade_ready_o(shade_ready), .shade_i('0),
    .tex_req_o(tex_req), .tex_addr_o(tex_addr), .tex_data_i(tex_data),
    .texk_req_o(texk_req), .texk_addr_o(texk_addr), .texk_data_i('0),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .x_o(x_o), .y_o(y_o), .rgba_o(rgba_o), .level_o(level_o),
    .visited_o(visited_o), .inside_o(inside_o), .flags_o(flags_o), .eflags_o(eflags_o), .pflags_o(pflags_o),
    .rn_o(rn_o), .rsteps_o(rsteps_o), .rflags_o(rflags_o)
  );

  // ---- texel RAM ----
  reg [63:0] ram [0:(1 << tu_formats_pkg::TexRamLog2Words)-1];
  integer texwords;
  always @(posedge clk)
    if (tex_req) tex_data <= tex_addr < texwords ? ram[tex_addr][TPW-1:0] : '0;

  // ---- stimulus and expected pixels ----
  reg [1023:0] dir, logpath;
  integer fs, fe, fl, r, stall, seed, seed0, progress;
  reg [31:0] ex [0:MaxPix-1], ey [0:MaxPix-1], ergba [0:MaxPix-1], evis [0:MaxPix-1], eef [0:MaxPix-1];
  integer npix, got, mismatches, cycles, idle, last_out, spans_in, drain;
  reg have, done;

  task fail(input [8*120-1:0] msg);
    begin
      $display("tu_unit_tb: FAIL %0s (after %0d pixels, cycle %0d)", msg, got, cycles);
      $fatal(1);
    end
  endtask

  // The next span of spans.txt into the span registers (have = 0 at the end of the file).
  task next_span;
    reg [7:0] ch;
    begin
      have = 1'b0;
      r = $fscanf(fs, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h\n",
                  a, b, c, d, e, f, g, h, i, x0, x1, y, kux, kvx, kuy, kvy, m, nn, dm, dexp, laniso, maxlod,
                  lbias, lminlod, lmaxlod, lbase, ltop, tbase, tlw, tlh, twrap, tfmt, tsrgb, wsrc, cap, filt,
                  fnmax, clip);
      if (r == 38) have = 1'b1;
      else if (r > 0) fail("spans.txt: a line without 38 fields");
    end
  endtask

  initial begin
    if (!$value$plusargs("dir=%s", dir)) begin
      $display("tu_unit_tb: FAIL no +dir=STIMULUS_DIR");
      $fatal(1);
    end
    if (!$value$plusargs("texwords=%d", texwords)) texwords = 0;
    if (!$value$plusargs("stall=%d", stall)) stall = 30;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    seed0 = seed;
    progress = $test$plusargs("progress");
    if (texwords > 0) $readmemh({dir, "/texels.hex"}, ram, 0, texwords - 1);
    fe = $fopen({dir, "/expect.txt"}, "r");
    if (fe == 0) fail("cannot open expect.txt");
    npix = 0;
    while (!$feof(fe) && npix < MaxPix) begin
      r = $fscanf(fe, "%h %h %h %h %h\n", ex[npix], ey[npix], ergba[npix], evis[npix], eef[npix]);
      if (r == 5) npix = npix + 1;
      else if (r > 0) fail("expect.txt: a line without 5 fields");
      else r = $fgetc(fe);
    end
    fs = $fopen({dir, "/spans.txt"}, "r");
    if (fs == 0) fail("cannot open spans.txt");
    r = $fgetc(fs);  // the comment line
    while (r != 10 && r != -1) r = $fgetc(fs);
    fl = 0;
    if ($value$plusargs("log=%s", logpath)) fl = $fopen(logpath, "w");
    got = 0; mismatches = 0; cycles = 0; idle = 0; last_out = 0; spans_in = 0; done = 1'b0;
    r = $urandom(seed);
    next_span;
    repeat (3) @(posedge clk);
    rst_n <= 1'b1;
  end

  reg taken, in_draw, out_draw;
  always @(posedge clk) if (rst_n) begin
    taken = 1'b0;
    cycles = cycles + 1;
    idle = idle + 1;
    if (in_valid && in_ready) begin
      taken = 1'b1;
      spans_in = spans_in + 1;
      idle = 0;
    end
    if (out_valid && out_ready) begin
      idle = 0;
      last_out = cycles;
      if (fl != 0)
        $fdisplay(fl, "%h %h %h %h %h %h %h %h %h %h %h %h", x_o, y_o, rgba_o, level_o, visited_o, inside_o,
                  flags_o, eflags_o, pflags_o, rn_o, rsteps_o, rflags_o);
      if (got >= npix) fail("a pixel more than expect.txt holds");
      if (x_o !== ex[got][XW-1:0] || y_o !== ey[got][XW-1:0] || rgba_o !== ergba[got] ||
          visited_o !== evis[got][tu_formats_pkg::EwaCountW-1:0] || inside_o !== '0 || flags_o !== '0 ||
          eflags_o !== eef[got][4:0]) begin
        mismatches = mismatches + 1;
        if (mismatches <= 10)
          $display("tu_unit_tb: mismatch pixel %0d: got (%0d,%0d) rgba %h visited %0d inside %0d flags %h eflags %h; expected (%0d,%0d) rgba %h visited %0d eflags %h",
                   got, x_o, y_o, rgba_o, visited_o, inside_o, flags_o, eflags_o, ex[got], ey[got], ergba[got], evis[got], eef[got]);
      end
      got = got + 1;
    end
    if (idle > HangCycles) fail("hung: no handshake for 20000 cycles");
    if (progress && cycles % 1000 == 0) $display("tu_unit_tb: cycle %0d, %0d spans in, %0d pixels out", cycles, spans_in, got);
    if (!have && got == npix && !done) begin
      done = 1'b1;
      drain = 0;
    end
    if (done) begin
      drain = drain + 1;
      if (drain == 64) begin
        if (fl != 0) $fclose(fl);
        if (mismatches != 0) begin
          $display("tu_unit_tb: FAIL %0d pixels, %0d mismatches", got, mismatches);
          $fatal(1);
        end
        // Cycles as testbench/cosim/harness.hpp counts them: from the first edge a span can be
        // taken (edge 2 after reset release: in_valid rises after edge 1) to the last pixel's edge.
        $display("tu_unit_tb: PASS %0d spans, %0d pixels, 0 mismatches, %0d cycles, %0d%% stalls, seed %0d",
                 spans_in, got, last_out - 1, stall, seed0);
        $finish;
      end
    end
    #1;
    if (taken) next_span;  // into the span ports after the edge the unit sampled them on
    in_draw = ($urandom % 100) >= stall;
    out_draw = ($urandom % 100) >= stall;
    // A presented span stays valid (same fields) until it is taken; a new one may wait a bubble.
    if (taken || !in_valid) in_valid <= have && in_draw;
    out_ready <= out_draw;
  end
endmodule
