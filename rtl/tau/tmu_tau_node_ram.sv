/// The tau unit's node memory: 289 words of 48 bits, node (i, j) at i + 17 j, {v, u} each
/// TexCoord SQ16.8. A single-port RAM with a registered read: one access per clock, a write
/// (we_i) or a read whose word is on rdata_o after the edge. A write to an address beyond
/// the memory (289 .. 511) is dropped. No reset: write every node a sample reads first.
module tmu_tau_node_ram (
  input  logic                       clk_i,
  input  logic                       we_i,
  input  tmu_pkg::tau_node_addr_t    addr_i,
  input  logic [2*tmu_pkg::TexCoordW-1:0] wdata_i,
  output logic [2*tmu_pkg::TexCoordW-1:0] rdata_o
);

  localparam int unsigned Words = (tmu_pkg::TauMaxCells + 1) * (tmu_pkg::TauMaxCells + 1);
  localparam int unsigned DW    = 2 * tmu_pkg::TexCoordW;

  logic [DW-1:0] mem_q [Words];
  logic [DW-1:0] rdata_q;

  always_ff @(posedge clk_i) begin
    if (we_i && 32'(addr_i) < Words) mem_q[addr_i] <= wdata_i;
    rdata_q <= mem_q[addr_i];
  end

  assign rdata_o = rdata_q;

endmodule
