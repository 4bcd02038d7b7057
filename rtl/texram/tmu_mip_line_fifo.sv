/// Line FIFO of one mipmap-generator stage (000 §12, FIFO 1408 of Fig. 14): the pair sums of
/// an even line of a level wait here for the odd line below. Both lines visit the columns in
/// the same order, one entry per column pair, so the FIFO is a RAM addressed by the column
/// pair x >> 1: the even line writes entry i, the odd line reads it back in the same order.
///
/// A RAM without reset ("load before use"): an odd line only reads entries its even line
/// wrote. Asynchronous read, one write per clock.
///
/// Example (Depth 4, a level 8 texels wide): line 2 writes entries 0, 1, 2, 3; line 3 reads
/// entries 0, 1, 2, 3 and completes four texels of the next level.
module tmu_mip_line_fifo #(
  /// Entries: half a line of the stage's level (at least one).
  parameter int unsigned Depth = 512,
  /// Bits of an entry.
  parameter int unsigned Width = 9,
  /// Address bits (derived; one bit for a one-entry FIFO, whose address is unused).
  localparam int unsigned AddrW = (Depth > 1) ? $clog2(Depth) : 1
) (
  input  logic             clk_i,
  /// Write of entry addr_i (even line).
  input  logic             we_i,
  input  logic [AddrW-1:0] addr_i,
  input  logic [Width-1:0] wdata_i,
  /// Entry addr_i (odd line).
  output logic [Width-1:0] rdata_o
);

  if (Depth < 1 || Width < 1) begin : gen_check
    $error("tmu_mip_line_fifo: Depth and Width must be at least 1");
  end

  if (Depth > 1) begin : gen_ram
    logic [Width-1:0] mem_q [Depth];
    always_ff @(posedge clk_i) begin
      if (we_i) mem_q[addr_i] <= wdata_i;
    end
    assign rdata_o = mem_q[addr_i];
  end else begin : gen_reg
    logic unused_addr;
    assign unused_addr = ^addr_i;
    logic [Width-1:0] entry_q;
    always_ff @(posedge clk_i) begin
      if (we_i) entry_q <= wdata_i;
    end
    assign rdata_o = entry_q;
  end

`ifndef SYNTHESIS
  // Writes stay within the FIFO (a one-entry FIFO is written at address 0).
  a_addr_in_range: assert property (@(posedge clk_i) we_i |-> 32'(addr_i) < Depth);
`endif

endmodule
