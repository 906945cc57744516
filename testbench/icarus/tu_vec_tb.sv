// Vector-file co-simulation without C++ (the second simulator, Icarus Verilog 11 `-g2012`): reads
// a texunit vector file (vectors/README.md) itself, drives the block through the generated adapter
// tu_vec_dut (fields packed LSB first: field k at the sum of the widths before it) with valid/ready
// random stalls on both sides, keeps a scoreboard (one output per input, in order; no output
// without an input, none during a 64-cycle drain) and compares every output bit for bit with the
// file's expected fields. Prints "tu_vec_tb: PASS ..." or "tu_vec_tb: FAIL ..." and ends with
// $finish (PASS) or $fatal (anything else); scripts/icarus_cosim.sh checks both.
// Plusargs: +vectors=FILE, +stall=PERCENT (default 30), +seed=N (default 1), +progress (a line
// every 1000 cycles).
module tu_vec_tb;
  parameter integer NumIn = 1;        // fields of role in / out, in file order
  parameter integer NumOut = 1;
  parameter integer InBits = 1;       // sum of their widths
  parameter integer OutBits = 1;
  parameter [NumIn*8-1:0] InWidths = 0;    // width of field k at [8k +: 8]
  parameter [NumOut*8-1:0] OutWidths = 0;
  localparam integer MaxLine = 8192;  // characters per line
  localparam integer Ring = 4096;     // inputs in flight (far above any block's latency)
  localparam integer HangCycles = 200000;

  reg clk = 1'b0, rst_n = 1'b0;
  always #5 clk = ~clk;

  // ---- file reader: one line at a time into lb[0 .. ll-1] ----
  reg [1023:0] path;
  integer fd, lineno, ll, c, stall, seed, i;
  reg [7:0] lb [0:MaxLine-1];
  reg eof;

  task fail(input [8*200-1:0] msg);
    begin
      $display("tu_vec_tb: FAIL %0s:%0d: %0s", path, lineno, msg);
      $fatal(1);
    end
  endtask

  task read_line;
    begin
      ll = 0;
      c = $fgetc(fd);
      eof = (c == -1);
      while (c != -1 && c != 10) begin
        if (ll >= MaxLine) fail("line too long");
        if (c != 13) begin
          lb[ll] = c[7:0];
          ll = ll + 1;
        end
        c = $fgetc(fd);
      end
      lineno = lineno + 1;
    end
  endtask

  // True when lb starts with the text (given right-aligned in a packed string of n characters).
  function starts_with(input [8*32-1:0] s, input integer n);
    integer k;
    begin
      starts_with = ll >= n;
      for (k = 0; k < n && starts_with; k = k + 1)
        if (ll <= k || lb[k] != s[8*(n-1-k) +: 8]) starts_with = 1'b0;
    end
  endfunction

  function integer skip_blanks(input integer from);
    integer k;  // Icarus 11 cannot index with the function's own return variable
    begin
      k = from;
      while (k < ll && (lb[k] == " " || lb[k] == 9)) k = k + 1;
      skip_blanks = k;
    end
  endfunction

  // ---- header: "# fields: name:role:fmt ..." -> the widths of the in and out fields ----
  integer nin, nout, p, q, w, role;  // role 0 in, 1 out, 2 ref
  task parse_fields;
    begin
      nin = 0;
      nout = 0;
      p = skip_blanks(9);
      while (p < ll) begin
        while (p < ll && lb[p] != ":") p = p + 1;  // past the name
        p = p + 1;
        if (p + 2 < ll && lb[p] == "i" && lb[p + 1] == "n" && lb[p + 2] == ":") role = 0;
        else if (p + 3 < ll && lb[p] == "o" && lb[p + 1] == "u" && lb[p + 2] == "t" && lb[p + 3] == ":") role = 1;
        else if (p + 3 < ll && lb[p] == "r" && lb[p + 1] == "e" && lb[p + 2] == "f" && lb[p + 3] == ":") role = 2;
        else fail("fields: role is not in, out or ref");
        while (p < ll && lb[p] != ":") p = p + 1;
        p = p + 2;  // past ':' and the s / u / f letter
        w = 0;
        while (p < ll && lb[p] >= "0" && lb[p] <= "9") begin
          w = w * 10 + (lb[p] - "0");
          p = p + 1;
        end
        while (p < ll && lb[p] != " " && lb[p] != 9) p = p + 1;
        if (role == 0) begin
          if (nin >= NumIn || InWidths[8*nin +: 8] != w) fail("fields: input fields do not match the compiled block");
          nin = nin + 1;
        end else if (role == 1) begin
          if (nout >= NumOut || OutWidths[8*nout +: 8] != w) fail("fields: output fields do not match the compiled block");
          nout = nout + 1;
        end
        p = skip_blanks(p);
      end
      if (nin != NumIn || nout != NumOut) fail("fields: field count does not match the compiled block");
    end
  endtask

  // ---- data line -> in_vec / exp_vec (hex fields; ref fields are skipped) ----
  reg [InBits-1:0] in_vec;
  reg [OutBits-1:0] exp_vec;
  reg [63:0] val;
  integer fi, fo, ioff, ooff, digits, h;
  task parse_data;
    begin
      fi = 0;
      fo = 0;
      ioff = 0;
      ooff = 0;
      p = skip_blanks(0);
      while (p < ll && (fi < NumIn || fo < NumOut)) begin
        val = 0;
        digits = 0;
        while (p < ll && lb[p] != " " && lb[p] != 9) begin
          if (lb[p] >= "0" && lb[p] <= "9") h = lb[p] - "0";
          else if (lb[p] >= "a" && lb[p] <= "f") h = lb[p] - "a" + 10;
          else if (lb[p] >= "A" && lb[p] <= "F") h = lb[p] - "A" + 10;
          else fail("not a hex digit");
          val = {val[59:0], h[3:0]};
          digits = digits + 1;
          p = p + 1;
        end
        w = fi < NumIn ? InWidths[8*fi +: 8] : OutWidths[8*fo +: 8];
        if (digits > (w + 3) / 4 || (w < 64 && (val >> w) != 0)) fail("field value does not fit its width");
        for (i = 0; i < w; i = i + 1)
          if (fi < NumIn) in_vec[ioff + i] = val[i];
          else exp_vec[ooff + i] = val[i];
        if (fi < NumIn) begin
          ioff = ioff + w;
          fi = fi + 1;
        end else begin
          ooff = ooff + w;
          fo = fo + 1;
        end
        p = skip_blanks(p);
      end
      if (fi < NumIn || fo < NumOut) fail("too few fields");
    end
  endtask

  // ---- the block ----
  reg in_valid = 1'b0, out_ready = 1'b0;
  wire in_ready, out_valid;
  reg [InBits-1:0] in_data = 0;
  wire [OutBits-1:0] out_data;
  tu_vec_dut #(.InBits(InBits), .OutBits(OutBits)) u_dut (
    .clk_i(clk), .rst_ni(rst_n), .in_valid_i(in_valid), .in_ready_o(in_ready), .in_i(in_data),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_o(out_data)
  );

  // ---- scoreboard: expected outputs of accepted inputs, oldest first ----
  reg [OutBits-1:0] expq [0:Ring-1];
  integer lineq [0:Ring-1];
  integer wr = 0, rd = 0, sent = 0, got = 0, mismatches = 0, cycles = 0, idle = 0, drain;
  reg have = 1'b0, done = 1'b0;
  integer cur_line;

  task next_vector;
    begin
      have = 1'b0;
      while (!have && !eof) begin
        read_line;
        if (!eof || ll > 0) begin
          p = skip_blanks(0);
          if (p < ll && lb[p] != "#") begin
            parse_data;
            have = 1'b1;
            cur_line = lineno;
          end
        end
      end
    end
  endtask

  initial begin
    if (!$value$plusargs("vectors=%s", path)) begin
      $display("tu_vec_tb: FAIL no +vectors=FILE");
      $fatal(1);
    end
    if (!$value$plusargs("stall=%d", stall)) stall = 30;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    lineno = 0;
    fd = $fopen(path, "r");
    if (fd == 0) fail("cannot open");
    read_line;
    if (!starts_with("# texunit-vectors 1", 19) || ll != 19) fail("line 1 is not '# texunit-vectors 1'");
    read_line;
    while (!eof && !starts_with("# fields:", 9)) read_line;
    if (eof) fail("no '# fields:' header line");
    parse_fields;
    i = $urandom(seed);
    next_vector;
    repeat (3) @(posedge clk);
    rst_n <= 1'b1;
  end

  // Inputs and outputs change just after the clock edge (#1), the block samples on the edge.
  reg taken;
  reg progress;
  initial progress = $test$plusargs("progress");
  always @(posedge clk) if (rst_n) begin
    taken = 1'b0;
    cycles = cycles + 1;
    idle = idle + 1;
    if (in_valid && in_ready) begin
      taken = 1'b1;
      expq[wr % Ring] = exp_vec;
      lineq[wr % Ring] = cur_line;
      wr = wr + 1;
      sent = sent + 1;
      idle = 0;
      if (wr - rd > Ring) fail("more inputs in flight than the scoreboard holds");
      next_vector;
    end
    if (out_valid && out_ready) begin
      idle = 0;
      if (rd == wr) begin
        lineno = 0;
        fail("output without an input (scoreboard empty)");
      end
      if (out_data !== expq[rd % Ring]) begin
        mismatches = mismatches + 1;
        if (mismatches <= 10)
          $display("tu_vec_tb: mismatch %0s:%0d: got %h expected %h", path, lineq[rd % Ring], out_data, expq[rd % Ring]);
      end
      rd = rd + 1;
      got = got + 1;
    end
    if (idle > HangCycles) fail("hung: no handshake for 200000 cycles");
    if (progress && cycles % 1000 == 0) $display("tu_vec_tb: cycle %0d, %0d in, %0d out", cycles, sent, got);
    if (!have && rd == wr && !done) begin
      done = 1'b1;
      drain = 0;
    end
    if (done) begin
      drain = drain + 1;
      if (drain == 64) begin
        if (mismatches != 0) begin
          $display("tu_vec_tb: FAIL %0s: %0d vectors, %0d mismatches", path, got, mismatches);
          $fatal(1);
        end
        $display("tu_vec_tb: PASS %0s: %0d vectors, 0 mismatches, %0d cycles, %0d%% stalls", path, got, cycles, stall);
        $finish;
      end
    end
    #1;
    // A presented input stays valid (same data) until it is taken; a new one may wait a bubble.
    if (taken || !in_valid) in_valid <= have && !done && ($urandom % 100) >= stall;
    in_data <= in_vec;
    out_ready <= ($urandom % 100) >= stall;
  end
endmodule
