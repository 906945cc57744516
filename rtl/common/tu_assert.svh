// Assertion macros (docs/architecture.md "Assertions"). Verilator runs them as SVA (co-simulation
// builds pass --assert); Icarus Verilog 11 has no concurrent assertions, so there the handshake
// checks are plain clocked checks; Yosys 0.23 (synthesis) gets none.
//   `TU_ASSERT_HANDSHAKE(Name, valid, ready, data): after reset, valid is never X, and while valid
//      is high and ready low, valid stays high and data stays stable on the next clock. Placed at
//      every producer (module outputs) and at the unit's entry inputs (docs/architecture.md).
//   `TU_ASSERT_PARAM(Name, cond, message): an elaboration-time parameter check.
// Both expect clk_i and rst_ni (active-low reset) in the module. The SVA disable on an alias of
// rst_ni: read directly, Verilator flags rst_ni as used both synchronously and asynchronously.
`ifndef TU_ASSERT_SVH
`define TU_ASSERT_SVH

`ifdef YOSYS
  `define TU_ASSERT_HANDSHAKE(Name, valid, ready, data)
  `define TU_ASSERT_PARAM(Name, cond, message)
`elsif __ICARUS__
  `define TU_ASSERT_HANDSHAKE(Name, valid, ready, data)                                          \
    logic Name``_stalled_q = 1'b0;                                                               \
    logic [4095:0] Name``_data_q;  /* wide enough for every port group ($bits of a port: wrong) */ \
    always @(posedge clk_i) begin                                                                \
      if (rst_ni && $isunknown(valid)) $error("%m: %s: valid is X", `"Name`");                  \
      if (rst_ni && Name``_stalled_q && (!(valid) || 4096'(data) !== Name``_data_q))             \
        $error("%m: %s: valid dropped or data changed while not ready", `"Name`");               \
      Name``_stalled_q <= rst_ni && (valid) && !(ready);                                         \
      Name``_data_q <= 4096'(data);                                                              \
    end
  `define TU_ASSERT_PARAM(Name, cond, message)                                                   \
    initial if (!(cond)) $error("%m: %s: %s", `"Name`", message);
`else
  `define TU_ASSERT_HANDSHAKE(Name, valid, ready, data)                                          \
    logic Name``_on;                                                                             \
    assign Name``_on = rst_ni;                                                                   \
    Name``_known: assert property (@(posedge clk_i) disable iff (!Name``_on) !$isunknown(valid)) \
      else $error("%m: %s: valid is X", `"Name`");                                              \
    Name``_hold: assert property (@(posedge clk_i) disable iff (!Name``_on)                      \
                                  (valid) && !(ready) |=> (valid) && $stable(data))              \
      else $error("%m: %s: valid dropped or data changed while not ready", `"Name`");
  `define TU_ASSERT_PARAM(Name, cond, message)                                                   \
    if (!(cond)) begin : Name                                                                    \
      $error("%s", message);                                                                     \
    end
`endif

`endif  // TU_ASSERT_SVH
