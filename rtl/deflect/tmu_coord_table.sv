/// One table of the coordinate generator (001 §5; golden CoordTableMemory in
/// golden/deflect/coord_eval.hpp): 2^AddrBits signed entries of ValueBits bits in flops, one
/// write port and one asynchronous read port. The generator reads it in the cycle a request
/// is accepted and registers the entry, so a write is seen by every request accepted at a
/// later edge.
///
/// No reset (a RAM): every entry is undefined until written; the host loads every table
/// before the first request.
module tmu_coord_table #(
  /// log2 of the entries: PhiBits - 2 for a theta table, PhiBits - 1 for a phi table.
  parameter int unsigned AddrBits  = 8,
  /// W: bits of an entry (SQ1.(W-1)).
  parameter int unsigned ValueBits = 10
) (
  input  logic                        clk_i,

  input  logic                        we_i,
  input  logic [AddrBits-1:0]         waddr_i,
  input  logic signed [ValueBits-1:0] wdata_i,

  input  logic [AddrBits-1:0]         raddr_i,
  output logic signed [ValueBits-1:0] rdata_o
);

  logic signed [ValueBits-1:0] mem_q [2**AddrBits];

  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
  end

  assign rdata_o = mem_q[raddr_i];

endmodule
