/// The ready/valid rules of one stream channel (docs/conventions.md, "Handshake"), stated once
/// and bound (SystemVerilog `bind`, at the end of each block's file) to every channel with a
/// ready: a block's input channels (`<ch>_valid_i`, `<ch>_ready_o`, the `<ch>_*_i` payload),
/// which checks whoever drives them, the test bench or the block around it; and its output
/// channels, memory requests included (`<ch>_valid_o`, `<ch>_ready_i`, the `<ch>_*_o` payload),
/// which checks the block. A transfer happens at an edge where valid and ready were both high.
///
///   a_valid_held    a valid not taken (valid high, ready low) is still high at the next edge
///   a_data_stable   ... and its payload is unchanged (what a_output_stable said in each block)
///   a_valid_known   after reset valid is never X or Z. Verilator is 2-state, so there this
///                   can never fire (the project's X check is the second rtl run with other
///                   random initial values); it states the rule for a 4-state simulator.
///
/// The instance names the channel (u_<ch>_check), so a failure reads e.g. "Assertion failed
/// in TOP.tmu_ccc_decoder.u_out_check.a_data_stable". Simulation only: what runs Verilator
/// reads it for every block, unlisted (rtl/manifest.txt's header); Yosys and the Icarus engine
/// (both with SYNTHESIS defined, where the binds vanish) do not read it, and its body is empty
/// under SYNTHESIS anyway (Yosys 0.23 cannot parse concurrent assertions). Not counted for
/// coverage: its ports are the channel's signals, already counted in the block.
module tmu_stream_check #(
  /// Payload bits (at least 1).
  parameter int unsigned W = 1
) (
  input  logic         clk_i,
  input  logic         rst_ni,
  input  logic         valid_i,
  input  logic         ready_i,
  input  logic [W-1:0] data_i
);

`ifndef SYNTHESIS
  // verilator coverage_off
  a_valid_held: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (valid_i && !ready_i) |=> valid_i);
  a_data_stable: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (valid_i && !ready_i) |=> $stable(data_i));
  a_valid_known: assert property (@(posedge clk_i) disable iff (!rst_ni) !$isunknown(valid_i));
  // verilator coverage_on
`endif

endmodule
